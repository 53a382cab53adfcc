#include "rackopt/stiffness/period_stats.hpp"

#include <algorithm>
#include <cmath>

#include "rackopt/stiffness/curve_numerics.hpp"

namespace rackopt {
namespace {

struct Point {
  double x = 0, y = 0;
};

}  // namespace

double curve_quantity(const MeshState& state, CurveQuantity quantity) {
  return quantity == CurveQuantity::kStiffness ? state.stiffness : state.approach;
}

std::vector<PeriodStats> period_stats(const MeshStiffnessModel& model, const StiffnessCurve& curve,
                                      CurveQuantity quantity) {
  const double p = M_PI * model.drive().pinion.module;
  const double span = model.drive().rack.span;
  const double tol = 1e-9 * p;
  std::vector<std::pair<double, double>> windows;
  const int whole = static_cast<int>(std::floor(span / p + 1e-9));
  for (int k = 0; k < whole; ++k) windows.emplace_back(k * p, std::min((k + 1) * p, span));
  if (whole == 0) {
    windows.emplace_back(0.0, span);
  } else if (span - whole * p > tol) {
    windows.emplace_back(span - p, span);
  }

  const std::vector<MeshState>& s = curve.samples;
  const std::size_t n = s.size();
  auto same_x = [&](double a, double b) { return std::abs(a - b) <= tol; };
  auto value_at = [&](double X, int side) { return curve_quantity(model.at(X, side), quantity); };

  std::vector<PeriodStats> out;
  out.reserve(windows.size());
  std::vector<Point> pts;
  for (const auto& [a, b] : windows) {
    // The window's points: its samples, at a discontinuity on an edge only
    // the limit from inside, and the edge values themselves when no sample
    // falls there.
    pts.clear();
    std::size_t i = static_cast<std::size_t>(
        std::lower_bound(s.begin(), s.end(), a - tol, [](const MeshState& m, double x) { return m.travel < x; }) -
        s.begin());
    if (i < n && same_x(s[i].travel, a)) {
      if (i + 1 < n && same_x(s[i + 1].travel, a)) ++i;  // right limit
    } else {
      pts.push_back({a, value_at(a, +1)});
    }
    for (; i < n && s[i].travel < b - tol; ++i) pts.push_back({s[i].travel, curve_quantity(s[i], quantity)});
    if (i < n && same_x(s[i].travel, b)) {
      pts.push_back({s[i].travel, curve_quantity(s[i], quantity)});  // left limit (first of a pair)
    } else {
      pts.push_back({b, value_at(b, -1)});
    }

    PeriodStats w;
    w.start = a;
    w.end = b;
    const std::size_t m = pts.size();
    std::size_t i_min = 0, i_max = 0;
    for (std::size_t k = 1; k < m; ++k) {
      if (pts[k].y < pts[i_min].y) i_min = k;
      if (pts[k].y > pts[i_max].y) i_max = k;
    }
    w.min = pts[i_min].y;
    w.travel_at_min = pts[i_min].x;
    w.max = pts[i_max].y;
    w.travel_at_max = pts[i_max].x;

    // Two points at the same travel are the two limits of a discontinuity:
    // they end one smooth piece and start the next.
    auto smooth = [&](std::size_t k) { return pts[k + 1].x - pts[k].x > tol; };
    // Extremes between samples: golden section around each sampled local
    // extreme of a smooth piece close to the window's extreme (as curve()).
    const double x_tol = 1e-7 * p;
    const double range = std::max(w.max - w.min, 1e-300);
    for (std::size_t k = 1; k + 1 < m; ++k) {
      if (!smooth(k - 1) || !smooth(k)) continue;
      const double y0 = pts[k - 1].y, y1 = pts[k].y, y2 = pts[k + 1].y;
      const double lo = pts[k - 1].x, hi = pts[k + 1].x;
      if (y1 <= y0 && y1 <= y2 && y1 - w.min <= 1e-2 * range) {
        auto [x, v] = golden_min([&](double X) { return value_at(X, 0); }, lo, hi, x_tol);
        if (v < w.min) {
          w.min = v;
          w.travel_at_min = x;
        }
      }
      if (y1 >= y0 && y1 >= y2 && w.max - y1 <= 1e-2 * range) {
        auto [x, v] = golden_min([&](double X) { return -value_at(X, 0); }, lo, hi, x_tol);
        if (-v > w.max) {
          w.max = -v;
          w.travel_at_max = x;
        }
      }
    }

    // Mean: the cubic through neighbouring points of the same smooth piece.
    double integral = 0;
    for (std::size_t k = 0; k + 1 < m; ++k) {
      if (!smooth(k)) continue;
      double xs[4], ys[4];
      int c = 0;
      const std::size_t first = (k > 0 && smooth(k - 1)) ? k - 1 : k;
      const std::size_t last = (k + 2 < m && smooth(k + 1)) ? k + 2 : k + 1;
      for (std::size_t q = first; q <= last; ++q) {
        xs[c] = pts[q].x;
        ys[c] = pts[q].y;
        ++c;
      }
      integral += interval_integral(xs, ys, c, pts[k].x, pts[k + 1].x);
    }
    w.mean = b > a ? integral / (b - a) : pts[0].y;
    out.push_back(w);
  }
  return out;
}

}  // namespace rackopt
