// The curve's quadrature and extreme search (stiffness/curve_numerics.hpp)
// against closed forms: the integral of a cubic through its samples is
// exact whether the samples are equally spaced (the short formula) or not
// (the Lagrange basis), and the golden section finds a parabola's vertex.
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/stiffness/curve_numerics.hpp"

namespace rackopt {
namespace {

double cubic(double x) { return 2 - 3 * x + 0.5 * x * x + 1.7 * x * x * x; }
double cubic_integral(double a, double b) {
  auto F = [](double x) { return 2 * x - 1.5 * x * x + x * x * x / 6 + 0.425 * x * x * x * x; };
  return F(b) - F(a);
}

TEST(CurveNumerics, MiddleIntervalOfEquallySpacedCubicIsExact) {
  const double xs[4] = {0.1, 0.35, 0.6, 0.85};
  double ys[4];
  for (int k = 0; k < 4; ++k) ys[k] = cubic(xs[k]);
  EXPECT_NEAR(interval_integral(xs, ys, 4, xs[1], xs[2]), cubic_integral(xs[1], xs[2]), 1e-14);
}

TEST(CurveNumerics, UnequalSpacingAndEndIntervalsAreExactForCubics) {
  const double xs[4] = {0.1, 0.2, 0.6, 1.3};
  double ys[4];
  for (int k = 0; k < 4; ++k) ys[k] = cubic(xs[k]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(interval_integral(xs, ys, 4, xs[k], xs[k + 1]), cubic_integral(xs[k], xs[k + 1]), 1e-13) << k;
  }
  // Three points: exact for quadratics.
  const double q[3] = {1, 4, 9};  // x^2 at 1, 2, 3
  const double qx[3] = {1, 2, 3};
  EXPECT_NEAR(interval_integral(qx, q, 3, 1, 2), 7.0 / 3.0, 1e-14);
  // Two points: the trapezoid.
  EXPECT_NEAR(interval_integral(qx, q, 2, 1, 2), 2.5, 1e-14);
}

TEST(CurveNumerics, GoldenSectionFindsTheVertex) {
  // Without an offset: 1 + (t - t0)^2 is flat to rounding within sqrt(eps) of t0.
  const auto [x, f] = golden_min([](double t) { return (t - 0.3) * (t - 0.3); }, 0.0, 1.0, 1e-9);
  EXPECT_NEAR(x, 0.3, 1e-8);
  EXPECT_LT(f, 1e-16);
}

}  // namespace
}  // namespace rackopt
