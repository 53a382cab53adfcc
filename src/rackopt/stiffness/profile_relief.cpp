#include "rackopt/stiffness/profile_relief.hpp"

#include <algorithm>

namespace rackopt {

double relief_profile(const ProfileRelief& relief, double u) {
  if (!relief.active() || u <= 0) return 0.0;
  const double t = std::min(u / relief.length, 1.0);
  return relief.amount * (relief.shape == ProfileRelief::Shape::kParabolic ? t * t : t);
}

ReliefOnPath::ReliefOnPath(const Drive& drive, const MeshGeometry& geometry)
    : pinion_tip_(drive.pinion.tip_relief),
      pinion_root_(drive.pinion.root_relief),
      rack_tip_(drive.rack.tip_relief),
      rack_root_(drive.rack.root_relief),
      s_end_(geometry.path.s_end),
      s_start_(geometry.path.s_start),
      s_rack_tip_(geometry.path.s_rack_tip) {
  any_ = pinion_tip_.active() || pinion_root_.active() || rack_tip_.active() || rack_root_.active();
}

double ReliefOnPath::at(double s) const {
  if (!any_) return 0.0;
  // The pinion tip and the rack root meet at s_E: both zones grow towards it.
  const double toward_end = s - s_end_;
  return relief_profile(pinion_tip_, pinion_tip_.length + toward_end) +
         relief_profile(rack_root_, rack_root_.length + toward_end) +
         relief_profile(pinion_root_, pinion_root_.length - (s - s_start_)) +
         relief_profile(rack_tip_, rack_tip_.length - (s - s_rack_tip_));
}

}  // namespace rackopt
