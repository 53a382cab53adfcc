#include "rackopt/study/study_runner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/solvers/pareto.hpp"
#include "rackopt/study/study_kind_rules.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/study/warning_groups.hpp"
#include "study_test_support.hpp"
#include "support/sql_text.hpp"

namespace rackopt::study {
namespace {

using namespace rackopt::study::testing;

std::string bits(const std::vector<double>& x) {
  std::string k(x.size() * sizeof(double), '\0');
  if (!x.empty()) std::memcpy(k.data(), x.data(), k.size());
  return k;
}


// Railway sizing: pressure angle and span, least stiffness fluctuation with a
// contact ratio of at least 1.3. Fluctuation grows with span and (here) with
// the pressure angle, the contact ratio rises with the angle from 1.22 at
// 10 deg, so the optimum sits on the contact-ratio bound at the shortest span.
StudySpec sizing_spec(StudyKind kind) {
  StudySpec s = railway_spec(kind);
  s.variables = {continuous("pinion.pressure_angle", 10 * kDeg, 20 * kDeg, 16 * kDeg),
                 continuous("rack.span", 1.2, 3.0)};
  s.objectives = {objective("stiffness_fluctuation")};
  s.constraints = {constraint("contact_ratio", 1.3)};
  s.solver.algorithm = "LN_COBYLA";
  s.solver.max_evaluations = 120;
  s.solver.xtol_rel = 1e-7;
  return s;
}

// ---------------------------------------------------------------- sweeps

TEST(StudySweep, GridIsIndependentOfThreadCount) {
  StudySpec s = sizing_spec(StudyKind::kSweep);
  s.variables[0].levels = 5;
  s.variables[1].levels = 7;
  s.report_metrics = {metrics::parse_metric_request("supports_per_metre")};
  const StudyResult one = run_study(s, options_in(scratch_path("grid1"), 1));
  const StudyResult two = run_study(s, options_in(scratch_path("grid2"), 2));
  ASSERT_EQ(to_string(one.status), "ok");
  ASSERT_EQ(one.sweep_points.size(), 35u);
  ASSERT_EQ(two.sweep_points.size(), 35u);
  // Start design (automatic objective scale) + the grid.
  EXPECT_EQ(one.evaluations, 36u);
  for (std::size_t k = 0; k < 35; ++k) {
    EXPECT_EQ(bits(one.sweep_points[k].x), bits(two.sweep_points[k].x)) << k;
    EXPECT_EQ(bits(one.sweep_points[k].metric_values), bits(two.sweep_points[k].metric_values)) << k;
    // Grid layout: first variable slowest, ends exact.
    EXPECT_EQ(one.sweep_points[k].x[0], k / 7 == 4 ? 20 * kDeg : 10 * kDeg + (k / 7) * (20 * kDeg - 10 * kDeg) / 4);
    // supports_per_metre is 1/span by definition: checks that x reached the drive.
    EXPECT_DOUBLE_EQ(metric(one.sweep_points[k], "supports_per_metre"), 1.0 / one.sweep_points[k].x[1]);
  }
  EXPECT_EQ(one.sweep_points[6].x[1], 3.0);
  // Same rows in the same order in both stores.
  const auto ra = rows_of(one, s), rb = rows_of(two, s);
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t i = 0; i < ra.size(); ++i) {
    EXPECT_EQ(bits(ra[i].x), bits(rb[i].x));
    EXPECT_EQ(ra[i].phase, rb[i].phase);
  }
  // Best = the feasible point of least fluctuation, found by scanning ourselves.
  ASSERT_TRUE(one.best);
  double best = INFINITY;
  for (const auto& p : one.sweep_points)
    if (metric(p, "contact_ratio") >= 1.3 * (1 - 1e-6)) best = std::min(best, metric(p, "stiffness_fluctuation"));
  EXPECT_EQ(one.best->objectives[0], best);
  EXPECT_TRUE(std::filesystem::exists(one.evaluations_csv_path));
}

TEST(StudySweep, WithoutObjectivesHasNoBestAndNoLeastInfeasible) {
  // A plain response sweep: nothing to rank, every point feasible, so the
  // result must not pretend that no feasible design exists.
  StudySpec s = railway_spec(StudyKind::kSweep);
  s.variables = {continuous("rack.span", 1.2, 3.0)};
  s.variables[0].levels = 4;
  s.objectives.clear();
  s.constraints.clear();
  s.report_metrics = {metrics::parse_metric_request("supports_per_metre")};
  const StudyResult r = run_study(s, options_in(scratch_path("plain_sweep")));
  ASSERT_EQ(r.sweep_points.size(), 4u);
  for (const auto& p : r.sweep_points) EXPECT_TRUE(p.feasible);
  EXPECT_FALSE(r.best);
  EXPECT_FALSE(r.least_infeasible);
  // With an impossible constraint the least infeasible point is reported.
  s.constraints = {constraint("contact_ratio", 3.0)};
  const StudyResult q = run_study(s, options_in(scratch_path("plain_sweep_infeasible")));
  EXPECT_FALSE(q.best);
  ASSERT_TRUE(q.least_infeasible);
  EXPECT_FALSE(q.least_infeasible->feasible);
}

// The record of a study, as plain SQL sees it: every variable and metric a
// real column in SI with its unit in value_columns, and the models each
// design ran (docs/recorder.md, "Queries").
TEST(StudyRecord, SqlFiltersVariablesAndMetricsWithTheirUnitsAndModels) {
  StudySpec s = railway_spec(StudyKind::kSweep);
  s.variables = {continuous("rack.span", 1.2, 3.0)};
  s.variables[0].levels = 5;
  s.objectives.clear();
  s.constraints.clear();
  s.report_metrics = {metrics::parse_metric_request("supports_per_metre"),
                      metrics::parse_metric_request("contact_ratio")};
  const std::string dir = scratch_path("record_columns");
  const StudyResult r = run_study(s, options_in(dir));
  ASSERT_EQ(r.sweep_points.size(), 5u);
  std::size_t close_supports = 0;
  for (const auto& p : r.sweep_points) close_supports += metric(p, "supports_per_metre") > 0.5 ? 1 : 0;
  ASSERT_GT(close_supports, 0u);
  ASSERT_LT(close_supports, 5u);
  auto text = [&](const std::string& sql) { return test_support::sql_text(dir + "/evaluations.sqlite", sql); };
  EXPECT_EQ(text("SELECT count(*) FROM evaluations WHERE supports_per_metre > 0.5"), std::to_string(close_supports));
  EXPECT_EQ(text("SELECT count(*) FROM evaluations WHERE abs(supports_per_metre * rack_span - 1) > 1e-12"), "0");
  EXPECT_EQ(text("SELECT unit FROM value_columns WHERE source = 'rack.span'"), "m");
  EXPECT_EQ(text("SELECT unit FROM value_columns WHERE source = 'supports_per_metre'"), "1/m");
  EXPECT_EQ(text("SELECT unit FROM value_columns WHERE name = 'contact_ratio'"), "-");
  EXPECT_EQ(text("SELECT count(*) FROM evaluations WHERE models LIKE '%geometry%'"), std::to_string(r.evaluations));
  // evaluations.csv names the same units in its header.
  std::ifstream csv(r.evaluations_csv_path);
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "id,phase,ok,message,gradient_probe,seconds_s,rack.span_m,supports_per_metre_per_m,contact_ratio");
}

class StudySampledSweep : public ::testing::TestWithParam<SweepSpec::Method> {};

TEST_P(StudySampledSweep, SnapsDiscreteValuesAndIsThreadIndependent) {
  StudySpec s = railway_spec(StudyKind::kSweep);
  s.variables = {continuous("pinion.pressure_angle", 12 * kDeg, 20 * kDeg),
                 discrete("pinion.teeth", {18, 22, 26})};
  s.sweep.method = GetParam();
  s.sweep.points = 20;
  s.report_metrics = {metrics::parse_metric_request("contact_ratio")};
  const StudyResult one = run_study(s, options_in(scratch_path("lhs1"), 1));
  const StudyResult two = run_study(s, options_in(scratch_path("lhs2"), 2));
  ASSERT_EQ(one.sweep_points.size(), 20u);
  EXPECT_EQ(one.evaluations, 20u);  // no objective: no start design needed
  for (std::size_t k = 0; k < 20; ++k) {
    const double z = one.sweep_points[k].x[1];
    EXPECT_TRUE(z == 18 || z == 22 || z == 26) << z;
    EXPECT_EQ(bits(one.sweep_points[k].x), bits(two.sweep_points[k].x));
    EXPECT_EQ(bits(one.sweep_points[k].metric_values), bits(two.sweep_points[k].metric_values));
  }
}

INSTANTIATE_TEST_SUITE_P(Samplers, StudySampledSweep,
                         ::testing::Values(SweepSpec::Method::kLatinHypercube, SweepSpec::Method::kSobol),
                         [](const ::testing::TestParamInfo<SweepSpec::Method>& param_info) {
                           return std::string(param_info.param == SweepSpec::Method::kSobol ? "Sobol" : "LatinHypercube");
                         });

TEST(StudySweep, ImpossibleDesignsAreFailedEvaluationsWithReasons) {
  // 5..45 deg: below ~8 deg the path of contact is shorter than a pitch,
  // above ~33 deg the cutter's tip round / tooth is impossible.
  StudySpec s = railway_spec(StudyKind::kSweep);
  s.variables = {continuous("pinion.pressure_angle", 5 * kDeg, 45 * kDeg, 20 * kDeg)};
  s.variables[0].levels = 9;
  s.objectives = {objective("stiffness_fluctuation")};
  s.constraints = {constraint("contact_ratio", 1.2)};
  const StudyResult r = run_study(s, options_in(scratch_path("failed_sweep")));
  ASSERT_EQ(r.sweep_points.size(), 9u);
  std::size_t failed = 0;
  for (const auto& p : r.sweep_points) {
    if (p.ok) continue;
    ++failed;
    EXPECT_FALSE(p.feasible);
    EXPECT_TRUE(std::isinf(p.max_violation));
    EXPECT_FALSE(p.message.empty());
  }
  EXPECT_GE(failed, 3u);  // 5, 40, 45 deg at least
  EXPECT_FALSE(r.sweep_points.front().ok);
  EXPECT_FALSE(r.sweep_points.back().ok);
  EXPECT_EQ(r.failed_evaluations, failed);  // the start (20 deg) is fine
  std::size_t failed_rows = 0;
  std::set<std::string> codes;
  for (const auto& row : rows_of(r, s)) {
    if (row.ok) continue;
    ++failed_rows;
    for (const char* code : {"contact_ratio_below_one", "no_involute", "pointed_cutter", "cutter_tip_radius",
                             "pointed_tooth"})
      if (row.message.find(code) != std::string::npos) codes.insert(code);
  }
  EXPECT_EQ(failed_rows, failed);
  EXPECT_GE(codes.size(), 2u);
  ASSERT_TRUE(r.best);
  EXPECT_TRUE(r.best->feasible);
}

TEST(StudySweep, BadSweepIsAnInputErrorNamingTheStudyFile) {
  StudySpec s = railway_spec(StudyKind::kSweep);
  s.variables = {continuous("pinion.pressure_angle", 12 * kDeg, 20 * kDeg), continuous("rack.span", 1, 3)};
  s.sweep.levels = 1000;
  s.sweep.max_points = 5000;
  try {
    run_study(s, options_in(scratch_path("bad_sweep")));
    FAIL() << "a sweep above max_points ran";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test_study.yaml"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------- optimize

TEST(StudyOptimize, AtLeastAsGoodAsADenseGridAndReproducible) {
  StudySpec grid = sizing_spec(StudyKind::kSweep);
  grid.variables[0].levels = 41;  // 0.25 deg
  grid.variables[1].levels = 7;
  const StudyResult g = run_study(grid, options_in(scratch_path("dense_grid"), 2));
  ASSERT_TRUE(g.best);

  const StudySpec s = sizing_spec(StudyKind::kOptimize);
  RunOptions with_progress = options_in(scratch_path("opt_a"));
  std::vector<Progress> seen;
  with_progress.progress = [&](const Progress& p) { seen.push_back(p); };
  const StudyResult a = run_study(s, with_progress);
  ASSERT_TRUE(a.best) << a.status;
  EXPECT_TRUE(a.best->feasible);
  // Constraints respected in the reported best (our re-check, from the metric).
  EXPECT_GE(metric(*a.best, "contact_ratio"), 1.3 * (1 - s.solver.constraint_tolerance));
  EXPECT_LE(a.best->objectives[0], g.best->objectives[0] * (1 + 1e-4))
      << "optimizer " << a.best->objectives[0] << " vs grid " << g.best->objectives[0];
  EXPECT_EQ(a.best->objectives[0], metric(*a.best, "stiffness_fluctuation"));
  EXPECT_LE(a.evaluations, s.solver.max_evaluations + 1);
  // History: non-increasing, ends at the best.
  ASSERT_EQ(a.best_history.size(), a.evaluations);
  for (std::size_t i = 1; i < a.best_history.size(); ++i) EXPECT_LE(a.best_history[i], a.best_history[i - 1]);
  EXPECT_EQ(a.best_history.back(), a.best->objectives[0]);
  ASSERT_TRUE(a.best_drive);
  EXPECT_EQ(a.best_drive->rack.span, a.best->x[1]);
  // Progress after every evaluation, against the planned budget.
  ASSERT_EQ(seen.size(), a.evaluations);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].done, i + 1);
    EXPECT_EQ(seen[i].budget, s.solver.max_evaluations + 1);
  }
  ASSERT_TRUE(seen.back().best);
  EXPECT_EQ(*seen.back().best, a.best->objectives[0]);

  const StudyResult b = run_study(s, options_in(scratch_path("opt_b")));
  ASSERT_TRUE(b.best);
  EXPECT_EQ(bits(a.best->x), bits(b.best->x));
  EXPECT_EQ(a.evaluations, b.evaluations);
  EXPECT_EQ(a.status, b.status);
}

TEST(StudyOptimize, MaximizeReportsTheMetricInItsOwnSense) {
  // Largest smooth minimum stiffness at span 2.4 m: stiffness falls with the
  // pressure angle, so again the contact-ratio bound is active.
  StudySpec s = railway_spec(StudyKind::kOptimize);
  s.variables = {continuous("pinion.pressure_angle", 10 * kDeg, 20 * kDeg)};
  s.objectives = {objective("min_stiffness_ks", true)};
  s.constraints = {constraint("contact_ratio", 1.3)};
  s.solver.max_evaluations = 60;
  const StudyResult r = run_study(s, options_in(scratch_path("maximize")));
  ASSERT_TRUE(r.best) << r.status;
  EXPECT_GT(r.best->objectives[0], 0);
  EXPECT_EQ(r.best->objectives[0], metric(*r.best, s.objectives[0].label));
  for (std::size_t i = 1; i < r.best_history.size(); ++i) EXPECT_GE(r.best_history[i], r.best_history[i - 1]);

  StudySpec g = s;
  g.kind = StudyKind::kSweep;
  g.variables[0].levels = 41;
  const StudyResult gr = run_study(g, options_in(scratch_path("maximize_grid"), 2));
  ASSERT_TRUE(gr.best);
  EXPECT_GE(r.best->objectives[0], gr.best->objectives[0] * (1 - 1e-4));
  // The grid's own choice is the largest feasible value.
  for (const auto& p : gr.sweep_points) {
    if (p.feasible) {
      EXPECT_LE(p.objectives[0], gr.best->objectives[0]);
    }
  }
}

TEST(StudyOptimize, ImpossibleConstraintReportsTheLeastInfeasibleDesign) {
  StudySpec s = sizing_spec(StudyKind::kOptimize);
  s.constraints = {constraint("contact_ratio", 3.0)};  // a 14..20 deg pinion of 22 teeth never gets there
  s.solver.max_evaluations = 40;
  const StudyResult r = run_study(s, options_in(scratch_path("no_feasible")));
  EXPECT_EQ(to_string(r.status), "no_feasible_point");
  EXPECT_FALSE(r.best);
  ASSERT_TRUE(r.least_infeasible);
  EXPECT_TRUE(r.least_infeasible->ok);
  EXPECT_FALSE(r.least_infeasible->feasible);
  // Violation = (3 - contact ratio) / 3, and no recorded design does better.
  const double cr = metric(*r.least_infeasible, "contact_ratio");
  EXPECT_NEAR(r.least_infeasible->max_violation, (3.0 - cr) / 3.0, 1e-12);
  for (const auto& row : rows_of(r, s)) {
    if (row.ok) {
      EXPECT_GE(row.inequality[0], r.least_infeasible->max_violation);
    }
  }
  EXPECT_FALSE(r.best_drive);
}

TEST(StudyOptimize, FailedStartDesignDoesNotStopTheStudy) {
  StudySpec s = railway_spec(StudyKind::kOptimize);
  s.variables = {continuous("pinion.pressure_angle", 20 * kDeg, 45 * kDeg, 42 * kDeg)};
  s.objectives = {objective("stiffness_fluctuation")};
  s.solver.max_evaluations = 30;
  const StudyResult r = run_study(s, options_in(scratch_path("failed_start")));
  EXPECT_GE(r.failed_evaluations, 1u);
  EXPECT_EQ(r.evaluations, rows_of(r, s).size());
  for (const auto& row : rows_of(r, s)) {
    if (!row.ok) {
      EXPECT_NE(row.message.find("pointed_cutter"), std::string::npos) << row.message;
    }
  }
  if (r.best) {
    EXPECT_TRUE(r.best->feasible);
  }
}

TEST(StudyOptimize, DiscreteEnumerationPicksTheBestCombination) {
  const double modules[] = {0.025, 0.031831, 0.04};
  StudySpec s = railway_spec(StudyKind::kOptimize);
  s.variables = {discrete("pinion.module", {modules[0], modules[1], modules[2]}),
                 continuous("pinion.pressure_angle", 10 * kDeg, 20 * kDeg)};
  s.objectives = {objective("stiffness_fluctuation")};
  s.objectives[0].scale = 1;  // so that each combination is the same solver run as its reference below
  s.constraints = {constraint("contact_ratio", 1.3)};
  s.solver.max_evaluations = 50;
  const StudyResult r = run_study(s, options_in(scratch_path("discrete")));
  ASSERT_TRUE(r.best) << r.status;

  // References: one study per module, the module written into the problem.
  double best_ref = INFINITY, best_module = 0;
  for (double m : modules) {
    StudySpec one = s;
    one.variables = {s.variables[1]};
    one.problem_overrides.push_back("pinion.module=" + std::to_string(m * 1000) + " mm");
    const StudyResult o = run_study(one, options_in(scratch_path("discrete_ref")));
    ASSERT_TRUE(o.best);
    if (o.best->objectives[0] < best_ref) {
      best_ref = o.best->objectives[0];
      best_module = m;
    }
  }
  EXPECT_NEAR(r.best->objectives[0], best_ref, 1e-9 * best_ref);
  EXPECT_NEAR(r.best->x[0], best_module, 1e-12);
  EXPECT_NE(r.best->label.find("combination"), std::string::npos) << r.best->label;
  ASSERT_TRUE(r.best_drive);
  EXPECT_NEAR(r.best_drive->pinion.module, best_module, 1e-12);
}

TEST(StudyOptimize, GacoSearchesDiscreteVariablesAsIntegersInOneRun) {
  const std::vector<double> modules = {0.02, 0.025, 0.031831, 0.04};
  StudySpec s = railway_spec(StudyKind::kOptimize);
  s.variables = {discrete("pinion.module", modules), continuous("pinion.pressure_angle", 10 * kDeg, 20 * kDeg)};
  s.objectives = {objective("stiffness_fluctuation")};
  s.objectives[0].scale = 1;
  s.constraints = {constraint("contact_ratio", 1.3)};
  s.max_discrete_combinations = 2;  // enumerating would be refused; one search is not
  s.solver.library = "pagmo";
  s.solver.algorithm = "gaco";
  s.solver.max_evaluations = 400;
  ASSERT_TRUE(searches_discrete_as_integers(s));
  const StudyResult r = run_study(s, options_in(scratch_path("gaco_integers")));
  ASSERT_TRUE(r.best) << r.status;
  EXPECT_LE(r.evaluations, 401u);  // one budget for every combination, plus the start design
  EXPECT_NE(std::find(modules.begin(), modules.end(), r.best->x[0]), modules.end()) << r.best->x[0];

  // The enumeration with COBYLA on each module is the reference: the one
  // search finds the same module and an optimum within 1 %.
  StudySpec e = s;
  e.solver = StudySpec{}.solver;
  e.solver.max_evaluations = 60;
  e.max_discrete_combinations = 256;
  ASSERT_FALSE(searches_discrete_as_integers(e));
  const StudyResult ref = run_study(e, options_in(scratch_path("gaco_integers_ref")));
  ASSERT_TRUE(ref.best);
  EXPECT_EQ(r.best->x[0], ref.best->x[0]);
  EXPECT_LE(r.best->objectives[0], ref.best->objectives[0] * 1.01);

  // Each listed combination is one the search reached, with the run's status,
  // and no combination twice.
  ASSERT_FALSE(r.per_combination.empty());
  EXPECT_LE(r.per_combination.size(), modules.size());
  std::set<std::string> labels;
  for (const CombinationOutcome& c : r.per_combination) {
    EXPECT_TRUE(labels.insert(c.label).second) << c.label;
    EXPECT_TRUE(c.best || c.least_infeasible) << c.label;
    const DesignResult& d = c.best ? *c.best : *c.least_infeasible;
    EXPECT_NE(c.label.find(format_quantity(d.x[0], s.variables[0].kind, s.variables[0].unit)), std::string::npos)
        << c.label;
  }
}

TEST(StudyOptimize, IntegerSearchOverMoreCombinationsThanCouldBeListed) {
  // 120^5 = 2.5e10 combinations of five lists: one GACO run, and nothing
  // may be sized by the combination count (a status per combination would
  // take hundreds of gigabytes).
  auto values = [](double lo, double hi) {
    std::vector<double> v;
    for (int k = 0; k < 120; ++k) v.push_back(lo + (hi - lo) * k / 119.0);
    return v;
  };
  StudySpec s = railway_spec(StudyKind::kOptimize);
  s.variables = {discrete("pinion.pressure_angle", values(14 * kDeg, 22 * kDeg)), discrete("rack.span", values(1.0, 3.0)),
                 discrete("pinion.face_width", values(0.1, 0.2)), discrete("mounting.clearance", values(0.0, 0.004)),
                 discrete("pinion.module", values(0.025, 0.04))};
  s.objectives = {objective("stiffness_fluctuation")};
  s.constraints = {constraint("contact_ratio", 1.3)};
  s.solver.library = "pagmo";
  s.solver.algorithm = "gaco";
  s.solver.max_evaluations = 64;
  ASSERT_TRUE(searches_discrete_as_integers(s));
  const StudyResult r = run_study(s, options_in(scratch_path("gaco_many")));
  ASSERT_TRUE(r.best) << r.status;
  EXPECT_LE(r.evaluations, 65u);
  EXPECT_LE(r.per_combination.size(), 65u);  // the combinations reached, not all of them
  EXPECT_FALSE(r.per_combination.empty());
}

TEST(StudyOptimize, SetupErrorsAreInputErrors) {
  const std::string dir = scratch_path("setup");
  StudySpec s = sizing_spec(StudyKind::kOptimize);
  s.solver.algorithm = "LN_BOBYQA";  // cannot take the constraint
  try {
    run_study(s, options_in(dir));
    FAIL() << "BOBYQA with a constraint ran";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("COBYLA"), std::string::npos) << e.what();  // says what to use instead
  }
  StudySpec w = sizing_spec(StudyKind::kOptimize);
  w.objectives = {objective("wear_life")};  // the railway problem has no wear section
  EXPECT_THROW(run_study(w, options_in(dir)), InputError);
  StudySpec m = sizing_spec(StudyKind::kOptimize);
  m.variables.push_back(discrete("pinion.teeth", {18, 19, 20, 21, 22}));
  m.variables.push_back(discrete("pinion.profile_shift", {0, 0.1, 0.2, 0.3}));
  m.max_discrete_combinations = 12;
  try {
    run_study(m, options_in(dir));
    FAIL() << "20 combinations ran with a limit of 12";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pinion.teeth"), std::string::npos) << e.what();
  }
  // Nothing was recorded by a refused study.
  EXPECT_FALSE(std::filesystem::exists(dir + "/evaluations.sqlite"));
}

// ---------------------------------------------------------------- resume

TEST(StudyResume, StoppedRunResumesWithoutRepeatsAndEndsBitIdentical) {
  const StudySpec s = sizing_spec(StudyKind::kOptimize);
  const StudyResult full = run_study(s, options_in(scratch_path("resume_full")));
  ASSERT_TRUE(full.best);

  const std::string dir = scratch_path("resume_cut");
  constexpr std::size_t kN = 9;
  RunOptions first = options_in(dir);
  std::size_t done = 0;
  first.progress = [&](const Progress& p) { done = p.done; };
  first.stop = [&] { return done >= kN; };
  const StudyResult cut = run_study(s, first);
  EXPECT_EQ(to_string(cut.status), "stopped");
  EXPECT_EQ(cut.evaluations, kN);

  // Without --resume the folder is refused; another study is refused either way.
  EXPECT_THROW(run_study(s, options_in(dir)), std::runtime_error);
  StudySpec other = s;
  other.constraints[0].min = 1.35;
  RunOptions other_opts = options_in(dir);
  other_opts.resume = true;
  EXPECT_THROW(run_study(other, other_opts), std::runtime_error);
  // ... but a bigger budget is the same study.
  StudySpec bigger = s;
  bigger.solver.max_evaluations += 1;
  EXPECT_EQ(study_fingerprint(bigger), study_fingerprint(s));

  RunOptions again = options_in(dir);
  again.resume = true;
  const StudyResult resumed = run_study(s, again);
  EXPECT_EQ(resumed.reused_evaluations, kN);
  EXPECT_EQ(resumed.evaluations, full.evaluations);
  EXPECT_EQ(resumed.status, full.status);
  ASSERT_TRUE(resumed.best);
  EXPECT_EQ(bits(resumed.best->x), bits(full.best->x));
  EXPECT_EQ(bits(resumed.best->metric_values), bits(full.best->metric_values));
  EXPECT_EQ(bits(resumed.best_history), bits(full.best_history));

  const auto rows = rows_of(resumed, s);
  EXPECT_EQ(rows.size(), full.evaluations);
  std::set<std::string> xs;
  for (const auto& row : rows) EXPECT_TRUE(xs.insert(bits(row.x)).second) << "x evaluated twice: row " << row.id;
  // The same rows as the uninterrupted run, in the same order.
  const auto full_rows = rows_of(full, s);
  ASSERT_EQ(full_rows.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(bits(rows[i].x), bits(full_rows[i].x)) << i;
}

TEST(StudyResume, SweepResumesWhereItStopped) {
  StudySpec s = sizing_spec(StudyKind::kSweep);
  s.variables[0].levels = 6;
  s.variables[1].levels = 6;
  const StudyResult full = run_study(s, options_in(scratch_path("sweep_full")));
  const std::string dir = scratch_path("sweep_cut");
  RunOptions first = options_in(dir);
  std::size_t done = 0;
  first.progress = [&](const Progress& p) { done = p.done; };
  first.stop = [&] { return done >= 10; };
  const StudyResult cut = run_study(s, first);
  EXPECT_EQ(to_string(cut.status), "stopped");
  EXPECT_LT(cut.sweep_points.size(), 36u);
  RunOptions again = options_in(dir, 2);
  again.resume = true;
  const StudyResult resumed = run_study(s, again);
  EXPECT_EQ(to_string(resumed.status), "ok");
  EXPECT_EQ(resumed.reused_evaluations, cut.evaluations);
  EXPECT_EQ(resumed.evaluations, full.evaluations);
  ASSERT_EQ(resumed.sweep_points.size(), full.sweep_points.size());
  for (std::size_t k = 0; k < full.sweep_points.size(); ++k)
    EXPECT_EQ(bits(resumed.sweep_points[k].metric_values), bits(full.sweep_points[k].metric_values));
  EXPECT_EQ(rows_of(resumed, s).size(), full.evaluations);
}

// The railway pinion has 22 teeth: below a pressure angle of about 17.6 deg
// (z_min = 2 / sin^2 a > 22) it is undercut, and the undercut warning names
// the design's own form radius, so designs at different angles raise
// different warnings. The sizing study's box (10..20 deg) has both kinds.
TEST(StudyResume, ReusedDesignsBringTheirWarningsInTheOrderOfAnUninterruptedRun) {
  const StudySpec s = sizing_spec(StudyKind::kOptimize);
  const StudyResult full = run_study(s, options_in(scratch_path("warn_full")));
  ASSERT_TRUE(full.best);
  ASSERT_GE(full.warnings.size(), 2u);

  const std::string dir = scratch_path("warn_cut");
  constexpr std::size_t kN = 9;
  RunOptions first = options_in(dir);
  std::size_t done = 0;
  first.progress = [&](const Progress& p) { done = p.done; };
  first.stop = [&] { return done >= kN; };
  const StudyResult cut = run_study(s, first);
  ASSERT_EQ(to_string(cut.status), "stopped");
  RunOptions again = options_in(dir);
  again.resume = true;
  const StudyResult resumed = run_study(s, again);
  ASSERT_EQ(resumed.reused_evaluations, kN);
  ASSERT_TRUE(resumed.best);

  // The designs taken from the store carried warnings, and each row holds
  // exactly what a fresh evaluation of its design says.
  const StudyProblem problem(s);
  const auto rows = rows_of(resumed, s);
  ASSERT_GE(rows.size(), kN);
  std::size_t reused_with_warnings = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].warnings, problem.evaluate_design(rows[i].x).warnings) << "row " << rows[i].id;
    if (i < kN && !rows[i].warnings.empty()) ++reused_with_warnings;
  }
  EXPECT_GT(reused_with_warnings, 0u);

  EXPECT_EQ(resumed.warnings, full.warnings);
  EXPECT_EQ(bits(resumed.best->x), bits(full.best->x));
  EXPECT_EQ(resumed.best->warnings, full.best->warnings);
  EXPECT_EQ(full.best->warnings, problem.evaluate_design(full.best->x).warnings);

  // Grouped by kind: each group counts exactly the recorded designs with a
  // warning of its kind and names them by their row id; the best design's
  // id is its row. A resumed run groups alike.
  const auto full_rows = rows_of(full, s);
  ASSERT_FALSE(full.warning_groups.empty());
  for (const WarningGroup& g : full.warning_groups) {
    std::vector<std::int64_t> ids;
    for (const auto& row : full_rows)
      for (const auto& w : row.warnings)
        if (warning_kind(w) == g.kind) {
          ids.push_back(row.id);
          break;
        }
    EXPECT_EQ(g.designs, ids.size()) << g.kind;
    ids.resize(std::min(ids.size(), kMaxListedEvaluations));
    EXPECT_EQ(g.evaluations, ids) << g.kind;
  }
  ASSERT_GT(full.best->evaluation_id, 0);
  EXPECT_EQ(bits(full_rows.at(static_cast<std::size_t>(full.best->evaluation_id - 1)).x), bits(full.best->x));
  ASSERT_EQ(resumed.warning_groups.size(), full.warning_groups.size());
  for (std::size_t k = 0; k < full.warning_groups.size(); ++k) {
    EXPECT_EQ(resumed.warning_groups[k].kind, full.warning_groups[k].kind);
    EXPECT_EQ(resumed.warning_groups[k].designs, full.warning_groups[k].designs);
    EXPECT_EQ(resumed.warning_groups[k].evaluations, full.warning_groups[k].evaluations);
  }
  EXPECT_EQ(resumed.best->evaluation_id, full.best->evaluation_id);
}

// A design answered entirely from the store (evaluate: the start design)
// reports the warnings it was recorded with.
TEST(StudyResume, DesignTakenFromTheStoreKeepsItsOwnWarnings) {
  StudySpec s = railway_spec(StudyKind::kEvaluate);
  s.variables = {continuous("pinion.pressure_angle", 10 * kDeg, 20 * kDeg, 14 * kDeg)};
  s.report_metrics = {metrics::parse_metric_request("contact_ratio")};
  const std::string dir = scratch_path("warn_evaluate");
  const StudyResult fresh = run_study(s, options_in(dir));
  ASSERT_TRUE(fresh.best);
  ASSERT_FALSE(fresh.best->warnings.empty());
  bool undercut = false;
  for (const auto& w : fresh.best->warnings) undercut = undercut || w.find("pinion undercut") != std::string::npos;
  EXPECT_TRUE(undercut);
  RunOptions again = options_in(dir);
  again.resume = true;
  const StudyResult reused = run_study(s, again);
  ASSERT_EQ(reused.reused_evaluations, 1u);
  ASSERT_TRUE(reused.best);
  EXPECT_EQ(reused.best->warnings, fresh.best->warnings);
  EXPECT_EQ(reused.warnings, fresh.warnings);
}


TEST(StudyPareto, FrontIsFeasibleNonDominatedAndSpread) {
  StudySpec s = railway_spec(StudyKind::kPareto);
  s.variables = {continuous("rack.span", 1.0, 3.0), continuous("pinion.pressure_angle", 12 * kDeg, 20 * kDeg)};
  s.objectives = {objective("stiffness_fluctuation"), objective("supports_per_metre")};
  s.constraints = {constraint("contact_ratio", 1.3)};
  s.pareto.points = 6;
  s.pareto.primary = 0;
  s.solver.max_evaluations = 40;
  const StudyResult r = run_study(s, options_in(scratch_path("pareto")));
  ASSERT_GE(r.front.size(), 3u) << r.status;
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i < r.front.size(); ++i) {
    const DesignResult& p = r.front[i];
    EXPECT_TRUE(p.feasible);
    EXPECT_GE(metric(p, "contact_ratio"), 1.3 * (1 - s.solver.constraint_tolerance));
    EXPECT_EQ(p.objectives[1], metric(p, "supports_per_metre"));
    EXPECT_DOUBLE_EQ(p.objectives[1], 1.0 / p.x[0]);
    for (std::size_t j = 0; j < r.front.size(); ++j) {
      if (i != j) {
        EXPECT_FALSE(solvers::dominates(r.front[j].objectives, p.objectives)) << j << " dominates " << i;
      }
    }
    if (i > 0) {
      EXPECT_LE(r.front[i - 1].objectives[0], p.objectives[0]);
    }
    lo = std::min(lo, p.objectives[1]);
    hi = std::max(hi, p.objectives[1]);
  }
  // Spread: the front covers most of 1/3 .. 1 supports per metre.
  EXPECT_GT(hi - lo, 0.5 * (1.0 - 1.0 / 3.0));
  ASSERT_TRUE(r.chosen);
  ASSERT_LT(*r.chosen, r.front.size());
  ASSERT_TRUE(r.best_drive);
  EXPECT_EQ(r.best_drive->rack.span, r.front[*r.chosen].x[0]);
  // The chosen point is an interior compromise, not an end of the front.
  if (r.front.size() >= 3) {
    EXPECT_GT(*r.chosen, 0u);
    EXPECT_LT(*r.chosen, r.front.size() - 1);
  }
  // Weights (1, 0) choose the end with the least fluctuation.
  StudySpec w = s;
  w.choose_weights = {1, 0};
  const StudyResult rw = run_study(w, options_in(scratch_path("pareto_w")));
  ASSERT_TRUE(rw.chosen);
  EXPECT_EQ(*rw.chosen, 0u);
}

// ---------------------------------------------------------------- evaluate / reliability

TEST(StudyEvaluate, OneDesignMatchesEvaluateMetricsDirectly) {
  StudySpec s = railway_spec(StudyKind::kEvaluate);
  s.variables = {continuous("pinion.pressure_angle", 10 * kDeg, 20 * kDeg, 17 * kDeg)};
  s.objectives = {objective("stiffness_fluctuation")};
  s.report_metrics = {metrics::parse_metric_request("min_stiffness"), metrics::parse_metric_request("contact_ratio")};
  const StudyResult r = run_study(s, options_in(scratch_path("evaluate")));
  EXPECT_EQ(to_string(r.status), "ok");
  EXPECT_EQ(r.evaluations, 1u);
  ASSERT_TRUE(r.best);
  EXPECT_EQ(r.best->x[0], 17 * kDeg);

  const ProblemTree tree = load_problem_tree_file(s.problem_path, s.problem_overrides);
  const std::vector<std::pair<std::string, double>> x{{"pinion.pressure_angle", 17 * kDeg}};
  const auto want = s.all_metrics();
  const metrics::MetricValues v = metrics::evaluate_metrics(drive_with_values(tree, x), want, {});
  ASSERT_TRUE(v.all_ok());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(r.best->metric_values[i], v.values[i].value);
  ASSERT_TRUE(r.best_drive);
  EXPECT_EQ(r.best_drive->pinion.pressure_angle, 17 * kDeg);
}

TEST(StudyEvaluate, WithoutVariablesEvaluatesTheProblemAsWrittenAndResumes) {
  StudySpec s = railway_spec(StudyKind::kEvaluate);
  s.report_metrics = {metrics::parse_metric_request("supports_per_metre")};
  const std::string dir = scratch_path("evaluate_plain");
  const StudyResult r = run_study(s, options_in(dir));
  ASSERT_TRUE(r.best);
  EXPECT_TRUE(r.best->x.empty());
  EXPECT_DOUBLE_EQ(metric(*r.best, "supports_per_metre"), 1 / 2.4);  // rack.span: 2.4 m in the file
  RunOptions again = options_in(dir);
  again.resume = true;
  const StudyResult r2 = run_study(s, again);
  EXPECT_EQ(r2.reused_evaluations, 1u);
  EXPECT_EQ(r2.evaluations, 1u);
  EXPECT_EQ(rows_of(r2, s).size(), 1u);
}

TEST(StudyReliability, RunsTheWearAnalysisOfTheDesign) {
  StudySpec s;
  s.name = "rel";
  s.file = "rel.yaml";
  s.kind = StudyKind::kReliability;
  s.problem_path = kSourceDir + "/problems/ship_lift.yaml";
  s.problem_overrides = {"reliability.samples=60"};
  s.report_metrics = {metrics::parse_metric_request("wear_life"), metrics::parse_metric_request("wear_life_at_R(0.9)")};
  s.metric_options.bootstrap_replicates = 20;
  const StudyResult r = run_study(s, options_in(scratch_path("reliability"), 2));
  EXPECT_EQ(to_string(r.status), "ok");
  ASSERT_TRUE(r.best);
  ASSERT_TRUE(r.reliability);
  EXPECT_EQ(r.reliability->lives.size(), 60u);
  // The deterministic life of the analysis is the wear_life metric of the design.
  EXPECT_NEAR(metric(*r.best, "wear_life"), r.reliability->nominal.life_cycles / 1.0e4 * 365.25 * 86400,
              1e-6 * metric(*r.best, "wear_life"));
  EXPECT_LT(metric(*r.best, "wear_life_at_R(0.9)"), metric(*r.best, "wear_life"));
}

// ---------------------------------------------------------------- fingerprint

TEST(StudyFingerprint, DependsOnWhatChangesResultsOnly) {
  const StudySpec s = sizing_spec(StudyKind::kOptimize);
  const std::string f = study_fingerprint(s);
  EXPECT_EQ(f, study_fingerprint(s));
  EXPECT_EQ(f.size(), 16u);
  StudySpec same = s;
  same.name = "another name";
  same.solver.max_evaluations = 5;
  same.solver.max_seconds = 3;
  same.output.plots = false;
  EXPECT_EQ(study_fingerprint(same), f);
  StudySpec a = s;
  a.variables[1].upper = std::nextafter(3.0, 4.0);
  EXPECT_NE(study_fingerprint(a), f);
  StudySpec b = s;
  b.problem_overrides.push_back("rack.span=2 m");
  EXPECT_NE(study_fingerprint(b), f);
  StudySpec c = s;
  c.seed = 8;
  EXPECT_NE(study_fingerprint(c), f);
  StudySpec d = s;
  d.objectives[0].maximize = true;
  EXPECT_NE(study_fingerprint(d), f);
}

}  // namespace
}  // namespace rackopt::study
