// CumulativeIntegrals: the tabulated integrals from x to b against closed
// forms, for smooth functions and for one that is steep near a (the way the
// pinion tooth's integrands rise towards the tip).
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/stiffness/cumulative_integrals.hpp"

namespace rackopt {
namespace {

TEST(CumulativeIntegrals, MatchClosedFormsFromAnyLowerLimit) {
  const double a = -0.6, b = 0.3, pole = -0.65;  // 1/(x - pole)^3 is steep near a
  const CumulativeIntegrals table(
      [&](double x) {
        return CumulativeIntegrals::Values{std::exp(x), std::cos(3 * x), x * x * x, 1.0 / std::pow(x - pole, 3)};
      },
      a, b, 8, 1.5);
  auto exact = [&](double x) {
    return CumulativeIntegrals::Values{std::exp(b) - std::exp(x), (std::sin(3 * b) - std::sin(3 * x)) / 3,
                                       (std::pow(b, 4) - std::pow(x, 4)) / 4,
                                       0.5 / std::pow(x - pole, 2) - 0.5 / std::pow(b - pole, 2)};
  };
  for (int i = 0; i <= 200; ++i) {
    const double x = a + (b - a) * i / 200.0;
    const CumulativeIntegrals::Values got = table.from(x), want = exact(x);
    for (std::size_t k = 0; k < got.size(); ++k) {
      // Relative to the whole integral from a: the table's error does not
      // shrink with the remaining interval.
      const double scale = std::abs(exact(a)[k]);
      EXPECT_NEAR(got[k], want[k], 1e-12 * scale) << "function " << k << " from x = " << x;
    }
  }
  // Outside [a, b] the limit is clamped; at b nothing is left.
  EXPECT_EQ(table.from(a - 1)[0], table.from(a)[0]);
  EXPECT_NEAR(table.from(b)[2], 0.0, 1e-16);
  EXPECT_NEAR(table.from(b + 1)[1], 0.0, 1e-16);
}

}  // namespace
}  // namespace rackopt
