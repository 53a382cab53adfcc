// The study report writer on synthetic StudySpec/StudyResult values: what
// summary.json says is what the result holds, every table has one row per
// design, report.md links only files that exist, a missing gnuplot is a
// warning.
#include "rackopt/study_report/study_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/output/plot.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/study/best_design_curve.hpp"
#include "report_test_support.hpp"
#include "support/shipped_problems.hpp"

namespace {

TEST(StudyReport, OptimizeSummaryHoldsTheBestDesignCountsAndTimings) {
  const StudySpec spec = base_spec(StudyKind::kOptimize);
  StudyResult r;
  r.status = study::StudyStatus::kConverged;
  r.best = design(spec, 0.025, 2.0, "start 0");
  r.evaluations = 40;
  r.reused_evaluations = 8;
  r.failed_evaluations = 3;
  r.seconds = 0.64;
  for (int i = 0; i < 40; ++i) {
    r.best_history.push_back(i < 5 ? std::numeric_limits<double>::infinity() : 1.0 / (i + 1));
  }
  r.warnings = {"model says hello"};
  r.best_drive = std::make_shared<const Drive>(load_problem(spec.problem_path));
  attach_best_design_curve(spec, r);  // the runner's handover: the report draws, never computes

  const std::string dir = scratch_path("optimize");
  const StudyReport rep = write_study_report(spec, r, dir);
  const auto j = nlohmann::json::parse(read_text(dir + "/summary.json"));
  EXPECT_EQ(j, nlohmann::json::parse(rep.summary_json));
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["kind"], "optimize");
  EXPECT_EQ(j["study"], "synthetic");
  EXPECT_EQ(j["evaluations"], 40);
  EXPECT_EQ(j["failed_evaluations"], 3);
  EXPECT_EQ(j["reused_evaluations"], 8);
  EXPECT_DOUBLE_EQ(j["timings"]["seconds"].get<double>(), 0.64);
  // 32 new evaluations in 0.64 s
  EXPECT_NEAR(j["timings"]["per_evaluation_ms"].get<double>(), 20.0, 1e-9);
  const auto& best = j["best"];
  EXPECT_DOUBLE_EQ(best["variables"]["pinion.module"]["value"].get<double>(), 0.025);
  EXPECT_EQ(best["variables"]["pinion.module"]["display"], "25 mm");
  EXPECT_EQ(best["variables"]["rack.span"]["display"], "2 m");
  EXPECT_DOUBLE_EQ(best["metrics"]["stiffness_fluctuation"]["value"].get<double>(), 0.025 * 10 + 0.02);
  EXPECT_DOUBLE_EQ(best["metrics"]["min_stiffness"]["value"].get<double>(), 2.5e6);
  EXPECT_EQ(best["metrics"]["min_stiffness"]["display"], "2.5 MN/m");
  EXPECT_TRUE(best["metrics"]["contact_ratio"]["ok"].get<bool>());
  EXPECT_TRUE(best["feasible"].get<bool>());
  EXPECT_EQ(best["objectives"][0]["metric"], "stiffness_fluctuation");
  EXPECT_EQ(best["objectives"][0]["sense"], "minimize");
  EXPECT_FALSE(j.contains("front"));
  EXPECT_FALSE(j.contains("least_infeasible"));
  EXPECT_EQ(j["warnings"][0], "model says hello");

  // Every file the summary names exists, and the tables have one row per design.
  for (const auto& [role, path] : j["files"].items()) EXPECT_TRUE(fs::exists(path.get<std::string>())) << role;
  for (const char* role : {"best_csv", "history_csv", "stiffness_csv", "report_md", "summary_json"}) {
    EXPECT_TRUE(j["files"].contains(role)) << role;
  }
  const auto bestcsv = read_csv(dir + "/best.csv");
  ASSERT_EQ(bestcsv.size(), 2u);
  const int mcol = column(bestcsv[0], "pinion.module_m");
  const int mmcol = column(bestcsv[0], "pinion.module_mm");
  const int kcol = column(bestcsv[0], "min_stiffness_N_per_m");
  ASSERT_GE(mcol, 0);
  ASSERT_GE(mmcol, 0);
  ASSERT_GE(kcol, 0);
  EXPECT_EQ(std::strtod(bestcsv[1][mcol].c_str(), nullptr), 0.025);  // SI round trip, bit for bit
  EXPECT_NEAR(std::strtod(bestcsv[1][mmcol].c_str(), nullptr), 25.0, 1e-9);
  EXPECT_EQ(std::strtod(bestcsv[1][kcol].c_str(), nullptr), 2.5e6);
  EXPECT_EQ(bestcsv[1][column(bestcsv[0], "role")], "best");

  const auto hist = read_csv(dir + "/history.csv");
  ASSERT_EQ(hist.size(), 41u);
  EXPECT_EQ(hist[0][0], "evaluation");
  EXPECT_EQ(hist[1][1], "");  // no feasible point yet
  EXPECT_DOUBLE_EQ(std::strtod(hist[40][1].c_str(), nullptr), 1.0 / 40);
  EXPECT_GT(read_csv(dir + "/stiffness.csv").size(), 10u);

  if (gnuplot_available()) {
    EXPECT_TRUE(fs::exists(dir + "/history.png"));
    EXPECT_TRUE(fs::exists(dir + "/stiffness.png"));
    EXPECT_TRUE(j["files"].contains("history_png"));
  }
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_NE(e.path().extension(), ".tmp") << e.path();
    EXPECT_NE(e.path().extension(), ".log") << e.path();
  }
  expect_links_exist(dir);
  const std::string md = read_text(dir + "/report.md");
  // The stiffness plot ends at the span with both hinges marked, and the
  // report says below it why the curve is not symmetric.
  const std::string gp = read_text(dir + "/stiffness.gp");
  const auto stiff = read_csv(dir + "/stiffness.csv");
  const double span = std::strtod(stiff.back()[0].c_str(), nullptr);
  std::ostringstream range;
  range.precision(17);
  range << "set xrange [0:" << span << "]";
  EXPECT_NE(gp.find(range.str()), std::string::npos) << gp;
  EXPECT_NE(gp.find("set label 'hinge'"), std::string::npos);
  if (gnuplot_available()) {
    EXPECT_NE(md.find("![Stiffness over one span](stiffness.png)"), std::string::npos) << md;
    EXPECT_NE(md.find("not symmetric about mid-span"), std::string::npos);
    EXPECT_NE(md.find("![Convergence](history.png)"), std::string::npos);
  }
  EXPECT_NE(md.find("converged"), std::string::npos);
  EXPECT_NE(md.find("25 mm"), std::string::npos);
  EXPECT_NE(md.find("contact_ratio"), std::string::npos);
  EXPECT_NE(md.find("model says hello"), std::string::npos);
  EXPECT_NE(md.find(spec.description), std::string::npos);
  EXPECT_EQ(j["description"], spec.description);
}

TEST(StudyReport, ParetoFrontHasEveryPointAndExactlyOneChosen) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.objectives.push_back(objective("supports_per_metre"));
  const StudyResult r = pareto_result(spec, 7, 4);
  const std::string dir = scratch_path("pareto2");
  const StudyReport rep = write_study_report(spec, r, dir);
  const auto j = nlohmann::json::parse(rep.summary_json);
  EXPECT_EQ(j["kind"], "pareto");
  ASSERT_EQ(j["front"].size(), 7u);
  EXPECT_EQ(j["chosen"], 4);
  int chosen = 0;
  for (std::size_t k = 0; k < 7; ++k) {
    const auto& p = j["front"][k];
    chosen += p["chosen"].get<bool>() ? 1 : 0;
    EXPECT_EQ(p["chosen"].get<bool>(), k == 4);
    // JSON numbers carry 10 significant digits (JsonWriter); the CSVs are exact.
    EXPECT_NEAR(p["objectives"][1]["value"].get<double>(), 1.0 / r.front[k].x[1], 1e-9);
    EXPECT_NEAR(p["variables"]["rack.span"]["value"].get<double>(), r.front[k].x[1], 1e-9 * 3);
  }
  EXPECT_EQ(chosen, 1);
  EXPECT_TRUE(j["best"].is_null());

  const auto front = read_csv(dir + "/front.csv");
  ASSERT_EQ(front.size(), 8u);
  const int ccol = column(front[0], "chosen");
  const int scol = column(front[0], "supports_per_metre_per_m");
  ASSERT_GE(ccol, 0);
  ASSERT_GE(scol, 0);
  for (std::size_t k = 0; k < 7; ++k) {
    EXPECT_EQ(front[k + 1][ccol], k == 4 ? "1" : "0");
    EXPECT_EQ(std::strtod(front[k + 1][scol].c_str(), nullptr), 1.0 / r.front[k].x[1]);
  }
  if (gnuplot_available()) {
    EXPECT_TRUE(fs::exists(dir + "/pareto.png"));
  }
  EXPECT_FALSE(fs::exists(dir + "/best.csv"));
  expect_links_exist(dir);
  EXPECT_NE(read_text(dir + "/report.md").find("**chosen**"), std::string::npos);
}

// The grey cloud behind the front reads the objectives' columns of
// evaluations.csv by the names the record's writer gives them (with units).
TEST(StudyReport, FrontPlotFindsTheObjectivesInTheRecordsCsv) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.objectives.push_back(objective("supports_per_metre"));
  StudyResult r = pareto_result(spec, 5, 2);
  const std::string dir = scratch_path("pareto_cloud");
  record::StoreOptions options;
  for (const auto& m : spec.all_metrics())
    options.units[metrics::to_string(m)] = std::string(metrics::find_metric(m.name).unit);
  std::vector<std::string> keys;
  for (const auto& v : spec.variables) keys.push_back(v.key);
  {
    auto store = record::EvaluationStore::open(dir + "/evaluations.sqlite", "fp", keys, false, options);
    for (const auto& d : r.front) {
      record::RecordedEvaluation e;
      e.x = d.x;
      for (std::size_t i = 0; i < d.metric_labels.size(); ++i) e.metrics.emplace_back(d.metric_labels[i], d.metric_values[i]);
      store.append(e);
    }
    std::vector<std::string> labels;
    for (const auto& m : spec.all_metrics()) labels.push_back(metrics::to_string(m));
    record::write_evaluations_csv(store, keys, labels, dir + "/evaluations.csv");
  }
  r.evaluations_csv_path = dir + "/evaluations.csv";
  write_study_report(spec, r, dir);
  const std::string gp = read_text(dir + "/pareto.gp");
  EXPECT_NE(gp.find("keyentry with points pt 7 ps 1 lc rgb '#c8c8c8' title 'every evaluation'"), std::string::npos);
  EXPECT_NE(gp.find("'evaluations.csv' skip 1 using"), std::string::npos);
}

TEST(StudyReport, ThreeObjectiveFrontIsPlottedAsThreeProjections) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.objectives.push_back(objective("supports_per_metre"));
  spec.objectives.push_back(objective("min_stiffness", true));
  const StudyResult r = pareto_result(spec, 9, 0);
  const std::string dir = scratch_path("pareto3");
  const StudyReport rep = write_study_report(spec, r, dir);
  const std::string gp = read_text(dir + "/pareto.gp");
  EXPECT_NE(gp.find("# 3 projections: 1 row of 3\n"), std::string::npos);
  // One legend for the three panels, below them.
  EXPECT_EQ(occurrences_of(gp, "'front.csv' skip 1 using"), 3u);
  EXPECT_EQ(occurrences_of(gp, "title 'Pareto front'"), 1u);
  EXPECT_EQ(occurrences_of(gp, "title 'chosen design'"), 1u);
  EXPECT_EQ(occurrences_of(gp, "title 'every evaluation'"), 0u);  // no evaluations.csv here
  const auto j = nlohmann::json::parse(rep.summary_json);
  EXPECT_EQ(j["front"][0]["objectives"][2]["sense"], "maximize");
  if (gnuplot_available()) {
    EXPECT_TRUE(fs::exists(dir + "/pareto.png"));
  }
}

TEST(StudyReport, FrontQualityInSummaryReportAndHistory) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.objectives.push_back(objective("min_stiffness", true));  // maximized: minimized as its negative
  spec.pareto.points = 10;
  StudyResult r = pareto_result(spec, 7, 3);
  study::FrontSummary f;
  f.requested = 10;
  f.quality.points = 7;
  f.quality.non_dominated = 7;
  f.quality.hypervolume = 0.625;
  f.quality.spacing = 0.125;
  f.quality.ideal = {0.02, -3.0e7};      // minimized: -(largest min_stiffness)
  f.quality.reference = {0.04, -1.0e7};  // -(smallest acceptable min_stiffness)
  f.history_evaluations = {100, 200};
  f.history_hypervolume = {0.5, 0.75};
  f.shortfall = {"eps 3 found no feasible design"};
  r.front_summary = f;
  const std::string dir = scratch_path("front_quality");
  const StudyReport rep = write_study_report(spec, r, dir);
  const auto j = nlohmann::json::parse(rep.summary_json);
  const auto& q = j["front_quality"];
  EXPECT_EQ(q["requested"], 10);
  EXPECT_EQ(q["points"], 7);
  EXPECT_EQ(q["hypervolume"].get<double>(), 0.625);
  EXPECT_EQ(q["spacing"].get<double>(), 0.125);
  // Reported in each metric's own sense: the maximized one positive again.
  EXPECT_EQ(q["reference"]["min_stiffness"].get<double>(), 1.0e7);
  EXPECT_EQ(q["ideal"]["stiffness_fluctuation"].get<double>(), 0.02);
  ASSERT_EQ(q["hypervolume_history"].size(), 2u);
  EXPECT_EQ(q["hypervolume_history"][1][0], 200);
  EXPECT_EQ(q["hypervolume_history"][1][1].get<double>(), 0.75);
  EXPECT_EQ(q["shortfall"][0], "eps 3 found no feasible design");
  EXPECT_EQ(read_text(dir + "/hypervolume.csv"), "evaluations,hypervolume\n100,0.5\n200,0.75\n");
  EXPECT_NE(read_text(dir + "/history.gp").find("hypervolume.csv"), std::string::npos);
  const std::string md = read_text(dir + "/report.md");
  EXPECT_NE(md.find("7 delivered of 10 requested"), std::string::npos);
  EXPECT_NE(md.find("eps 3 found no feasible design"), std::string::npos);
  EXPECT_NE(md.find("hypervolume: 0.625"), std::string::npos);
}

TEST(StudyReport, FourObjectiveFrontIsPlottedAsSixProjections) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.objectives.push_back(objective("supports_per_metre"));
  spec.objectives.push_back(objective("min_stiffness", true));
  spec.objectives.push_back(objective("contact_ratio", true));
  const StudyResult r = pareto_result(spec, 9, 0);
  const std::string dir = scratch_path("pareto4");
  write_study_report(spec, r, dir);
  const std::string gp = read_text(dir + "/pareto.gp");
  EXPECT_NE(gp.find("# 6 projections: 2 rows of 3\n"), std::string::npos);
  EXPECT_EQ(occurrences_of(gp, "'front.csv' skip 1 using"), 6u);
  EXPECT_EQ(occurrences_of(gp, "title 'Pareto front'"), 1u);
}

TEST(StudyReport, SweepTableHasOneRowPerPointAndFeasibilityFlags) {
  StudySpec spec = base_spec(StudyKind::kSweep);
  StudyResult r;
  r.status = study::StudyStatus::kOk;
  for (int a = 0; a < 5; ++a) {
    for (int b = 0; b < 4; ++b) {
      DesignResult d = design(spec, 0.02 + 0.003 * a, 0.4 + 0.8 * b, "sweep " + std::to_string(a * 4 + b));
      r.sweep_points.push_back(d);
    }
  }
  // one failed point: metric columns empty, ok = 0
  r.sweep_points[3].ok = false;
  r.sweep_points[3].feasible = false;
  r.sweep_points[3].metric_ok.assign(r.sweep_points[3].metric_ok.size(), false);
  r.sweep_points[3].max_violation = std::numeric_limits<double>::infinity();
  r.sweep_points[3].message = "pointed tooth, \"really\"";
  r.best = r.sweep_points[0];
  r.evaluations = 20;
  r.failed_evaluations = 1;
  const std::string dir = scratch_path("sweep");
  const StudyReport rep = write_study_report(spec, r, dir);
  const auto j = nlohmann::json::parse(rep.summary_json);
  EXPECT_EQ(j["sweep_points"], 20);
  std::size_t expect_feasible = 0;
  for (const auto& d : r.sweep_points) expect_feasible += d.feasible ? 1 : 0;
  EXPECT_EQ(j["feasible_points"], expect_feasible);

  const auto t = read_csv(dir + "/sweep.csv");
  ASSERT_EQ(t.size(), 21u);
  const int fcol = column(t[0], "feasible");
  const int okcol = column(t[0], "ok");
  const int crcol = column(t[0], "contact_ratio");
  const int vcol = column(t[0], "max_violation");
  ASSERT_GE(fcol, 0);
  ASSERT_GE(crcol, 0);
  for (std::size_t i = 0; i < 20; ++i) {
    ASSERT_EQ(t[i + 1].size(), t[0].size()) << "row " << i;
    EXPECT_EQ(t[i + 1][fcol], r.sweep_points[i].feasible ? "1" : "0");
    // feasible exactly when contact ratio >= 1.3 (for the points that computed)
    if (i != 3) {
      EXPECT_EQ(t[i + 1][fcol] == "1", std::strtod(t[i + 1][crcol].c_str(), nullptr) >= 1.3) << i;
    }
  }
  EXPECT_EQ(t[4][okcol], "0");
  EXPECT_EQ(t[4][crcol], "");
  EXPECT_EQ(t[4][vcol], "");
  EXPECT_EQ(t[4].back(), "pointed tooth, \"really\"");  // CSV-quoted, last column
  EXPECT_TRUE(j["files"].contains("best_csv"));
  if (gnuplot_available()) {
    EXPECT_TRUE(fs::exists(dir + "/sweep.png"));
  }
  expect_links_exist(dir);
}

TEST(StudyReport, NoFeasiblePointShowsTheLeastInfeasibleDesign) {
  const StudySpec spec = base_spec(StudyKind::kOptimize);
  StudyResult r;
  r.status = study::StudyStatus::kNoFeasiblePoint;
  r.least_infeasible = design(spec, 0.02, 0.8, "start 0");  // contact ratio 1.2 < 1.3
  ASSERT_FALSE(r.least_infeasible->feasible);
  r.evaluations = 12;
  r.best_history = std::vector<double>(12, std::numeric_limits<double>::infinity());
  const std::string dir = scratch_path("infeasible");
  const StudyReport rep = write_study_report(spec, r, dir);
  const auto j = nlohmann::json::parse(rep.summary_json);
  EXPECT_EQ(j["status"], "no_feasible_point");
  EXPECT_TRUE(j["best"].is_null());
  EXPECT_FALSE(j["feasible"].get<bool>());
  ASSERT_TRUE(j.contains("least_infeasible"));
  EXPECT_NEAR(j["least_infeasible"]["max_violation"].get<double>(), (1.3 - 1.2) / 1.3, 1e-10);
  EXPECT_NE(j["message"].get<std::string>().find("least infeasible"), std::string::npos);
  const auto b = read_csv(dir + "/best.csv");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[1][column(b[0], "role")], "least_infeasible");
  EXPECT_EQ(b[1][column(b[0], "feasible")], "0");
  // no finite history: no convergence plot
  EXPECT_FALSE(fs::exists(dir + "/history.png"));
  expect_links_exist(dir);
  EXPECT_NE(read_text(dir + "/report.md").find("Least infeasible design"), std::string::npos);
}

TEST(StudyReport, StoppedStudySaysHowToResume) {
  const StudySpec spec = base_spec(StudyKind::kOptimize);
  StudyResult r;
  r.status = study::StudyStatus::kStopped;
  r.best = design(spec, 0.025, 2.0, "start 0");
  r.evaluations = 9;
  const std::string dir = scratch_path("stopped");
  const auto j = nlohmann::json::parse(write_study_report(spec, r, dir).summary_json);
  EXPECT_EQ(j["status"], "stopped");
  EXPECT_NE(j["message"].get<std::string>().find("--resume"), std::string::npos);
}

TEST(StudyReport, FailedDesignWritesNullsNotNaN) {
  const StudySpec spec = base_spec(StudyKind::kEvaluate);
  StudyResult r;
  r.status = study::StudyStatus::kAllFailed;
  DesignResult d = design(spec, 0.02, 1.0, "start 0");
  d.ok = false;
  d.feasible = false;
  d.metric_ok.assign(d.metric_ok.size(), false);
  d.metric_values.assign(d.metric_values.size(), 0.0);
  d.objectives = {std::numeric_limits<double>::quiet_NaN()};
  d.max_violation = std::numeric_limits<double>::infinity();
  d.message = "undercut beyond the limit";
  r.least_infeasible = d;
  r.evaluations = 1;
  r.failed_evaluations = 1;
  const std::string dir = scratch_path("failed");
  const auto j = nlohmann::json::parse(write_study_report(spec, r, dir).summary_json);
  const auto& li = j["least_infeasible"];
  EXPECT_TRUE(li["max_violation"].is_null());
  EXPECT_TRUE(li["metrics"]["contact_ratio"]["value"].is_null());
  EXPECT_FALSE(li["metrics"]["contact_ratio"]["ok"].get<bool>());
  EXPECT_TRUE(li["objectives"][0]["value"].is_null());
  EXPECT_NE(j["message"].get<std::string>().find("undercut beyond the limit"), std::string::npos);
  EXPECT_EQ(j["timings"]["per_evaluation_ms"].get<double>(), 0.0);  // 0 s over 1 evaluation
}

TEST(StudyReport, MissingGnuplotIsAWarningAndNothingLinksAPlot) {
  const StudySpec spec = base_spec(StudyKind::kOptimize);
  StudyResult r;
  r.status = study::StudyStatus::kConverged;
  r.best = design(spec, 0.025, 2.0, "start 0");
  r.evaluations = 3;
  r.best_history = {0.5, 0.4, 0.3};
  const std::string dir = scratch_path("nognuplot");
  ::setenv("RACKOPT_GNUPLOT", "/nonexistent/gnuplot-for-rackopt-tests", 1);
  const StudyReport rep = write_study_report(spec, r, dir);
  ::unsetenv("RACKOPT_GNUPLOT");
  ASSERT_FALSE(rep.warnings.empty());
  EXPECT_NE(rep.warnings[0].find("not found"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/history.png"));
  EXPECT_TRUE(fs::exists(dir + "/history.gp"));  // the script is there to run by hand
  const auto j = nlohmann::json::parse(rep.summary_json);
  EXPECT_FALSE(j["files"].contains("history_png"));
  EXPECT_EQ(j["warnings"].size(), rep.warnings.size());
  const std::string md = read_text(dir + "/report.md");
  EXPECT_EQ(md.find(".png"), std::string::npos);
  expect_links_exist(dir);
}

TEST(StudyReport, OutputSwitchesTurnPlotsAndReportOff) {
  StudySpec spec = base_spec(StudyKind::kOptimize);
  spec.output.plots = false;
  spec.output.report = false;
  StudyResult r;
  r.status = study::StudyStatus::kConverged;
  r.best = design(spec, 0.025, 2.0, "start 0");
  r.best_history = {0.5};
  const std::string dir = scratch_path("switches");
  const StudyReport rep = write_study_report(spec, r, dir);
  EXPECT_FALSE(fs::exists(dir + "/report.md"));
  EXPECT_FALSE(fs::exists(dir + "/history.gp"));
  EXPECT_TRUE(fs::exists(dir + "/summary.json"));
  for (const auto& w : rep.written) EXPECT_TRUE(fs::exists(w)) << w;
}

TEST(StudyReport, BestDesignsOwnWarningsComeFirstUnderTheirOwnHeading) {
  StudySpec spec = base_spec(StudyKind::kOptimize);
  spec.output.plots = false;
  StudyResult r;
  r.status = study::StudyStatus::kConverged;
  r.best = design(spec, 0.025, 2.0, "start 0");
  r.best->warnings = {"undercut of the best", "shared remark"};
  r.best_history = {0.5};
  // Run order: another design's warning came first.
  r.warnings = {"warning of another design", "shared remark", "undercut of the best"};
  const std::string dir = scratch_path("best_warnings");
  const StudyReport rep = write_study_report(spec, r, dir);
  const auto j = nlohmann::json::parse(rep.summary_json);
  EXPECT_EQ(j["best"]["warnings"], nlohmann::json({"undercut of the best", "shared remark"}));
  EXPECT_EQ(j["warnings"], nlohmann::json({"undercut of the best", "shared remark", "warning of another design"}));

  const std::string md = read_text(dir + "/report.md");
  const std::size_t own = md.find("## Warnings of the best design\n");
  const std::size_t rest = md.find("## Other warnings of the run\n");
  ASSERT_NE(own, std::string::npos) << md;
  ASSERT_NE(rest, std::string::npos) << md;
  const std::size_t a = md.find("- undercut of the best\n"), b = md.find("- shared remark\n"),
                    c = md.find("- warning of another design\n");
  EXPECT_TRUE(own < a && a < b && b < rest && rest < c) << md;
  EXPECT_EQ(md.find("- shared remark\n", b + 1), std::string::npos) << "listed twice\n" << md;

  // A best design without warnings: one plain list, no empty section.
  r.best->warnings.clear();
  const std::string dir2 = scratch_path("run_warnings_only");
  const StudyReport rep2 = write_study_report(spec, r, dir2);
  const std::string md2 = read_text(dir2 + "/report.md");
  EXPECT_EQ(md2.find("Warnings of the best design"), std::string::npos) << md2;
  EXPECT_EQ(md2.find("Other warnings"), std::string::npos) << md2;
  EXPECT_NE(md2.find("## Warnings\n\n- warning of another design\n- shared remark\n- undercut of the best\n"),
            std::string::npos)
      << md2;
  EXPECT_EQ(nlohmann::json::parse(rep2.summary_json)["best"]["warnings"], nlohmann::json::array());
}

TEST(StudyReport, NearDuplicateWarningsAreOneGroupWithTheirCountAndDesigns) {
  StudySpec spec = base_spec(StudyKind::kOptimize);
  spec.output.plots = false;
  const StudyResult r = near_duplicate_warnings_result(spec);
  const std::string dir = scratch_path("warning_groups");
  const StudyReport rep = write_study_report(spec, r, dir);

  // report.md: the best design's own warnings first, under their own
  // heading with its evaluation, then one line per kind.
  const std::string md = read_text(dir + "/report.md");
  const std::size_t own = md.find("## Warnings of the best design (evaluation 17)\n\n");
  const std::size_t rest = md.find("## Other warnings of the run, by kind\n");
  ASSERT_NE(own, std::string::npos) << md;
  ASSERT_NE(rest, std::string::npos) << md;
  EXPECT_LT(own, rest);
  const std::size_t remark = md.find("- the best design's own remark\n");
  EXPECT_TRUE(own < remark && remark < rest) << md;
  const std::size_t undercut =
      md.find("- **pinion undercut: z = … \\< z\\_min = …** — 448 designs (evaluations 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, …)\n"
              "  - for example: pinion undercut: z = 11 \\< z\\_min = 18.1\n");
  EXPECT_GT(undercut, rest) << md;
  EXPECT_NE(md.find("- **cutter tip radius … mm is larger than the rack's** — 4 designs (evaluations 100, 200, 300, "
                    "400)\n  - for example: cutter tip radius 0.1 mm is larger than the rack's\n"),
            std::string::npos)
      << md;
  // 448 messages became: the best design's own one, and the kind with its example.
  EXPECT_EQ(occurrences_of(md, "pinion undercut"), 3u) << md;
  // The remark only the best design gave is not repeated among the others.
  EXPECT_EQ(occurrences_of(md, "own remark"), 1u) << md;

  // report.html is report.md rendered: the same groups.
  const std::string html = read_text(dir + "/report.html");
  EXPECT_NE(html.find("Other warnings of the run, by kind"), std::string::npos);
  EXPECT_NE(html.find("448 designs (evaluations 1, 2, 3"), std::string::npos);
  EXPECT_EQ(occurrences_of(html, "pinion undercut"), 3u);

  // summary.json: the groups for programs, the flat list as before.
  const auto j = nlohmann::json::parse(rep.summary_json);
  EXPECT_EQ(j["best"]["evaluation"], 17);
  ASSERT_EQ(j["warning_groups"].size(), 3u) << j["warning_groups"];
  const auto& g = j["warning_groups"][0];
  EXPECT_EQ(g["kind"], "pinion undercut: z = … < z_min = …");
  EXPECT_EQ(g["example"], "pinion undercut: z = 11 < z_min = 18.1");
  EXPECT_EQ(g["designs"], 448);
  EXPECT_EQ(g["evaluations"].size(), kMaxListedEvaluations);
  EXPECT_EQ(g["evaluations"][16], 17);
  EXPECT_EQ(g["best_design"], true);
  EXPECT_EQ(j["warning_groups"][1]["example"], "the best design's own remark");
  EXPECT_EQ(j["warning_groups"][1]["designs"], 1);
  EXPECT_EQ(j["warning_groups"][1]["best_design"], true);
  EXPECT_EQ(j["warning_groups"][2]["designs"], 4);
  EXPECT_EQ(j["warning_groups"][2]["best_design"], false);
  EXPECT_EQ(j["warning_kinds_dropped"], 0);
  EXPECT_EQ(j["warnings"][0], r.best->warnings[0]);
  EXPECT_EQ(j["warnings"].size(), r.warnings.size());  // the best design's two are among the run's first 20
}

TEST(StudyReport, ReliabilityStudyWritesTheWearFiles) {
  StudySpec spec;
  spec.name = "ship lift reliability";
  spec.kind = StudyKind::kReliability;
  spec.problem_path = test_support::shipped_problem_path("ship_lift.yaml");
  auto drive = std::make_shared<const Drive>(load_problem(spec.problem_path));
  WearReliabilityOptions opt;
  opt.samples = 100;
  opt.threads = 1;
  auto wr = std::make_shared<const WearReliabilityResult>(run_wear_reliability(*drive, opt));
  StudyResult r;
  r.status = study::StudyStatus::kOk;
  r.evaluations = 1;
  r.best_drive = drive;
  r.reliability = wr;
  r.best = DesignResult{};
  r.best->ok = r.best->feasible = true;
  r.best->label = "design";
  const std::string dir = scratch_path("reliability");
  const auto j = nlohmann::json::parse(write_study_report(spec, r, dir).summary_json);
  for (const char* role : {"wear_profile_csv", "life_samples_csv", "reliability_csv", "life_histogram_csv"}) {
    ASSERT_TRUE(j["files"].contains(role)) << role;
    EXPECT_TRUE(fs::exists(j["files"][role].get<std::string>())) << role;
  }
  // one row per Monte Carlo sample
  EXPECT_EQ(read_csv(dir + "/life_samples.csv").size(), wr->lives.size() + 1);
  // The wear analysis itself is in the summary, as `rackopt wear --json` has it.
  ASSERT_TRUE(j.contains("reliability"));
  EXPECT_EQ(j["reliability"]["life_years"].get<double>(), wr->nominal.life_years);
  EXPECT_EQ(j["reliability"]["reliability"].size(), drive->reliability.times.size());
  EXPECT_EQ(j["reliability"]["life_at_R"].size(), drive->reliability.reliabilities.size());
  std::ifstream md(dir + "/report.md");
  const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("Wear life and reliability of the design"), std::string::npos);
  if (gnuplot_available()) {
    EXPECT_TRUE(j["files"].contains("reliability_png"));
  }
  expect_links_exist(dir);
}

TEST(RenderPlot, FailingScriptLeavesNoImageAndWarns) {
  const std::string dir = scratch_path("badplot");
  fs::create_directories(dir);
  std::ofstream(dir + "/bad.gp") << "set terminal pngcairo\nset output 'bad.png.tmp'\nplot 'missing.csv' using 1:2\n";
  std::vector<std::string> warnings;
  const std::string png = render_plot(dir, "bad.gp", "bad.png", warnings);
  EXPECT_EQ(png, "");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_FALSE(fs::exists(dir + "/bad.png"));
  EXPECT_FALSE(fs::exists(dir + "/bad.png.tmp"));
}

TEST(MetricDisplay, UsesTheMetricsDisplayUnit) {
  EXPECT_EQ(metric_display("min_stiffness", 2.61e7), "26.1 MN/m");
  EXPECT_EQ(metric_display("contact_ratio", 1.5), "1.5");
  EXPECT_EQ(metric_display("supports_per_metre", 0.5), "0.5 1/m");
  EXPECT_EQ(metric_display("wear_life_at_R(0.9)", 31557600.0 * 2), "2 yr");
  DesignVariable v = variable("pinion.pressure_angle", QuantityKind::kAngle, "deg", 0.2, 0.4);
  EXPECT_EQ(variable_display(v, 20.0 * std::numbers::pi / 180.0), "20 deg");
  DesignVariable z = variable("pinion.teeth", QuantityKind::kCount, "", 12, 30);
  EXPECT_EQ(variable_display(z, 17.0), "17");
}

}  // namespace
