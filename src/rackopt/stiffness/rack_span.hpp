// The rack body between two hinges as a beam (physics.md 6): influence
// coefficients along the line of action between contacts on one segment.
//
// A unit force along the LOA at a contact at abscissa a (from the left hinge)
// and height e above the neutral axis is carried to the neutral axis at the
// same abscissa as a vertical force -sin a0, an axial force +cos a0 and the
// couple -e cos a0 (when effects.couple_term). The displacement of contact j
// along the LOA is u_c cos a0 - v_c sin a0 with u_c = u(a_j) - e_j theta(a_j).
// Euler-Bernoulli bending, optional Timoshenko shear (effects.body_shear),
// optional axial (effects.body_axial); pin-pin: both hinges fix x;
// pin-roller: only the left one.
#pragma once

#include "rackopt/core/drive.hpp"

namespace rackopt {

class RackSpanCompliance {
 public:
  RackSpanCompliance(const RackSpec& rack, double pressure_angle, const Effects& effects);

  // LOA displacement at contact (a_j, e_j) per unit LOA force at contact
  // (a_k, e_k), both on the same segment, 0 <= a <= span [m/N]. Symmetric.
  double influence(double a_j, double e_j, double a_k, double e_k) const;
  // influence(a, e, a, e).
  double self(double a, double e) const { return influence(a, e, a, e); }

  double span() const { return l_; }

 private:
  double l_, s_, c_, EI_, EA_, kGA_;
  bool couple_, axial_, shear_, pin_pin_;
};

}  // namespace rackopt
