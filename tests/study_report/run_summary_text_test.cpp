// The text `rackopt run` prints when a study ends (study_summary_text): it
// names the status and the best or chosen design with its values in display
// units, caps the warnings, and tells a stopped run how to resume.
#include "rackopt/study_report/run_summary_text.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "report_test_support.hpp"

namespace {

TEST(StudySummaryText, NamesTheStatusAndTheBestDesign) {
  const StudySpec spec = base_spec(StudyKind::kOptimize);
  StudyResult r;
  r.status = study::StudyStatus::kConverged;
  r.best = design(spec, 0.025, 2.0, "start 0");
  r.evaluations = 40;
  StudyReport rep;
  rep.files.add("report_md", "out/synthetic/report.md");
  rep.files.add("report_html", "out/synthetic/report.html");
  const std::string text = study_summary_text(spec, r, rep, "out/synthetic");
  EXPECT_EQ(text.rfind("study synthetic (optimize): converged\n  " + status_message(spec, r) + "\n", 0), 0u)
      << text;
  EXPECT_NE(text.find("  best design (start 0):\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    pinion.module = 25 mm\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    min_stiffness: 2.5 MN/m\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  wrote out/synthetic/ (out/synthetic/report.md, out/synthetic/report.html)\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("continue with"), std::string::npos) << text;
  EXPECT_EQ(text.find("NO FEASIBLE DESIGN"), std::string::npos) << text;
}

TEST(StudySummaryText, ParetoMarksTheChosenPointAndListsItsValues) {
  const StudySpec spec = base_spec(StudyKind::kPareto);
  StudyResult r;
  r.status = study::StudyStatus::kOk;
  r.front = {design(spec, 0.02, 3.0, "eps 0"), design(spec, 0.026, 2.1, "eps 1"), design(spec, 0.032, 1.2, "eps 2")};
  r.chosen = 1;
  r.best = r.front[1];
  const std::string text = study_summary_text(spec, r, StudyReport{}, "o");
  EXPECT_NE(text.find("  Pareto front, 3 points:\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    0:  stiffness_fluctuation "), std::string::npos) << text;
  EXPECT_NE(text.find("  * 1:  stiffness_fluctuation "), std::string::npos) << text;
  EXPECT_NE(text.find("  chosen design (*):\n    pinion.module = 26 mm\n"), std::string::npos) << text;
  // Without report.md the summary is where the results are.
  EXPECT_NE(text.find("  wrote o/ (summary.json)\n"), std::string::npos) << text;
}

TEST(StudySummaryText, StoppedRunSaysHowToResumeAndWarningsAreCapped) {
  const StudySpec spec = base_spec(StudyKind::kOptimize);
  StudyResult r;
  r.status = study::StudyStatus::kStopped;
  r.evaluations = 12;
  r.least_infeasible = design(spec, 0.02, 1.2, "start 0");
  StudyReport rep;
  for (int i = 0; i < 7; ++i) rep.warnings.push_back("remark " + std::to_string(i));
  const std::string text = study_summary_text(spec, r, rep, "out/x");
  EXPECT_NE(text.find("study synthetic (optimize): stopped\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  NO FEASIBLE DESIGN. Least infeasible design (start 0):\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  warning: remark 4\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("remark 5"), std::string::npos) << text;
  EXPECT_NE(text.find("  ... and 2 more warnings (summary.json, report.md)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  continue with: rackopt run synthetic.yaml --out out/x --resume\n"), std::string::npos)
      << text;
}

}  // namespace
