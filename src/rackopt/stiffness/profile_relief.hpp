// Profile relief (tip and root relief of pinion and rack) seen from the line
// of action: the gap a tooth pair must close before it carries load, as a
// function of the LOA coordinate s of its contact
// (docs/models/transmission_error.md).
//
// Example:
//   ReliefOnPath relief(drive, geometry);
//   if (relief.any()) double gap = relief.at(pair.s);  // [m]
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {

// Relief of one flank end at distance u into its zone (u in [0, L]):
// amount * (u/L)^1 (linear) or ^2 (parabolic); 0 for u <= 0, amount for u >= L.
double relief_profile(const ProfileRelief& relief, double u);

class ReliefOnPath {
 public:
  // Maps the four reliefs of the drive (pinion tip/root, rack tip/root) onto
  // the LOA of `geometry`:
  //  * pinion tip:  zone [s_E - L, s_E] (roll length from the pinion tip);
  //  * pinion root: zone [s_start, s_start + L] (start of the active profile);
  //  * rack tip:    zone [s_A, s_A + L] (s_A: the rack tip line on the LOA;
  //                 when the pinion is undercut the contact starts above s_A
  //                 and only the part of the zone beyond s_start is met);
  //  * rack root:   zone [s_E - L, s_E] (the rack's lowest contact meets the pinion tip).
  ReliefOnPath(const Drive& drive, const MeshGeometry& geometry);

  // True when any relief has amount > 0.
  bool any() const { return any_; }
  // Total relief (pinion + rack flank) at LOA coordinate s [m], >= 0.
  double at(double s) const;

 private:
  ProfileRelief pinion_tip_, pinion_root_, rack_tip_, rack_root_;
  double s_end_ = 0, s_start_ = 0, s_rack_tip_ = 0;
  bool any_ = false;
};

}  // namespace rackopt
