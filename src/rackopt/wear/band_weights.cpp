#include "rackopt/wear/band_weights.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace rackopt {
namespace {

// Semicircle (elliptic pressure) weight integrals on [-1, 1]:
// F0' = sqrt(1-u^2), F1' = u sqrt(1-u^2). Both at once: they share the root.
struct Primitives {
  double f0, f1;
};
Primitives F01(double u) {
  const double q = std::max(1.0 - u * u, 0.0);
  const double r = std::sqrt(q);
  return {0.5 * (u * r + std::asin(u)), -q * r / 3.0};
}

// The first segment k in [0, segments) for which `before(k)` is false, when
// `before` holds on a prefix of the segments (binary search).
template <class Before>
std::size_t first_segment_not(std::size_t segments, Before before) {
  std::size_t lo = 0, hi = segments;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (before(mid)) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

}  // namespace

bool load_intervals_sorted(const std::vector<double>& node_c, const LoadIntervals& intervals) {
  for (const auto& iv : intervals)
    for (std::size_t k = 0; k + 1 < iv.size(); ++k)
      if (!(node_c[iv[k]] <= node_c[iv[k + 1]])) return false;
  return true;
}

void pointwise_weights(const std::vector<double>& node_c, const LoadIntervals& intervals, double c,
                       std::vector<int>& idx, std::vector<double>& val) {
  for (const auto& iv : intervals) {
    if (iv.size() < 2) continue;
    // Segments that end before c cannot hold it; with non-decreasing nodes
    // they are a prefix (and the test below is false on each of them).
    std::size_t k = first_segment_not(iv.size() - 1, [&](std::size_t j) { return !(c <= node_c[iv[j + 1]]); });
    for (; k + 1 < iv.size(); ++k) {
      const double ca = node_c[iv[k]], cb = node_c[iv[k + 1]];
      if (ca > c) break;  // this and every later segment start past c
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

void band_weights(const std::vector<double>& node_c, const LoadIntervals& intervals, double c, double L,
                  std::vector<int>& idx, std::vector<double>& val) {
  const double k2pi = 2.0 / M_PI;
  // The upper node's weight of the last segment, kept out of `val` until the
  // next segment's lower part is added to it (the same sum as adding to
  // val.back(), without a round trip through memory between the two
  // divisions of consecutive segments, which serialized the loop).
  int pending_idx = -1;
  double pending_val = 0;
  auto flush = [&] {
    if (pending_idx < 0) return;
    idx.push_back(pending_idx);
    val.push_back(pending_val);
    pending_idx = -1;
  };
  for (const auto& iv : intervals) {
    if (iv.size() < 2) continue;  // no segment
    if (node_c[iv.back()] <= c - L || node_c[iv.front()] >= c + L) continue;
    // Segments wholly below the band (ub <= -1) are a prefix: start after
    // them. u = (node - c)/L is computed as in the loop, and it is monotone
    // in the node coordinate (rounding is), so the same segments are skipped.
    // The search compares without dividing (node - c <= -L, which can
    // differ from u <= -1 only by a rounding at the band's edge), and the
    // exact test then moves the start to where the loop's own expression
    // puts it.
    const auto below = [&](std::size_t j) { return (node_c[iv[j + 1]] - c) / L <= -1; };
    std::size_t k = first_segment_not(iv.size() - 1, [&](std::size_t j) { return node_c[iv[j + 1]] - c <= -L; });
    while (k > 0 && below(k - 1) == false) --k;
    while (k + 1 < iv.size() && below(k)) ++k;
    // F0, F1 at the previous segment's upper end are reused (asin is the cost).
    double prev_u = std::nan(""), prev_f0 = 0, prev_f1 = 0;
    // A segment's lower u is the previous one's upper u (the same expression
    // of the same node): carried over, not divided again.
    double ub = (node_c[iv[k]] - c) / L;
    for (; k + 1 < iv.size(); ++k) {
      const double ua = ub;
      ub = (node_c[iv[k + 1]] - c) / L;
      if (ua >= 1) break;  // this and every later segment lie above the band
      if (!(ub > ua) || ub <= -1) continue;
      const double u1 = std::max(ua, -1.0), u2 = std::min(ub, 1.0);
      const Primitives fa = u1 == prev_u ? Primitives{prev_f0, prev_f1} : F01(u1);
      const double f0a = fa.f0, f1a = fa.f1;
      const Primitives fb = F01(u2);
      prev_u = u2;
      prev_f0 = fb.f0;
      prev_f1 = fb.f1;
      const double I0 = prev_f0 - f0a, I1 = prev_f1 - f1a;
      const double du = ub - ua;
      // The lower node is usually the previous segment's upper node: merge.
      const double lower = k2pi * (ub * I0 - I1) / du;
      if (pending_idx == iv[k]) {
        pending_val += lower;
        flush();
      } else {
        flush();
        idx.push_back(iv[k]);
        val.push_back(lower);
      }
      pending_idx = iv[k + 1];
      pending_val = k2pi * (I1 - ua * I0) / du;
    }
  }
  flush();
}

}  // namespace rackopt
