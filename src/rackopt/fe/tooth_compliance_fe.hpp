// Single-tooth compliances by FE, with the definition the analytic tooth
// models are compared under: the pinion (whole gear, bore fixed) or a rack
// segment (base fixed) alone, a unit normal load at the contact of LOA
// coordinate s spread over a Hertz-sized patch (a point load has a
// log-infinite displacement under it), and the displacement read where the
// load line crosses the loaded tooth's centre line, along the load line.
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_options.hpp"
#include "rackopt/fe/mesh2d.hpp"

namespace rackopt::fe {

enum class ToothMember { kPinion, kRack };

// One member's compliance at one contact (m/N for the drive's face width).
struct ToothComplianceFe {
  ToothMember member = ToothMember::kPinion;
  double s = 0;              // LOA coordinate of the contact [m]
  double compliance = 0;     // FE: displacement along the load line at the read point / load
  Point2 load_point;         // where the load acts, in the member's own frame [m]
  Point2 read_point;         // where the displacement is read [m]
  double analytic = 0;       // the analytic tooth model's compliance under the same definition
  int nodes = 0, elements = 0;
  double seconds = 0;        // wall time of mesh + solve
};

// FE single-tooth compliance of `member` of `drive` at LOA coordinate s
// (within the drive's contact path), the load the drive's load.force.
// Throws DesignError (from the geometry or the body outlines) before any FE
// work, CcxNotFound / CcxError from the solve, std::invalid_argument for bad
// options or an s outside the path.
ToothComplianceFe fe_tooth_compliance(const Drive& drive, ToothMember member, double s,
                                      const FeOptions& options = {});

}  // namespace rackopt::fe
