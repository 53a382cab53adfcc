// Fillet-foundation (gear body) compliance of the pinion: Sainsot, Velex &
// Duverger (2004), docs/models/tooth.md. Uses the tool addendum in theta_f (through
// MeshGeometry::pinion.root_angle) and the full u_f definition with the
// -h tan(alpha_m) term (both are known bugs in public codes).
//
// Reads from MeshGeometry only: pinion.base_radius, pinion.half_base_angle,
// pinion.root_radius, pinion.root_angle (theta_f). From PinionSpec: the
// bore radius r_int and Young's modulus.
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {

// The four coefficient functions of Sainsot et al. (docs/models/tooth.md):
// X*(h_f, theta_f) = A/theta_f^2 + B h_f^2 + C h_f/theta_f + D/theta_f + E h_f + F.
struct SainsotCoefficients {
  double L = 0, M = 0, P = 0, Q = 0;
};
SainsotCoefficients sainsot_coefficients(double h_f, double theta_f);

class FilletFoundationCompliance {
 public:
  // Throws InputError when the bore radius is not given (<= 0) or theta_f,
  // r_f, r_b, E are not positive; DesignError "bore_outside_root" when
  // r_int >= r_f (no rim left under the teeth).
  FilletFoundationCompliance(const MeshGeometry& geometry, const PinionSpec& pinion);

  // [m/N] for a unit normal load at LOA coordinate s, effective face width
  // face_width (the integrator passes b - w_s while a spall is under the
  // contact, docs/models/tooth.md):
  //   1/k_f = cos^2(a_m)/(E b) [L* (u_f/S_f)^2 + M* u_f/S_f + P* (1 + Q* tan^2 a_m)]
  // with a_m = alpha_1 = s/r_b - alpha_2 (load angle; s <= 0 is evaluated at
  // the base circle), u_f = y_c - h tan(a_m) - r_f, S_f = 2 r_f theta_f.
  // Throws InputError for face_width <= 0; DesignError
  // "fillet_foundation_out_of_range" if the table, far outside its fitted
  // range, gives a non-positive compliance.
  double at(double s, double face_width) const;

  // u_f [m] at LOA coordinate s: distance along the tooth centre line from the
  // root circle to where the line of action crosses the centre line.
  double u_f(double s) const;

  // True when (h_f, theta_f) lies outside the fitted range of the coefficient
  // table (about 1.4 <= h_f <= 7, 0.01 <= theta_f <= 0.12 rad); callers warn.
  bool outside_fitted_range() const { return outside_range_; }
  double h_f() const { return h_f_; }
  double theta_f() const { return theta_f_; }
  double root_thickness() const { return S_f_; }  // S_f = 2 r_f theta_f [m]
  SainsotCoefficients coefficients() const { return {L_, M_, P_, Q_}; }

 private:
  double rb_, alpha2_, rf_, E_, L_, M_, P_, Q_, S_f_, h_f_, theta_f_;
  bool outside_range_ = false;
};

}  // namespace rackopt
