// Tests of the design-of-experiments samplers. Expected values come from the
// definitions (grid order written out by hand, strata counted), from known
// properties of the Sobol sequence (each coordinate of the first 2^m points
// hits every dyadic interval once; the first two dimensions form a
// (0,m,2)-net; index 1 is the centre), and from closed-form integrals.
#include "rackopt/doe/samplers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace rackopt::doe {
namespace {

using Points = std::vector<std::vector<double>>;

std::string thrown_message(auto&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<nothing thrown>";
}

// Stratum index of x in [lo, hi] cut into n equal strata.
std::size_t stratum_of(double x, double lo, double hi, std::size_t n) {
  return static_cast<std::size_t>(std::floor((x - lo) / (hi - lo) * static_cast<double>(n)));
}

// True when column d of the points hits each of n strata exactly once.
bool one_per_stratum(const Points& p, std::size_t d, double lo, double hi) {
  std::vector<int> hits(p.size(), 0);
  for (const auto& x : p) {
    const std::size_t s = stratum_of(x[d], lo, hi, p.size());
    if (s >= p.size()) return false;
    ++hits[s];
  }
  return std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; });
}

TEST(FullGrid, FirstVariableSlowest) {
  // Written out by hand from "nested loops in variable order".
  const Points expected = {{1, 10}, {1, 20}, {1, 30}, {2, 10}, {2, 20}, {2, 30}};
  EXPECT_EQ(full_grid({{1, 2}, {10, 20, 30}}), expected);
}

TEST(FullGrid, SizeIsProductOfLevelCounts) {
  const Points g = full_grid({{0, 1}, {0, 1, 2}, {5}, {7, 8, 9, 10}});
  ASSERT_EQ(g.size(), 2u * 3u * 1u * 4u);
  std::set<std::vector<double>> distinct(g.begin(), g.end());
  EXPECT_EQ(distinct.size(), g.size());
  // Last variable fastest: consecutive points differ in it first.
  EXPECT_EQ(g[0][3], 7);
  EXPECT_EQ(g[1][3], 8);
  EXPECT_EQ(g[4][1], 1);  // after 4 values of the last variable, the second one moves (third has 1 level)
}

TEST(FullGrid, RejectsTooManyPointsAndEmptyInput) {
  EXPECT_NO_THROW(full_grid({{1, 2}, {1, 2, 3}}, 6));
  EXPECT_NE(thrown_message([] { full_grid({{1, 2}, {1, 2, 3}}, 5); }).find("more than 5"),
            std::string::npos);
  // 40 variables of 1000 levels: 10^120 points, must be refused without overflow.
  const std::vector<std::vector<double>> huge(40, std::vector<double>(1000, 1.0));
  EXPECT_THROW(full_grid(huge), std::invalid_argument);
  EXPECT_THROW(full_grid({}), std::invalid_argument);
  EXPECT_THROW(full_grid({{1, 2}, {}}), std::invalid_argument);
  EXPECT_THROW(full_grid({{1, NAN}}), std::invalid_argument);
}

TEST(Linspace, EndsExactAndEvenSpacing) {
  const auto v = linspace_levels(0.1, 0.7, 7);
  ASSERT_EQ(v.size(), 7u);
  EXPECT_EQ(v.front(), 0.1);
  EXPECT_EQ(v.back(), 0.7);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_NEAR(v[i], 0.1 + 0.1 * static_cast<double>(i), 1e-15);  // step (0.7-0.1)/6 = 0.1
  }
  EXPECT_EQ(linspace_levels(2.0, 4.0, 1), std::vector<double>{3.0});  // centre
  EXPECT_EQ(linspace_levels(2.0, 2.0, 3), std::vector<double>(3, 2.0));
  EXPECT_THROW(linspace_levels(0, 1, 0), std::invalid_argument);
  EXPECT_THROW(linspace_levels(1, 0, 3), std::invalid_argument);
  EXPECT_THROW(linspace_levels(0, INFINITY, 3), std::invalid_argument);
}

TEST(LatinHypercube, OnePointPerStratumInEveryDimension) {
  const std::vector<double> lo = {0.0, -3.0, 1e-3, 100.0, 5.0};
  const std::vector<double> hi = {1.0, 3.0, 2e-3, 1000.0, 5.5};
  const std::size_t n = 97;
  const Points p = latin_hypercube(lo, hi, n, 42);
  ASSERT_EQ(p.size(), n);
  for (std::size_t d = 0; d < lo.size(); ++d) {
    EXPECT_TRUE(one_per_stratum(p, d, lo[d], hi[d])) << "dimension " << d;
    for (const auto& x : p) {
      EXPECT_GE(x[d], lo[d]);
      EXPECT_LE(x[d], hi[d]);
    }
  }
}

TEST(LatinHypercube, RandomWithinStrataNotCentred) {
  // Offsets inside the strata are uniform on [0,1): mean 1/2, variance 1/12.
  const std::size_t n = 400;
  const std::vector<double> lo = {0.0, 0.0}, hi = {1.0, 1.0};
  const Points p = latin_hypercube(lo, hi, n, 7);
  double sum = 0, sum2 = 0;
  for (const auto& x : p) {
    for (double v : x) {
      const double offset = v * n - std::floor(v * n);
      sum += offset;
      sum2 += offset * offset;
    }
  }
  const double m = sum / (2.0 * n), var = sum2 / (2.0 * n) - m * m;
  // Standard error of the mean of 800 uniforms: sqrt(1/12/800) = 0.0102.
  EXPECT_NEAR(m, 0.5, 0.04);
  EXPECT_NEAR(var, 1.0 / 12.0, 0.02);  // centred strata would give variance 0
  // Dimensions use different permutations (identical ones would put every point on the diagonal).
  int same = 0;
  for (const auto& x : p) same += stratum_of(x[0], 0, 1, n) == stratum_of(x[1], 0, 1, n);
  EXPECT_LT(same, 10);
}

TEST(LatinHypercube, DeterministicBySeedAndEdgeCases) {
  const std::vector<double> lo = {0, 0, 0}, hi = {1, 2, 3};
  EXPECT_EQ(latin_hypercube(lo, hi, 20, 5), latin_hypercube(lo, hi, 20, 5));
  EXPECT_NE(latin_hypercube(lo, hi, 20, 5), latin_hypercube(lo, hi, 20, 6));
  EXPECT_TRUE(latin_hypercube(lo, hi, 0, 5).empty());
  const Points one = latin_hypercube(lo, hi, 1, 5);
  ASSERT_EQ(one.size(), 1u);
  for (std::size_t d = 0; d < 3; ++d) {
    EXPECT_GE(one[0][d], lo[d]);
    EXPECT_LE(one[0][d], hi[d]);
  }
  const std::vector<double> flat_lo = {1.5, 0}, flat_hi = {1.5, 1};
  for (const auto& x : latin_hypercube(flat_lo, flat_hi, 10, 1)) EXPECT_EQ(x[0], 1.5);
  const std::vector<double> bad_hi = {1, 2};
  EXPECT_THROW(latin_hypercube(lo, bad_hi, 4, 1), std::invalid_argument);
  const std::vector<double> inverted = {1, -1, 3};
  EXPECT_THROW(latin_hypercube(lo, inverted, 4, 1), std::invalid_argument);
  EXPECT_THROW(latin_hypercube({}, {}, 4, 1), std::invalid_argument);
}

TEST(Sobol, FirstPointsAreCornerThenCentre) {
  const std::vector<double> lo = {-1.0, 10.0, 0.0}, hi = {1.0, 20.0, 4.0};
  const Points p = sobol_points(lo, hi, 2, 0);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0], lo);                                  // index 0: the origin
  EXPECT_EQ(p[1], (std::vector<double>{0.0, 15.0, 2.0}));  // index 1: (1/2, ..., 1/2)
  EXPECT_EQ(sobol_points(lo, hi, 1, 0), Points{lo});
  EXPECT_TRUE(sobol_points(lo, hi, 0, 0).empty());
}

TEST(Sobol, EveryCoordinateBalancedForPowerOfTwo) {
  // Each one-dimensional projection of a Sobol sequence is a (0,1)-sequence:
  // the first 2^m points hit every interval of width 2^-m exactly once. The
  // digital shift (seed != 0) permutes those intervals, so it must hold too.
  const std::vector<double> lo(40, 0.0), hi(40, 1.0);
  for (std::uint64_t seed : {0ull, 12345ull}) {
    const Points p = sobol_points(lo, hi, 256, seed);
    for (std::size_t d = 0; d < 40; ++d) {
      EXPECT_TRUE(one_per_stratum(p, d, 0.0, 1.0)) << "seed " << seed << " dimension " << d;
    }
  }
}

TEST(Sobol, FirstTwoDimensionsFormANet) {
  // (0,m,2)-net: every dyadic box of area 2^-m, [a 2^-j,(a+1) 2^-j) x
  // [b 2^-(m-j),(b+1) 2^-(m-j)), holds exactly one of the first 2^m points.
  const int m = 6;
  const std::size_t n = std::size_t{1} << m;
  const std::vector<double> lo = {0, 0}, hi = {1, 1};
  for (std::uint64_t seed : {0ull, 99ull}) {
    const Points p = sobol_points(lo, hi, n, seed);
    for (int j = 0; j <= m; ++j) {
      const std::size_t nx = std::size_t{1} << j, ny = n / nx;
      std::vector<int> hits(n, 0);
      for (const auto& x : p) ++hits[stratum_of(x[0], 0, 1, nx) * ny + stratum_of(x[1], 0, 1, ny)];
      EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }))
          << "seed " << seed << " boxes " << nx << " x " << ny;
    }
  }
}

TEST(Sobol, IntegratesSmoothFunctionFarBetterThanMonteCarlo) {
  // f(y) = prod_i (pi/2) sin(pi t_i), t = (y - 2)/3 on [2,5]^5: mean over the box is exactly 1.
  // Plain Monte Carlo with n points has standard error sqrt(E[f^2]-1)/sqrt(n),
  // E[f^2] = (pi^2/8)^5 (closed form), i.e. 0.0213 for n = 4096.
  const std::size_t d = 5, n = 4096;
  const std::vector<double> lo(d, 2.0), hi(d, 5.0);
  auto f = [&](const std::vector<double>& y) {
    double v = 1;
    for (double yi : y) v *= std::numbers::pi / 2 * std::sin(std::numbers::pi * (yi - 2.0) / 3.0);
    return v;
  };
  const double mc_std_error =
      std::sqrt(std::pow(std::numbers::pi * std::numbers::pi / 8, 5) - 1) / std::sqrt(double(n));
  double worst_sobol = 0;
  double mc_sq = 0;
  for (std::uint64_t seed : {0ull, 1ull, 2ull, 3ull}) {
    double s = 0;
    for (const auto& y : sobol_points(lo, hi, n, seed)) s += f(y);
    worst_sobol = std::max(worst_sobol, std::abs(s / n - 1.0));
    // Pseudo-random reference with the same budget.
    std::mt19937_64 rng(seed + 100);
    double r = 0;
    std::vector<double> y(d);
    for (std::size_t i = 0; i < n; ++i) {
      for (auto& yi : y) yi = 2.0 + 3.0 * static_cast<double>(rng() >> 11) * 0x1p-53;
      r += f(y);
    }
    mc_sq += (r / n - 1.0) * (r / n - 1.0);
  }
  EXPECT_LT(worst_sobol, 0.1 * mc_std_error);
  EXPECT_LT(worst_sobol, std::sqrt(mc_sq / 4));  // also beats the pseudo-random runs actually made
}

TEST(Sobol, DeterministicBySeedAndInBox) {
  const std::vector<double> lo = {0.5, -2.0}, hi = {0.75, 8.0};
  const Points a = sobol_points(lo, hi, 100, 17);
  EXPECT_EQ(a, sobol_points(lo, hi, 100, 17));
  EXPECT_NE(a, sobol_points(lo, hi, 100, 18));
  EXPECT_NE(a, sobol_points(lo, hi, 100, 0));
  for (const auto& x : a) {
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_GE(x[k], lo[k]);
      EXPECT_LT(x[k], hi[k]);
    }
  }
  // A longer run starts with the shorter one (a sequence, not a set).
  const Points longer = sobol_points(lo, hi, 150, 17);
  EXPECT_TRUE(std::equal(a.begin(), a.end(), longer.begin()));
}

TEST(Sobol, RejectsMoreThan40Dimensions) {
  const std::vector<double> lo40(40, 0.0), hi40(40, 1.0);
  EXPECT_NO_THROW(sobol_points(lo40, hi40, 8, 0));
  const std::vector<double> lo(41, 0.0), hi(41, 1.0);
  const std::string msg = thrown_message([&] { sobol_points(lo, hi, 8, 0); });
  EXPECT_NE(msg.find("41 variables"), std::string::npos) << msg;
  EXPECT_NE(msg.find("at most 40"), std::string::npos) << msg;
  EXPECT_NE(msg.find("latin_hypercube"), std::string::npos) << msg;
  EXPECT_THROW(sobol_points(lo40, hi40, std::size_t{1} << 30, 0), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt::doe
