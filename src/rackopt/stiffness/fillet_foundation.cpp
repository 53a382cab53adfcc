#include "rackopt/stiffness/fillet_foundation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt {
namespace {

// docs/models/tooth.md, rows A..F for L*, M*, P*, Q* (Sainsot et al. 2004; digits
// identical in petrobras/ross, the PHM-BGU toolbox and van Eyk's solver).
struct Row {
  double A, B, C, D, E, F;
};
constexpr Row kL{-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045};
constexpr Row kM{60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086};
constexpr Row kP{-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236};
constexpr Row kQ{-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904};

double evaluate(const Row& r, double h, double th) {
  return r.A / (th * th) + r.B * h * h + r.C * h / th + r.D / th + r.E * h + r.F;
}

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

SainsotCoefficients sainsot_coefficients(double h_f, double theta_f) {
  return {evaluate(kL, h_f, theta_f), evaluate(kM, h_f, theta_f), evaluate(kP, h_f, theta_f),
          evaluate(kQ, h_f, theta_f)};
}

FilletFoundationCompliance::FilletFoundationCompliance(const MeshGeometry& geometry,
                                                       const PinionSpec& pinion) {
  const PinionGeometry& g = geometry.pinion;
  rb_ = g.base_radius;
  alpha2_ = g.half_base_angle;
  rf_ = g.root_radius;
  theta_f_ = g.root_angle;
  E_ = pinion.material.youngs_modulus;
  const double r_int = pinion.bore_radius;
  if (!(rb_ > 0.0) || !(rf_ > 0.0) || !(alpha2_ > 0.0)) {
    throw InputError({}, "pinion", "fillet foundation needs positive r_b, r_f and alpha_2");
  }
  if (!(theta_f_ > 0.0) || !(theta_f_ < 0.5 * std::numbers::pi)) {
    throw InputError({}, "pinion.root_angle", "theta_f = " + num(theta_f_) + " rad outside (0, pi/2)");
  }
  if (!(E_ > 0.0)) throw InputError({}, "pinion.material.youngs_modulus", "must be positive");
  if (!(r_int > 0.0)) {
    throw InputError({}, "pinion.bore_radius",
                     "the fillet-foundation model needs the bore radius r_int (> 0)");
  }
  if (r_int >= rf_) {
    throw DesignError("bore_outside_root", "bore radius " + num(r_int * 1e3) +
                                               " mm reaches the root radius " + num(rf_ * 1e3) +
                                               " mm: no rim under the teeth");
  }
  h_f_ = rf_ / r_int;
  S_f_ = 2.0 * rf_ * theta_f_;
  const SainsotCoefficients c = sainsot_coefficients(h_f_, theta_f_);
  L_ = c.L;
  M_ = c.M;
  P_ = c.P;
  Q_ = c.Q;
  outside_range_ = h_f_ < 1.4 || h_f_ > 7.0 || theta_f_ < 0.01 || theta_f_ > 0.12;
}

double FilletFoundationCompliance::u_f(double s) const {
  const double alpha1 = std::max(s, 0.0) / rb_ - alpha2_;
  const double roll = alpha1 + alpha2_;
  const double y_c = rb_ * (std::cos(alpha1) + roll * std::sin(alpha1));
  const double h = rb_ * (roll * std::cos(alpha1) - std::sin(alpha1));
  return y_c - h * std::tan(alpha1) - rf_;
}

double FilletFoundationCompliance::at(double s, double face_width) const {
  if (!(face_width > 0.0) || !std::isfinite(s)) {
    throw InputError({}, "face_width", "fillet foundation needs a positive face width and finite s");
  }
  const double alpha_m = std::max(s, 0.0) / rb_ - alpha2_;
  const double cm = std::cos(alpha_m), tm = std::tan(alpha_m);
  const double ratio = u_f(s) / S_f_;
  const double bracket = L_ * ratio * ratio + M_ * ratio + P_ * (1.0 + Q_ * tm * tm);
  if (!(bracket > 0.0)) {
    throw DesignError("fillet_foundation_out_of_range",
                      "Sainsot fillet-foundation law gives a non-positive compliance at h_f = " +
                          num(h_f_) + ", theta_f = " + num(theta_f_) + " rad");
  }
  return cm * cm / (E_ * face_width) * bracket;
}

}  // namespace rackopt
