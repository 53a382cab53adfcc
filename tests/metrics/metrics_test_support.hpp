// Small helpers several metrics tests share (one definition, so the test
// files can be compiled together in a unity build).
#pragma once

#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::test {

inline constexpr double kPi = std::numbers::pi;

// problems/<name>.yaml of the source tree.
inline std::string path(const std::string& name) {
  return test_support::shipped_problem_path(name + ".yaml");
}

// The shipped problem <name> loaded as it is.
inline Drive problem(const std::string& name) { return load_problem(path(name)); }

inline std::vector<metrics::MetricRequest> requests(std::initializer_list<const char*> texts) {
  std::vector<metrics::MetricRequest> out;
  for (const char* t : texts) out.push_back(metrics::parse_metric_request(t));
  return out;
}

// The metrics `texts` of drive `d` evaluated together.
inline metrics::MetricValues eval(const Drive& d, std::initializer_list<const char*> texts,
                                  const metrics::MetricOptions& o = {}) {
  const std::vector<metrics::MetricRequest> r = requests(texts);
  return metrics::evaluate_metrics(d, r, o);
}

}  // namespace rackopt::test
