// Band and pointwise weights (src/rackopt/wear/band_weights.hpp): the
// windowed search gives the weights of a visit of every segment bit for bit,
// and the band mean reproduces constant and linear loads.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "rackopt/wear/band_weights.hpp"

namespace rackopt {
namespace {

// The full visits: every segment of every interval, the definition the
// windowed functions must reproduce.
double ref_F0(double u) { return 0.5 * (u * std::sqrt(std::max(1.0 - u * u, 0.0)) + std::asin(u)); }
double ref_F1(double u) {
  const double q = std::max(1.0 - u * u, 0.0);
  return -q * std::sqrt(q) / 3.0;
}

void full_pointwise(const std::vector<double>& node_c, const LoadIntervals& intervals, double c,
                    std::vector<int>& idx, std::vector<double>& val) {
  for (const auto& iv : intervals) {
    for (std::size_t k = 0; k + 1 < iv.size(); ++k) {
      const double ca = node_c[iv[k]], cb = node_c[iv[k + 1]];
      if (c >= ca && c <= cb && cb > ca) {
        const double t = (c - ca) / (cb - ca);
        idx.push_back(iv[k]);
        val.push_back(1 - t);
        idx.push_back(iv[k + 1]);
        val.push_back(t);
        return;
      }
    }
  }
}

void full_band(const std::vector<double>& node_c, const LoadIntervals& intervals, double c, double L,
               std::vector<int>& idx, std::vector<double>& val) {
  const double k2pi = 2.0 / M_PI;
  const std::size_t first = idx.size();
  for (const auto& iv : intervals) {
    if (node_c[iv.back()] <= c - L || node_c[iv.front()] >= c + L) continue;
    double prev_u = std::nan(""), prev_f0 = 0, prev_f1 = 0;
    for (std::size_t k = 0; k + 1 < iv.size(); ++k) {
      const double ua = (node_c[iv[k]] - c) / L, ub = (node_c[iv[k + 1]] - c) / L;
      if (!(ub > ua) || ub <= -1 || ua >= 1) continue;
      const double u1 = std::max(ua, -1.0), u2 = std::min(ub, 1.0);
      const double f0a = u1 == prev_u ? prev_f0 : ref_F0(u1), f1a = u1 == prev_u ? prev_f1 : ref_F1(u1);
      prev_u = u2;
      prev_f0 = ref_F0(u2);
      prev_f1 = ref_F1(u2);
      const double I0 = prev_f0 - f0a, I1 = prev_f1 - f1a;
      const double du = ub - ua;
      if (idx.size() > first && idx.back() == iv[k]) {
        val.back() += k2pi * (ub * I0 - I1) / du;
      } else {
        idx.push_back(iv[k]);
        val.push_back(k2pi * (ub * I0 - I1) / du);
      }
      idx.push_back(iv[k + 1]);
      val.push_back(k2pi * (I1 - ua * I0) / du);
    }
  }
}

std::vector<std::uint64_t> bits(const std::vector<double>& v) {
  std::vector<std::uint64_t> b;
  for (double x : v) b.push_back(std::bit_cast<std::uint64_t>(x));
  return b;
}

// A path like the wear model's: `pairs` intervals of `m` nodes each, the
// nodes of interval j at lo + j p + (uniform phase), some repeated (a node
// snapped to the path end) and the intervals interleaved in the node array.
struct Nodes {
  std::vector<double> c;
  LoadIntervals intervals;
};
Nodes make_nodes(std::mt19937_64& rng, int pairs, int m, bool duplicates) {
  std::uniform_real_distribution<double> U(0, 1);
  Nodes n;
  const double p = 0.1 + U(rng), lo = U(rng) - 0.5, frac = 0.2 + 0.6 * U(rng);
  const double end = lo + (pairs - 1 + frac) * p;
  n.intervals.assign(pairs, {});
  for (int k = 0; k < m; ++k) {
    const double phi = frac * p * k / (m - 1);
    for (int j = 0; j < pairs; ++j) {
      double c = lo + phi + j * p;
      if (duplicates && c > end - 0.05 * p) c = end;
      n.intervals[j].push_back(static_cast<int>(n.c.size()));
      n.c.push_back(c);
    }
  }
  return n;
}

TEST(BandWeights, WindowedSearchEqualsTheFullVisitBitForBit) {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> U(0, 1);
  long compared = 0, nonempty = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Nodes n = make_nodes(rng, 1 + trial % 3, 2 + static_cast<int>(U(rng) * 200), trial % 2 == 0);
    ASSERT_TRUE(load_intervals_sorted(n.c, n.intervals));
    const double c_lo = *std::min_element(n.c.begin(), n.c.end()), c_hi = *std::max_element(n.c.begin(), n.c.end());
    for (int q = 0; q < 40; ++q) {
      // Points on, between and off the nodes; bands from a fraction of one
      // segment to wider than the path.
      double c = c_lo - 0.1 + (c_hi - c_lo + 0.2) * U(rng);
      if (q % 4 == 0) c = n.c[static_cast<std::size_t>(U(rng) * static_cast<double>(n.c.size()))];
      double L = std::pow(10.0, -4 + 4.5 * U(rng));
      if (q % 5 == 0) L = std::abs(n.c[static_cast<std::size_t>(U(rng) * static_cast<double>(n.c.size()))] - c);
      if (!(L > 0)) L = 1e-3;
      std::vector<int> i1{7}, i2{7};  // a previous point's weights in front
      std::vector<double> v1{0.5}, v2{0.5};
      full_band(n.c, n.intervals, c, L, i1, v1);
      band_weights(n.c, n.intervals, c, L, i2, v2);
      ASSERT_EQ(i1, i2) << "trial " << trial << " c " << c << " L " << L;
      ASSERT_EQ(bits(v1), bits(v2)) << "trial " << trial << " c " << c << " L " << L;
      std::vector<int> j1, j2;
      std::vector<double> w1, w2;
      full_pointwise(n.c, n.intervals, c, j1, w1);
      pointwise_weights(n.c, n.intervals, c, j2, w2);
      ASSERT_EQ(j1, j2) << "trial " << trial << " c " << c;
      ASSERT_EQ(bits(w1), bits(w2)) << "trial " << trial << " c " << c;
      ++compared;
      nonempty += i1.size() > 1 ? 1 : 0;
    }
  }
  EXPECT_EQ(compared, 300 * 40);
  EXPECT_GT(nonempty, compared / 2);  // most bands meet the path: the comparison is not vacuous
}

// The band mean of a load that is linear along one interval is the load at
// the band's centre (the semicircle weight is symmetric), and a band reaching
// past the interval's ends sees zero there.
TEST(BandWeights, BandMeanOfLinearLoad) {
  std::vector<double> c;
  LoadIntervals iv(1);
  for (int k = 0; k <= 100; ++k) {
    iv[0].push_back(k);
    c.push_back(0.01 * k);
  }
  std::vector<double> P(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) P[k] = 3.0 + 2.0 * c[k];
  auto mean = [&](double x, double L) {
    std::vector<int> idx;
    std::vector<double> val;
    band_weights(c, iv, x, L, idx, val);
    double w = 0;
    for (std::size_t k = 0; k < idx.size(); ++k) w += val[k] * P[idx[k]];
    return w;
  };
  EXPECT_NEAR(mean(0.5, 0.123), 3.0 + 2.0 * 0.5, 1e-12);
  EXPECT_NEAR(mean(0.3337, 0.05), 3.0 + 2.0 * 0.3337, 1e-12);
  // Centred on the path's end: half the band is off the path.
  const double half = mean(1.0, 1e-4);
  EXPECT_NEAR(half, 0.5 * 5.0, 1e-3);
  // A band wholly off the path sees nothing.
  EXPECT_EQ(mean(1.5, 0.1), 0.0);
}

TEST(BandWeights, PointwiseTakesTheLeftLimitAtAJump) {
  // Two intervals meeting at 1.0: the first one listed holds the shared point.
  const std::vector<double> c{0.0, 1.0, 1.0, 2.0};
  const LoadIntervals iv{{0, 1}, {2, 3}};
  std::vector<int> idx;
  std::vector<double> val;
  pointwise_weights(c, iv, 1.0, idx, val);
  ASSERT_EQ(idx, (std::vector<int>{0, 1}));
  EXPECT_EQ(val[1], 1.0);
  idx.clear();
  val.clear();
  pointwise_weights(c, iv, 2.5, idx, val);  // off the path: no weights
  EXPECT_TRUE(idx.empty());
  EXPECT_FALSE(load_intervals_sorted({0.0, 2.0, 1.0}, {{0, 1, 2}}));
}

}  // namespace
}  // namespace rackopt
