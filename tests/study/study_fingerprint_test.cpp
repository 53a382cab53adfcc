// study_fingerprint (study_spec.hpp): the same study gives the same text,
// each input it documents changes it, the documented exclusions (name,
// output options, the budget) do not, and the problem enters by its values
// after the overrides, not by its file's text.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/study/study_spec.hpp"
#include "study_test_support.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::study {
namespace {

using namespace rackopt::study::testing;

// An optimize study with something in every section the fingerprint reads.
StudySpec full_spec() {
  StudySpec s = railway_spec(StudyKind::kOptimize);
  s.variables = {continuous("pinion.pressure_angle", 17 * kDeg, 25 * kDeg, 20 * kDeg), continuous("rack.span", 1.2, 3.0),
                 discrete("pinion.teeth", {20, 22, 24})};
  s.objectives = {objective("stiffness_fluctuation")};
  s.constraints = {constraint("contact_ratio", 1.3, 2.5)};
  s.report_metrics = {metrics::parse_metric_request("min_stiffness")};
  s.choose_weights = {1, 2};
  return s;
}

struct Change {
  const char* what;
  std::function<void(StudySpec&)> apply;
};

TEST(StudyFingerprint, EqualSpecsGiveEqualText) {
  const StudySpec a = full_spec();
  const StudySpec b = full_spec();  // built again, not copied
  EXPECT_EQ(study_fingerprint(a), study_fingerprint(b));
  EXPECT_EQ(study_fingerprint(a), study_fingerprint(a));
}

TEST(StudyFingerprint, EveryDocumentedInputChangesIt) {
  const std::vector<Change> changes = {
      {"kind", [](StudySpec& s) { s.kind = StudyKind::kSweep; }},
      {"seed", [](StudySpec& s) { s.seed += 1; }},
      {"variable key", [](StudySpec& s) { s.variables[1] = continuous("rack.body_height", 1.2, 3.0); }},
      {"variable lower", [](StudySpec& s) { s.variables[0].lower = std::nextafter(s.variables[0].lower, 0.0); }},
      {"variable upper", [](StudySpec& s) { s.variables[1].upper = std::nextafter(3.0, 4.0); }},
      {"variable start", [](StudySpec& s) { s.variables[0].start = 21 * kDeg; }},
      {"no start", [](StudySpec& s) { s.variables[0].start.reset(); }},
      {"variable levels", [](StudySpec& s) { s.variables[1].levels = 9; }},
      {"discrete values", [](StudySpec& s) { s.variables[2].values.back() = 25; }},
      {"one variable fewer", [](StudySpec& s) { s.variables.pop_back(); }},
      {"variable order", [](StudySpec& s) { std::swap(s.variables[0], s.variables[1]); }},
      {"objective metric", [](StudySpec& s) { s.objectives[0] = objective("min_stiffness"); }},
      {"objective sense", [](StudySpec& s) { s.objectives[0].maximize = true; }},
      {"objective scale", [](StudySpec& s) { s.objectives[0].scale = 2; }},
      {"constraint min", [](StudySpec& s) { s.constraints[0].min = 1.31; }},
      {"constraint max", [](StudySpec& s) { s.constraints[0].max.reset(); }},
      {"constraint equals", [](StudySpec& s) { s.constraints[0].equals = 1.5; }},
      {"constraint scale", [](StudySpec& s) { s.constraints[0].scale = 0.5; }},
      {"constraint metric", [](StudySpec& s) { s.constraints[0] = constraint("min_stiffness", 1.3, 2.5); }},
      {"report metric", [](StudySpec& s) { s.report_metrics.clear(); }},
      {"load factor", [](StudySpec& s) { s.metric_options.load_factors.application = 1.25; }},
      {"allowable stress", [](StudySpec& s) { s.metric_options.allowable_bending_rack = 400e6; }},
      {"exact quantile", [](StudySpec& s) { s.metric_options.exact_quantile = !s.metric_options.exact_quantile; }},
      {"reliability samples", [](StudySpec& s) { s.metric_options.reliability_samples = 500; }},
      {"reliability seed", [](StudySpec& s) { s.metric_options.reliability_seed = 3; }},
      {"bootstrap", [](StudySpec& s) { s.metric_options.bootstrap_replicates = 50; }},
      {"cost weights", [](StudySpec& s) { s.metric_options.cost.per_support += 1; }},
      {"metric sampling", [](StudySpec& s) { s.metric_options.positions_per_period = 24; }},
      {"solver algorithm", [](StudySpec& s) { s.solver.algorithm = "LN_BOBYQA"; }},
      {"solver library", [](StudySpec& s) { s.solver.library = "ipopt"; }},
      {"solver xtol_rel", [](StudySpec& s) { s.solver.xtol_rel = 1e-5; }},
      {"solver starts", [](StudySpec& s) { s.solver.starts = 3; }},
      {"solver seed", [](StudySpec& s) { s.solver.seed = 9; }},
      {"solver tolerance", [](StudySpec& s) { s.solver.constraint_tolerance = 1e-5; }},
      {"gradient step", [](StudySpec& s) { s.solver.gradient_step = 1e-5; }},
      {"pareto method", [](StudySpec& s) { s.pareto.method = solvers::Scalarization::kWeightedSum; }},
      {"pareto points", [](StudySpec& s) { s.pareto.points = 7; }},
      {"pareto primary", [](StudySpec& s) { s.pareto.primary = 1; }},
      {"pareto duplicates", [](StudySpec& s) { s.pareto.duplicate_tolerance = 1e-3; }},
      {"choose weights", [](StudySpec& s) { s.choose_weights = {2, 1}; }},
      {"sweep method", [](StudySpec& s) { s.sweep.method = SweepSpec::Method::kSobol; }},
      {"sweep levels", [](StudySpec& s) { s.sweep.levels = 6; }},
      {"sweep points", [](StudySpec& s) { s.sweep.points = 65; }},
      {"problem override", [](StudySpec& s) { s.problem_overrides.push_back("rack.span=2 m"); }},
      {"problem file", [](StudySpec& s) { s.problem_path = test_support::shipped_problem_path("gantry_axis.yaml"); }},
  };
  const StudySpec base = full_spec();
  const std::string f = study_fingerprint(base);
  std::set<std::string> seen = {f};
  for (const Change& c : changes) {
    StudySpec s = full_spec();
    c.apply(s);
    const std::string g = study_fingerprint(s);
    EXPECT_NE(g, f) << c.what;
    seen.insert(g);
  }
  // No two changes collide either: each input has its own place in the text.
  EXPECT_EQ(seen.size(), changes.size() + 1);
}

TEST(StudyFingerprint, NameOutputOptionsAndBudgetDoNotChangeIt) {
  const std::string f = study_fingerprint(full_spec());
  const std::vector<Change> kept = {
      {"name", [](StudySpec& s) { s.name = "another name"; }},
      {"description", [](StudySpec& s) { s.description = "words"; }},
      {"plots", [](StudySpec& s) { s.output.plots = !s.output.plots; }},
      {"report", [](StudySpec& s) { s.output.report = !s.output.report; }},
      {"stiffness curve", [](StudySpec& s) { s.output.stiffness_curve = !s.output.stiffness_curve; }},
      {"max_evaluations", [](StudySpec& s) { s.solver.max_evaluations *= 3; }},
      {"max_seconds", [](StudySpec& s) { s.solver.max_seconds = 12; }},
      {"metric threads", [](StudySpec& s) { s.metric_options.threads = 4; }},
  };
  for (const Change& c : kept) {
    StudySpec s = full_spec();
    c.apply(s);
    EXPECT_EQ(study_fingerprint(s), f) << c.what;
  }
}

// The problem by its values: a copy of the file with other comments is the
// same study, and so is a set of overrides that ends with the same values.
TEST(StudyFingerprint, TheProblemEntersByItsValuesAfterTheOverrides) {
  const std::string dir = test_support::scratch_dir("fingerprint_problem");
  const std::string original = test_support::read_text(test_support::shipped_problem_path("rack_railway.yaml"));
  ASSERT_FALSE(original.empty());
  const std::string commented = dir + "/commented.yaml";
  std::ofstream(commented) << "# a comment the original does not have\n\n" << original << "\n# and one at the end\n";
  StudySpec a = full_spec();
  StudySpec b = full_spec();
  b.problem_path = commented;
  EXPECT_EQ(study_fingerprint(a), study_fingerprint(b));

  // An override that sets a key to the value it already has in the file...
  StudySpec same_value = full_spec();
  same_value.problem_overrides.push_back("numerics.positions_per_period=24");
  EXPECT_EQ(study_fingerprint(same_value), study_fingerprint(a));
  // ... and the override applied later wins, as the loader applies them.
  StudySpec later_wins = full_spec();
  later_wins.problem_overrides = {"numerics.positions_per_period=30", "numerics.positions_per_period=24"};
  EXPECT_EQ(study_fingerprint(later_wins), study_fingerprint(a));
}

}  // namespace
}  // namespace rackopt::study
