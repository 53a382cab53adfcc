#include "rackopt/solvers/front_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "rackopt/solvers/pagmo_library.hpp"
#include "rackopt/solvers/pareto.hpp"

namespace rackopt::solvers {

namespace {

void check_sizes(const ObjectiveVectors& points, std::size_t m) {
  for (const auto& p : points)
    if (p.size() != m)
      throw std::invalid_argument("front quality: an objective vector has " + std::to_string(p.size()) +
                                  " values, expected " + std::to_string(m));
}

std::vector<double> range_of(const ObjectiveVectors& front, std::vector<double>* ideal) {
  const std::size_t m = front.empty() ? 0 : front[0].size();
  std::vector<double> lo(m, std::numeric_limits<double>::infinity()), hi(m, -std::numeric_limits<double>::infinity());
  for (const auto& p : front)
    for (std::size_t k = 0; k < m; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  if (ideal) *ideal = lo;
  std::vector<double> r(m);
  for (std::size_t k = 0; k < m; ++k) r[k] = hi[k] - lo[k];
  return r;
}

}  // namespace

std::vector<double> default_reference_point(const ObjectiveVectors& front) {
  if (front.empty()) return {};
  const std::size_t m = front[0].size();
  check_sizes(front, m);
  std::vector<double> ideal;
  const std::vector<double> range = range_of(front, &ideal);
  std::vector<double> ref(m);
  for (std::size_t k = 0; k < m; ++k) {
    const double worst = ideal[k] + range[k];
    ref[k] = worst + (range[k] > 0 ? 0.1 * range[k] : 1e-3 * std::max(1.0, std::abs(worst)));
  }
  return ref;
}

double hypervolume(const ObjectiveVectors& points, std::span<const double> reference) {
  const std::size_t m = reference.size();
  check_sizes(points, m);
  ObjectiveVectors inside;
  for (const auto& p : points) {
    bool better = true;
    for (std::size_t k = 0; k < m && better; ++k) better = p[k] < reference[k];
    if (better) inside.push_back(p);
  }
  if (inside.empty()) return 0.0;
  if (m == 1) {
    double best = inside[0][0];
    for (const auto& p : inside) best = std::min(best, p[0]);
    return reference[0] - best;
  }
  // pagmo (through its module, opened here the first time) wants at least 2
  // objectives and points that dominate the reference.
  return pagmo_api().hypervolume(inside, std::vector<double>(reference.begin(), reference.end()));
}

double spacing(const ObjectiveVectors& front) {
  const std::size_t n = front.size();
  if (n < 3) return 0.0;
  const std::size_t m = front[0].size();
  check_sizes(front, m);
  std::vector<double> range = range_of(front, nullptr);
  for (double& r : range)
    if (!(r > 0)) r = 1.0;
  std::vector<double> d(n, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      double l1 = 0;
      for (std::size_t k = 0; k < m; ++k) l1 += std::abs(front[i][k] - front[j][k]) / range[k];
      d[i] = std::min(d[i], l1);
    }
  double mean = 0;
  for (double v : d) mean += v;
  mean /= static_cast<double>(n);
  double ss = 0;
  for (double v : d) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / static_cast<double>(n - 1));
}

FrontQuality front_quality(const ObjectiveVectors& front, std::span<const double> reference) {
  FrontQuality q;
  q.points = front.size();
  if (front.empty()) return q;
  q.non_dominated = non_dominated(front).size();
  range_of(front, &q.ideal);
  q.reference = reference.empty() ? default_reference_point(front)
                                  : std::vector<double>(reference.begin(), reference.end());
  double box = 1;
  for (std::size_t k = 0; k < q.ideal.size(); ++k) box *= q.reference[k] - q.ideal[k];
  q.hypervolume = box > 0 ? hypervolume(front, q.reference) / box : 0.0;
  q.spacing = spacing(front);
  return q;
}

}  // namespace rackopt::solvers
