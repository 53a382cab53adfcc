// Study specs built directly in C++ (the YAML loader is another module).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/study/study_spec.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt::study::testing {

inline const std::string kSourceDir = RACKOPT_SOURCE_DIR;

// rack_railway with a coarser travel sampling: the tests compare the study
// layer against itself (sweep vs optimizer on the same model), so the
// resolution of the curve does not matter, only its cost.
inline StudySpec railway_spec(StudyKind kind) {
  StudySpec s;
  s.name = "test";
  s.file = "test_study.yaml";
  s.kind = kind;
  s.seed = 7;
  s.problem_path = kSourceDir + "/problems/rack_railway.yaml";
  s.problem_overrides = {"numerics.positions_per_period=24"};
  return s;
}

inline DesignVariable continuous(const std::string& key, double lower, double upper,
                                 std::optional<double> start = std::nullopt) {
  DesignVariable v;
  v.key = key;
  v.kind = *problem_key_kind(key);
  v.lower = lower;
  v.upper = upper;
  v.start = start;
  return v;
}

inline DesignVariable discrete(const std::string& key, std::vector<double> values) {
  DesignVariable v;
  v.key = key;
  v.kind = *problem_key_kind(key);
  v.values = values;
  v.lower = values.front();
  v.upper = values.back();
  return v;
}

inline ObjectiveSpec objective(const std::string& text, bool maximize = false) {
  ObjectiveSpec o;
  o.metric = metrics::resolve_request(metrics::parse_metric_request(text));
  o.label = metrics::to_string(o.metric);
  o.maximize = maximize;
  return o;
}

inline ConstraintSpec constraint(const std::string& text, std::optional<double> min, std::optional<double> max = {}) {
  ConstraintSpec c;
  c.metric = metrics::resolve_request(metrics::parse_metric_request(text));
  c.label = metrics::to_string(c.metric);
  c.min = min;
  c.max = max;
  return c;
}

// Every evaluation a finished study recorded, in record order.
inline std::vector<record::RecordedEvaluation> rows_of(const StudyResult& r, const StudySpec& spec) {
  StudyProblem p(spec);
  auto store = record::EvaluationStore::open(r.database_path, study_fingerprint(spec), p.variable_keys(), true,
                                             {.fingerprint_format = kStudyFingerprintFormat});
  return store.all();
}

// Result folders: a fresh path in this process's scratch folder.
using rackopt::test_support::scratch_path;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// The value of metric `label` of a design (a test failure when absent or
// not computed).
inline double metric(const DesignResult& d, const std::string& label) {
  for (std::size_t i = 0; i < d.metric_labels.size(); ++i)
    if (d.metric_labels[i] == label) {
      EXPECT_TRUE(d.metric_ok[i]) << label;
      return d.metric_values[i];
    }
  ADD_FAILURE() << "no metric " << label;
  return 0;
}

// Run options writing to `dir` on `threads` threads, nothing else set.
inline RunOptions options_in(const std::string& dir, unsigned threads = 1) {
  RunOptions o;
  o.out_dir = dir;
  o.threads = threads;
  return o;
}

}  // namespace rackopt::study::testing
