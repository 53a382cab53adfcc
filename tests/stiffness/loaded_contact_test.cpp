// solve_loaded_contact against hand solutions: springs in parallel with
// gaps, a coupled pair that opens (tension would be needed), and the
// optimality conditions on random positive definite matrices.
#include "rackopt/stiffness/loaded_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace rackopt {
namespace {

TEST(LoadedContact, ParallelSpringsWithoutGapShareByStiffness) {
  const double c1 = 2e-9, c2 = 3e-9, F = 1e4;
  const LoadedContact lc = solve_loaded_contact(std::vector<double>{c1, 0, 0, c2}, std::vector<double>{0, 0}, F);
  const double K = 1 / c1 + 1 / c2;
  EXPECT_NEAR(lc.approach, F / K, 1e-15 * F / K);
  EXPECT_NEAR(lc.tangent_stiffness, K, 1e-6);
  EXPECT_NEAR(lc.force[0], F * (1 / c1) / K, 1e-9);
  EXPECT_NEAR(lc.force[1], F * (1 / c2) / K, 1e-9);
}

// Gap e on spring 2: it closes once F c1 > e.
TEST(LoadedContact, GapClosesAtTheHandLoad) {
  const double c1 = 2e-9, c2 = 3e-9, e = 10e-6;
  const double F_close = e / c1;  // 5 kN
  for (double F : {1e3, 4.9e3, 5.1e3, 2e4}) {
    SCOPED_TRACE(F);
    const LoadedContact lc = solve_loaded_contact(std::vector<double>{c1, 0, 0, c2}, std::vector<double>{0, e}, F);
    if (F < F_close) {
      EXPECT_NEAR(lc.approach, F * c1, 1e-15);
      EXPECT_EQ(lc.force[1], 0.0);
      EXPECT_FALSE(lc.loaded[1]);
      EXPECT_NEAR(lc.tangent_stiffness, 1 / c1, 1e-3);
    } else {
      const double delta = (F + e / c2) / (1 / c1 + 1 / c2);
      EXPECT_NEAR(lc.approach, delta, 1e-12 * delta);
      EXPECT_NEAR(lc.force[1], (delta - e) / c2, 1e-9 * F);
      EXPECT_TRUE(lc.loaded[1]);
      EXPECT_NEAR(lc.tangent_stiffness, 1 / c1 + 1 / c2, 1e-3);
    }
    EXPECT_NEAR(lc.force[0] + lc.force[1], F, 1e-9 * F);
  }
}

// Coupled pair without gaps whose linear solution puts pair 2 in tension:
// C = [[1, 1.5], [1.5, 4]] (x1e-9): C^-1 1 = [2.5, -0.5]/1.75; pair 2 opens,
// delta = F c11, and pair 2's surface moves away by F c21 - delta > 0.
TEST(LoadedContact, CoupledPairThatWouldPullOpens) {
  const double F = 1e4;
  const std::vector<double> C{1e-9, 1.5e-9, 1.5e-9, 4e-9};
  const LoadedContact lc = solve_loaded_contact(C, std::vector<double>{0, 0}, F);
  EXPECT_NEAR(lc.approach, F * 1e-9, 1e-20);
  EXPECT_EQ(lc.force[1], 0.0);
  EXPECT_NEAR(lc.force[0], F, 1e-9);
  EXPECT_NEAR(lc.tangent_stiffness, 1e9, 1e-3);
}

// Random SPD matrices and gaps: the result satisfies the conditions of the
// minimum (forces >= 0 summing to F, loaded pairs at delta - g, open pairs
// not penetrating), and delta grows with F and with any gap.
TEST(LoadedContact, OptimalityConditionsOnRandomProblems) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 1 + trial % 4;
    std::vector<double> A(n * n), C(n * n, 0.0), g(n);
    for (double& a : A) a = u(rng) - 0.5;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < n; ++k) {
        for (std::size_t q = 0; q < n; ++q) C[i * n + k] += A[i * n + q] * A[k * n + q] * 1e-9;
      }
      C[i * n + i] += 0.3e-9;
      g[i] = u(rng) < 0.5 ? 0.0 : 30e-6 * u(rng);
    }
    const double F = 5e4;
    const LoadedContact lc = solve_loaded_contact(C, g, F);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_GE(lc.force[i], 0.0);
      sum += lc.force[i];
    }
    ASSERT_NEAR(sum, F, 1e-9 * F);
    for (std::size_t i = 0; i < n; ++i) {
      double Cf = 0;
      for (std::size_t k = 0; k < n; ++k) Cf += C[i * n + k] * lc.force[k];
      const double slack = Cf + g[i] - lc.approach;  // 0 when loaded, >= 0 when open
      if (lc.loaded[i]) {
        ASSERT_NEAR(slack, 0.0, 1e-9 * (F * 1e-9 + 30e-6));
      } else {
        ASSERT_GE(slack, -1e-9 * (F * 1e-9 + 30e-6));
      }
    }
    const LoadedContact more_load = solve_loaded_contact(C, g, 1.1 * F);
    ASSERT_GT(more_load.approach, lc.approach);
    std::vector<double> g2 = g;
    g2[trial % n] += 5e-6;
    ASSERT_GE(solve_loaded_contact(C, g2, F).approach, lc.approach - 1e-18);
  }
}

TEST(LoadedContact, RejectsBadSizes) {
  EXPECT_THROW(solve_loaded_contact(std::vector<double>{}, std::vector<double>{}, 1.0), std::invalid_argument);
  EXPECT_THROW(solve_loaded_contact(std::vector<double>{1, 2, 3}, std::vector<double>{0, 0}, 1.0),
               std::invalid_argument);
  EXPECT_THROW(solve_loaded_contact(std::vector<double>{1e-9}, std::vector<double>{0}, -1.0), std::invalid_argument);
  EXPECT_THROW(solve_loaded_contact(std::vector<double>{-1e-9}, std::vector<double>{0}, 1.0), std::runtime_error);
}

}  // namespace
}  // namespace rackopt
