// Straight-sided trapezoid rack tooth as a cantilever on the root line:
// closed-form bending, shear and axial compliances (docs/models/tooth.md);
// numerical quadrature with reduced sections for a spalled band (9.1).
//
// Reads from MeshGeometry only: pressure_angle, rack.dedendum, rack.addendum,
// rack.half_thickness_at_root (w_f), pinion.pitch_radius,
// profile_shift_length and clearance (for the contact height, docs/models/geometry.md).
// The values are copied: the object does not keep a reference to geometry.
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/cantilever_energy.hpp"
#include "rackopt/stiffness/tooth_compliance.hpp"

namespace rackopt {

class RackToothCompliance {
 public:
  // face_width: the rack face width actually used (RackSpec.face_width, or the
  // pinion's when that is 0: the caller resolves it). Material from
  // rack.material. Quadrature (spalled band, and the bending term below 5 deg
  // where the closed form cancels) uses max(numerics.quadrature_order, 16)
  // Gauss-Legendre points per piece. effects.rack_tooth is honoured by the
  // caller through `enabled` (false -> every call returns zeros).
  // Throws InputError for non-positive sizes/moduli, DesignError
  // "pointed_tooth" when the trapezoid closes below the rack tip.
  RackToothCompliance(const MeshGeometry& geometry, const RackSpec& rack, double face_width,
                      const Numerics& numerics, bool enabled = true);

  // Unit normal load at LOA coordinate s; the contact is at height
  // y_c = dedendum + h(s) above the root line with
  // h(s) = r sin^2 a0 - s sin a0 + x m + Delta (docs/models/geometry.md). s < 0 is
  // evaluated at s = 0 (as the pinion does).
  ToothCompliance at(double s, const SpallBand* spall = nullptr) const;
  // Same, by contact height y_c above the root line [m], clamped to the tooth
  // [0, dedendum + addendum]. Without a spall:
  //   1/k_b = 3/(2 E b sin^2 a0 tan a0) [cos^4 a0 ln(w_f/w_c) - 2 cos^2 a0 (1 - w_c/w_f)
  //           + (1 - w_c^2/w_f^2)/2]   (a0 >= 5 deg; quadrature below),
  //   1/k_s = 1.2 (1+nu) cos^2 a0 ln(w_f/w_c)/(E b tan a0),
  //   1/k_a = sin a0 cos a0 ln(w_f/w_c)/(2 E b),
  // with w_c = w_f - y_c tan a0 and ln(w_f/w_c)/tan a0 -> y_c/w_f as a0 -> 0.
  // With a spall band (heights above the root line) the part of the band
  // below the contact uses the 9.1 section; validated on every call.
  ToothCompliance at_height(double y_c, const SpallBand* spall = nullptr) const;

  // Height of the contact above the root line at LOA coordinate s [m] (unclamped).
  double contact_height(double s) const;

  // Throws DesignError "spall_off_profile" (band outside [0, tooth height]),
  // "spall_too_wide" (width > face width), "spall_too_deep" (depth >= 2 w at
  // the band's upper edge, the thinnest point); InputError for low > high or
  // negative sizes. Zero width or depth: valid, no effect.
  void validate(const SpallBand& spall) const;

  double half_thickness_at_root() const { return w_f_; }

 private:
  double alpha0_, tan_a0_, sin_a0_, cos_a0_, w_f_, dedendum_, height_, E_, nu_, G_, b_;
  double pitch_radius_, shift_, clearance_;
  bool enabled_;
  GaussLegendreRule rule_;
};

}  // namespace rackopt
