// FE calibration of the pinion's fillet foundation. Sainsot's table
// (fillet_foundation.hpp) was fitted for gears of 0.01 <= theta_f <= 0.12
// rad with its own tooth model; the pinions of rack drives are few-toothed
// (theta_f 0.065..0.255 in the calibration sample), and the tooth beam here stops at the base circle
// with a radial segment below it where the cutter leaves a thicker
// trochoid. Against the FE pinion (fe/tooth_compliance_fe.hpp: the whole
// pinion, bore held) the tooth beam plus Sainsot's foundation is 2-32 %
// too compliant, most for thick-rooted teeth (high pressure angle, positive
// shift). This term is the FE minus that sum, fitted in Sainsot's own form:
//
//   dc = [cos^2 a_m (L q^2 + M q + P) + sin^2 a_m Q] / (E b),  q = u_f / S_f,
//
// a_m the load angle, u_f and S_f as in fillet_foundation.hpp, each of
// L, M, P, Q linear in theta_f and tan a0. It is negative (a stiffening),
// and is applied only on top of the tooth beam and Sainsot's foundation.
// Data tests/data/fe/pinion_tooth.csv; fit, range and error in
// docs/models/fillet_calibration.md.
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/fillet_foundation.hpp"

namespace rackopt {

struct FilletCalibrationRange {
  double theta_lo = 0.06, theta_hi = 0.26;         // theta_f [rad]
  double alpha_lo = 0.2443, alpha_hi = 0.4364;     // a0 [rad]: 14..25 deg
};

class FilletCalibration {
 public:
  // Throws as FilletFoundationCompliance does (it reads the same geometry).
  FilletCalibration(const MeshGeometry& geometry, const PinionSpec& pinion);

  // [m/N] (<= 0 in the fitted range) at LOA coordinate s, face width b.
  double at(double s, double face_width) const;

  bool outside_fitted_range() const { return outside_range_; }
  double theta_f() const { return theta_f_; }

 private:
  FilletFoundationCompliance foundation_;  // u_f, S_f and theta_f as Sainsot's term has them
  double rb_, alpha2_, E_, theta_f_, S_f_, L_, M_, P_, Q_;
  bool outside_range_ = false;
};

}  // namespace rackopt
