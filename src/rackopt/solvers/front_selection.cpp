#include "rackopt/solvers/front_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace rackopt::solvers {

std::vector<double> crowding_distances(const std::vector<std::vector<double>>& front) {
  const std::size_t n = front.size();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> d(n, 0.0);
  if (n <= 2) return std::vector<double>(n, kInf);
  const std::size_t m = front[0].size();
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < m; ++k) {
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return front[a][k] < front[b][k]; });
    const double range = front[order.back()][k] - front[order.front()][k];
    d[order.front()] = kInf;
    d[order.back()] = kInf;
    if (!(range > 0)) continue;
    for (std::size_t i = 1; i + 1 < n; ++i)
      d[order[i]] += (front[order[i + 1]][k] - front[order[i - 1]][k]) / range;
  }
  return d;
}

std::vector<std::size_t> select_front_indices(const std::vector<std::vector<double>>& vectors, std::size_t points,
                                              double duplicate_tolerance) {
  std::vector<std::size_t> kept = non_dominated(vectors);
  if (kept.empty()) return kept;
  const std::size_t m = vectors[kept[0]].size();

  std::vector<double> lo(m, std::numeric_limits<double>::infinity()), hi(m, -std::numeric_limits<double>::infinity());
  for (std::size_t i : kept)
    for (std::size_t k = 0; k < m; ++k) {
      lo[k] = std::min(lo[k], vectors[i][k]);
      hi[k] = std::max(hi[k], vectors[i][k]);
    }
  std::vector<std::size_t> distinct;
  for (std::size_t i : kept) {
    const bool duplicate = std::any_of(distinct.begin(), distinct.end(), [&](std::size_t j) {
      for (std::size_t k = 0; k < m; ++k)
        if (std::abs(vectors[i][k] - vectors[j][k]) > duplicate_tolerance * (hi[k] - lo[k])) return false;
      return true;
    });
    if (!duplicate) distinct.push_back(i);
  }

  while (distinct.size() > std::max<std::size_t>(points, 2)) {
    std::vector<std::vector<double>> current;
    for (std::size_t i : distinct) current.push_back(vectors[i]);
    const std::vector<double> d = crowding_distances(current);
    std::size_t worst = 0;
    for (std::size_t j = 1; j < d.size(); ++j)
      if (d[j] <= d[worst]) worst = j;
    distinct.erase(distinct.begin() + static_cast<std::ptrdiff_t>(worst));
  }
  std::stable_sort(distinct.begin(), distinct.end(),
                   [&](std::size_t a, std::size_t b) { return vectors[a] < vectors[b]; });
  return distinct;
}

ParetoResult select_front(std::vector<ParetoPoint> feasible, std::size_t points, double duplicate_tolerance) {
  ParetoResult result;
  std::vector<std::vector<double>> vectors;
  for (const ParetoPoint& p : feasible) vectors.push_back(p.evaluation.objectives);
  const std::vector<std::size_t> kept = select_front_indices(vectors, points, duplicate_tolerance);
  if (kept.empty()) return result;
  const std::size_t m = vectors[kept[0]].size();
  result.ideal.assign(m, std::numeric_limits<double>::infinity());
  result.nadir.assign(m, -std::numeric_limits<double>::infinity());
  for (std::size_t i : kept) {
    for (std::size_t k = 0; k < m; ++k) {
      result.ideal[k] = std::min(result.ideal[k], vectors[i][k]);
      result.nadir[k] = std::max(result.nadir[k], vectors[i][k]);
    }
    result.front.push_back(std::move(feasible[i]));
  }
  return result;
}

}  // namespace rackopt::solvers
