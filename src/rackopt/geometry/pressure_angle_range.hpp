// The pressure angles at which the drive's cutter, tooth numbers, shift and
// clearance still give a drive that can exist (build_mesh_geometry accepts
// it): what `rackopt check` prints so an engineer knows how far a study may
// move the pressure angle before the geometry itself gives out.
#pragma once

#include <string>

#include "rackopt/core/drive.hpp"

namespace rackopt {

struct PressureAngleRange {
  bool found = false;         // the drive's own pressure angle is feasible (else lower/upper are 0)
  double lower = 0;           // [rad] smallest feasible angle of the interval holding the drive's own
  double upper = 0;           // [rad] largest one
  std::string lower_limit;    // DesignError code just below `lower` ("" when it is the scan's 5 deg end)
  std::string upper_limit;    // DesignError code just above `upper` ("" at the scan's 45 deg end)
};

// Scans 5..45 deg (the loader's range) in 0.25 deg steps from the drive's own
// pressure angle outwards and bisects each end to 0.001 deg. Everything but
// the pressure angle is kept. The feasible set is taken as the interval
// around the drive's own angle; a second feasible interval beyond a gap is
// not reported. About 200 geometry builds (a few ms).
PressureAngleRange feasible_pressure_angles(const Drive& drive);

}  // namespace rackopt
