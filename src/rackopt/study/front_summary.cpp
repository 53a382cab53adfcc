#include "rackopt/study/front_summary.hpp"

#include <algorithm>

#include "rackopt/solvers/pareto.hpp"

namespace rackopt::study {

namespace {

constexpr std::size_t kHistoryPoints = 64;

// Adds v to a non-dominated archive: dropped when an archived vector
// dominates or equals it, else archived and every vector it dominates removed.
void add_to_archive(std::vector<std::vector<double>>& archive, const std::vector<double>& v) {
  for (const auto& a : archive)
    if (a == v || solvers::dominates(a, v)) return;
  std::erase_if(archive, [&](const std::vector<double>& a) { return solvers::dominates(v, a); });
  archive.push_back(v);
}

}  // namespace

FrontSummary summarize_front(const std::vector<std::vector<double>>& front, std::span<const double> reference,
                             const std::vector<FeasibleObjectives>& feasible_in_order, std::size_t total_evaluations) {
  FrontSummary s;
  s.quality = solvers::front_quality(front, reference);
  if (front.empty() || total_evaluations == 0) return s;
  double box = 1;
  for (std::size_t k = 0; k < s.quality.ideal.size(); ++k) box *= s.quality.reference[k] - s.quality.ideal[k];
  if (!(box > 0)) return s;

  // Checkpoints: evenly spaced evaluation counts, the last = every evaluation.
  const std::size_t n = std::min(kHistoryPoints, total_evaluations);
  std::vector<std::size_t> at;
  for (std::size_t i = 1; i <= n; ++i) at.push_back((total_evaluations * i + n - 1) / n);
  std::vector<std::vector<double>> archive;
  std::size_t next = 0;
  for (std::size_t count : at) {
    for (; next < feasible_in_order.size() && feasible_in_order[next].first < count; ++next)
      add_to_archive(archive, feasible_in_order[next].second);
    s.history_evaluations.push_back(count);
    s.history_hypervolume.push_back(solvers::hypervolume(archive, s.quality.reference) / box);
  }
  return s;
}

}  // namespace rackopt::study
