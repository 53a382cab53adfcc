// The stiffness curve of the best design is computed by the runner and only
// drawn by the report: run_study hands it over exactly when the study asks
// for it (output.stiffness_curve), the report's stiffness.csv is that curve,
// and a design the model refuses leaves a warning instead of a curve.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/study_report/study_report.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/study/best_design_curve.hpp"
#include "rackopt/study/study_runner.hpp"
#include "report_test_support.hpp"
#include "support/shipped_problems.hpp"

namespace {

// rack_railway evaluated as written, with a coarse travel sampling (only the
// handover is checked, not the curve's resolution).
StudySpec railway_evaluate_spec(bool stiffness_curve) {
  StudySpec s;
  s.name = "handover";
  s.kind = StudyKind::kEvaluate;
  s.problem_path = test_support::shipped_problem_path("rack_railway.yaml");
  s.problem_overrides = {"numerics.positions_per_period=24"};
  s.report_metrics = {metrics::parse_metric_request("contact_ratio")};
  s.output.plots = false;
  s.output.stiffness_curve = stiffness_curve;
  return s;
}

RunOptions handover_run_options(const std::string& dir) {
  RunOptions o;
  o.out_dir = dir;
  o.threads = 1;
  return o;
}

TEST(BestCurveHandover, RunnerHandsTheCurveOverWhenAskedAndTheReportWritesIt) {
  const StudySpec spec = railway_evaluate_spec(true);
  const std::string dir = scratch_path("handover_on");
  const StudyResult r = run_study(spec, handover_run_options(dir));
  ASSERT_TRUE(r.best_drive);
  ASSERT_TRUE(r.best_curve);
  EXPECT_TRUE(r.best_curve_error.empty());
  const StudyReport rep = write_study_report(spec, r, dir);
  ASSERT_EQ(rep.files.get("stiffness_csv"), dir + "/stiffness.csv");
  EXPECT_EQ(read_text(dir + "/stiffness.csv"), stiffness_csv(MeshStiffnessModel(*r.best_drive).curve()));
}

TEST(BestCurveHandover, NoCurveWhenTheStudyDoesNotAskForIt) {
  const StudySpec spec = railway_evaluate_spec(false);
  const std::string dir = scratch_path("handover_off");
  const StudyResult r = run_study(spec, handover_run_options(dir));
  ASSERT_TRUE(r.best_drive);
  EXPECT_FALSE(r.best_curve);
  EXPECT_TRUE(r.best_curve_error.empty());
  const StudyReport rep = write_study_report(spec, r, dir);
  EXPECT_EQ(rep.files.get("stiffness_csv"), "");
  EXPECT_FALSE(fs::exists(dir + "/stiffness.csv"));
}

TEST(BestCurveHandover, ARefusedDesignIsAWarningOfTheReport) {
  StudySpec spec = railway_evaluate_spec(true);
  StudyResult r;
  r.status = study::StudyStatus::kOk;
  Drive pointed = load_problem(spec.problem_path);
  pointed.pinion.profile_shift = 2.5;  // a tooth this far out comes to a point
  r.best_drive = std::make_shared<const Drive>(pointed);
  attach_best_design_curve(spec, r);
  EXPECT_FALSE(r.best_curve);
  ASSERT_EQ(r.best_curve_error.rfind("no stiffness curve of the best design (", 0), 0u) << r.best_curve_error;
  const std::string dir = scratch_path("handover_refused");
  const StudyReport rep = write_study_report(spec, r, dir);
  ASSERT_FALSE(rep.warnings.empty());
  EXPECT_EQ(rep.warnings.back(), r.best_curve_error);
  EXPECT_FALSE(fs::exists(dir + "/stiffness.csv"));
}

}  // namespace
