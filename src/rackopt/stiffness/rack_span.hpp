// The rack body between two hinges as a beam (docs/models/rack_span.md): influence
// coefficients along the line of action between contacts on one segment.
//
// A unit force along the LOA at a contact at abscissa a (from the left hinge)
// and height e above the neutral axis is carried to the neutral axis at the
// same abscissa as a vertical force -sin a0, an axial force +cos a0 and the
// couple -e cos a0 (when effects.couple_term). The displacement of contact j
// along the LOA is u_c cos a0 - v_c sin a0 with u_c = u(a_j) - e_j psi(a_j),
// psi the rotation of the cross-section (the tooth is rigid and turns with it).
// Euler-Bernoulli bending, optional Timoshenko shear (effects.body_shear),
// optional axial (effects.body_axial); pin-pin: both hinges fix x;
// pin-roller: only the left one. Both hinges fix y.
//
// docs/models/rack_span.md derives every term. Compared with the usual
// single-load beam formulas the Timoshenko shear has one more term, c^2 e_j e_k / (l kappa G A): a couple
// is balanced by hinge reactions, so it causes a constant shear force over the
// span whose shear strain rotates every section.
#pragma once

#include "rackopt/core/drive.hpp"

namespace rackopt {

// One influence coefficient split by origin [m/N], for reports and tests.
// s = sin a0, c = cos a0; "couple" terms vanish when effects.couple_term is
// off, "shear" terms when effects.body_shear is off, "axial" when
// effects.body_axial is off.
struct RackSpanInfluence {
  double vertical = 0;      // s^2 * bending deflection at j per vertical force at k
  double couple = 0;        // c^2 e_j e_k * bending section rotation per couple
  double coupling = 0;      // s c (e_k v-per-couple + e_j psi-per-force), bending
  double axial = 0;         // c^2 * axial displacement per axial force
  double shear = 0;         // s^2 * shear deflection per vertical force
  double shear_couple = 0;  // c^2 e_j e_k / (l kappa G A): section rotation by the
                            // constant shear force a couple causes
  double total() const { return vertical + couple + coupling + axial + shear + shear_couple; }
};

class RackSpanCompliance {
 public:
  // Reads rack.span, rack.supports, rack.section (second_moment, and area /
  // shear_area when body_axial / body_shear are on) and rack.material (E, nu).
  // Throws std::invalid_argument when a value it uses is not finite and
  // positive (span, I, A, kappa*A, E; nu must be in (-1, 0.5]) or the pressure
  // angle is not in (0, pi/2). The loader validates user input, so this is a
  // programming error, not an InputError.
  RackSpanCompliance(const RackSpec& rack, double pressure_angle, const Effects& effects);

  // LOA displacement at contact (a_j, e_j) per unit LOA force at contact
  // (a_k, e_k), both on the same segment, 0 <= a <= span [m/N]; e is the
  // contact height above the neutral axis [m] (any finite value; ignored when
  // effects.couple_term is off). Exactly symmetric (bitwise) under swapping
  // j and k; continuous in a and e; closed form, no allocation.
  // Abscissae within 1e-9 * span outside [0, span] are clamped to the hinge
  // (rounding of a = x - k * span); anything further out, or a non-finite
  // a or e, throws std::invalid_argument.
  // At a hinge the vertical and axial terms vanish but the couple terms do
  // not: a contact above a hinge still tilts the section there.
  double influence(double a_j, double e_j, double a_k, double e_k) const;

  // The same coefficient split into its parts; parts(...).total() ==
  // influence(...) exactly.
  RackSpanInfluence parts(double a_j, double e_j, double a_k, double e_k) const;

  // influence(a, e, a, e), bit for bit (the same expressions without the
  // ordering of two contacts; one per pair and curve sample).
  double self(double a, double e) const;

  double span() const { return l_; }

 private:
  double checked_abscissa(double a) const;

  double l_;        // span [m]
  double s_, c_;    // sin a0, cos a0
  double inv_EI_;   // 1/(E I)
  double inv_EA_;   // 1/(E A), 0 when body_axial is off
  double inv_kGA_;  // 1/(kappa G A), 0 when body_shear is off
  bool couple_;     // effects.couple_term
  bool pin_pin_;    // both hinges fix x
};

}  // namespace rackopt
