#include "rackopt/stiffness/fillet_calibration.hpp"

#include <algorithm>
#include <cmath>

#include "rackopt/core/error.hpp"

namespace rackopt {
namespace {

// X = X0 + X1 theta_f + X2 tan a0 for X in L, M, P, Q: the minimax fit of
// the relative residuals by `fe_calibration --fit pinion
// tests/data/fe/pinion_tooth.csv` (docs/models/fillet_calibration.md).
struct Row {
  double c0, c_theta, c_tan;
};
// FILLET_CALIBRATION_FIT_BEGIN
constexpr Row kL{4.77775, 32.61749, -23.56976};
constexpr Row kM{-4.66072, -8.39449, 12.80309};
constexpr Row kP{0.61720, 0.16896, -2.68637};
constexpr Row kQ{-4.54669, -18.17139, 11.99049};
// FILLET_CALIBRATION_FIT_END

double evaluate(const Row& r, double theta, double t) { return r.c0 + r.c_theta * theta + r.c_tan * t; }

}  // namespace

FilletCalibration::FilletCalibration(const MeshGeometry& geometry, const PinionSpec& pinion)
    : foundation_(geometry, pinion) {
  rb_ = geometry.pinion.base_radius;
  alpha2_ = geometry.pinion.half_base_angle;
  E_ = pinion.material.youngs_modulus;
  theta_f_ = foundation_.theta_f();
  S_f_ = foundation_.root_thickness();
  const double t = std::tan(geometry.pressure_angle);
  L_ = evaluate(kL, theta_f_, t);
  M_ = evaluate(kM, theta_f_, t);
  P_ = evaluate(kP, theta_f_, t);
  Q_ = evaluate(kQ, theta_f_, t);
  const FilletCalibrationRange range;
  outside_range_ = theta_f_ < range.theta_lo || theta_f_ > range.theta_hi ||
                   geometry.pressure_angle < range.alpha_lo - 1e-9 || geometry.pressure_angle > range.alpha_hi + 1e-9;
}

double FilletCalibration::at(double s, double face_width) const {
  if (!(face_width > 0.0) || !std::isfinite(s)) {
    throw InputError({}, "face_width", "fillet calibration needs a positive face width and finite s");
  }
  const double alpha1 = std::max(s, 0.0) / rb_ - alpha2_;
  const double q = foundation_.u_f(s) / S_f_;
  const double c2 = std::cos(alpha1) * std::cos(alpha1);
  return (c2 * ((L_ * q + M_) * q + P_) + (1 - c2) * Q_) / (E_ * face_width);
}

}  // namespace rackopt
