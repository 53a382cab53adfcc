#include "rackopt/stiffness/rack_foundation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt {
namespace {

// X = X0 + X1 ln(H/S) + X2 rho/S for X in L, M, P, Q: the least-squares fit
// of `fe_calibration --fit rack tests/data/fe/rack_tooth.csv`
// (docs/models/rack_foundation.md), relative residuals weighted by the FE
// compliance.
struct Row {
  double c0, c_depth, c_round;
};
// RACK_FOUNDATION_FIT_BEGIN
constexpr Row kL{3.78714, 0.78795, -3.72013};
constexpr Row kM{0.05329, 0.41419, -0.90742};
constexpr Row kP{0.89952, 0.58292, -0.70979};
constexpr Row kQ{-1.02671, 0.45059, 2.28042};
// RACK_FOUNDATION_FIT_END

double evaluate(const Row& r, double log_depth, double round) { return r.c0 + r.c_depth * log_depth + r.c_round * round; }

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

RackFoundationCoefficients rack_foundation_coefficients(double depth_over_root, double round_over_root) {
  const double l = std::log(depth_over_root);
  return {evaluate(kL, l, round_over_root), evaluate(kM, l, round_over_root), evaluate(kP, l, round_over_root),
          evaluate(kQ, l, round_over_root)};
}

RackFoundationCompliance::RackFoundationCompliance(const MeshGeometry& geometry, const RackSpec& rack,
                                                   double body_depth, double face_width)
    : tan_a0_(std::tan(geometry.pressure_angle)),
      cos2_(std::cos(geometry.pressure_angle) * std::cos(geometry.pressure_angle)),
      sin2_(std::sin(geometry.pressure_angle) * std::sin(geometry.pressure_angle)),
      w_f_(geometry.rack.half_thickness_at_root),
      height_(geometry.rack.dedendum + geometry.rack.addendum),
      E_b_(rack.material.youngs_modulus * face_width),
      pitch_radius_sin2_(geometry.pinion.pitch_radius * std::sin(geometry.pressure_angle) *
                         std::sin(geometry.pressure_angle)),
      sin_a0_(std::sin(geometry.pressure_angle)),
      datum_lift_(geometry.profile_shift_length + geometry.clearance),
      dedendum_(geometry.rack.dedendum) {
  if (!(body_depth > 0) || !std::isfinite(body_depth)) {
    throw InputError({}, "rack.body_height", "the rack foundation needs a positive body depth below the root line");
  }
  if (!(face_width > 0)) throw InputError({}, "rack.face_width", "rack face width must be positive");
  if (!(rack.material.youngs_modulus > 0)) throw InputError({}, "rack.material.youngs_modulus", "must be positive");
  if (!(w_f_ > 0)) throw InputError({}, "rack", "rack tooth needs a positive root half-thickness");
  const double S = 2 * w_f_;
  const double round = rack.root_radius > 0 ? rack.root_radius : geometry.pinion.cutter_tip_radius;
  depth_over_root_ = body_depth / S;
  round_over_root_ = round / S;
  c_ = rack_foundation_coefficients(depth_over_root_, round_over_root_);
  const RackFoundationRange range;
  outside_range_ = depth_over_root_ < range.depth_lo || depth_over_root_ > range.depth_hi ||
                   round_over_root_ < range.round_lo || round_over_root_ > range.round_hi;
  // The compliance is a quadratic in q over the tooth: positive at both ends
  // and at its vertex if inside, or the law has left its ground.
  const double q_hi = at_height(height_) * E_b_, q_lo = at_height(0) * E_b_;
  double vertex = INFINITY;
  if (c_.L > 0) {
    const double q = -c_.M / (2 * c_.L);
    const double u_hi = height_ - (w_f_ - height_ * tan_a0_) * tan_a0_, u_lo = -w_f_ * tan_a0_;
    if (q > u_lo / S && q < u_hi / S) vertex = cos2_ * (c_.P - c_.M * c_.M / (4 * c_.L)) + sin2_ * c_.Q;
  }
  if (!(std::min({q_hi, q_lo, vertex}) > 0)) {
    throw DesignError("rack_foundation_out_of_range",
                      "rack foundation law gives a non-positive compliance at body depth / root thickness " +
                          num(depth_over_root_) + " and root round / root thickness " + num(round_over_root_) +
                          " (fitted " + num(range.depth_lo) + ".." + num(range.depth_hi) + " and " +
                          num(range.round_lo) + ".." + num(range.round_hi) + ")");
  }
}

double RackFoundationCompliance::at_height(double y_c) const {
  const double y = std::clamp(y_c, 0.0, height_);
  // The load line leaves the flank point (half thickness w) at a0 below the
  // horizontal and crosses the centre line w tan a0 lower.
  const double w = w_f_ - y * tan_a0_;
  const double q = (y - w * tan_a0_) / (2 * w_f_);
  return (cos2_ * ((c_.L * q + c_.M) * q + c_.P) + sin2_ * c_.Q) / E_b_;
}

double RackFoundationCompliance::at(double s) const {
  return at_height(dedendum_ + pitch_radius_sin2_ - s * sin_a0_ + datum_lift_);
}

}  // namespace rackopt
