#include "rackopt/study/wear_discretization_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace rackopt::study {
namespace {

// The largest value the problem schema allows for wear.profile_points.
constexpr int kMaxProfilePoints = 2000;

}  // namespace

bool is_wear_life_metric(const std::string& metric_name) {
  return metric_name == "wear_life" || metric_name == "wear_life_cycles" || metric_name == "wear_life_at_R";
}

void check_wear_discretization(const StudyProblem& problem, const std::vector<double>& x,
                               OptimumExplanation& explanation, unsigned threads) {
  const StudySpec& spec = problem.spec();
  std::vector<std::size_t> checked;  // constraint indices
  for (std::size_t j = 0; j < spec.constraints.size() && j < explanation.constraints.size(); ++j)
    if (explanation.constraints[j].active && is_wear_life_metric(spec.constraints[j].metric.name)) checked.push_back(j);
  if (checked.empty()) return;

  const int points = problem.drive_at(x).wear.profile_points;
  const int refined_points = std::min(2 * points, kMaxProfilePoints);
  if (refined_points <= points) return;
  // The same study with the profile points doubled: appended last, the
  // override wins over the file and every earlier problem_set entry.
  StudySpec refined_spec = spec;
  refined_spec.problem_overrides.push_back("wear.profile_points=" + std::to_string(refined_points));
  const StudyProblem refined(refined_spec);
  const DesignMetrics m = refined.compute_metrics(x, threads);
  const std::vector<std::string>& labels = refined.metric_labels();
  for (std::size_t j : checked) {
    ConstraintStatus& c = explanation.constraints[j];
    const auto it = std::find(labels.begin(), labels.end(), c.label);
    const std::size_t i = static_cast<std::size_t>(it - labels.begin());
    if (i >= m.metric_ok.size() || !m.metric_ok[i] || m.metric_values[i] == 0) {
      explanation.note += "; the refined evaluation of " + c.label + " failed" +
                          (m.failure.empty() ? std::string() : " (" + m.failure + ")");
      continue;
    }
    DiscretizationError d;
    d.setting = "wear.profile_points";
    d.points = points;
    d.refined_points = refined_points;
    d.refined_value = m.metric_values[i];
    d.relative_error = (c.value - d.refined_value) / std::abs(d.refined_value);
    c.discretization = d;
  }
}

}  // namespace rackopt::study
