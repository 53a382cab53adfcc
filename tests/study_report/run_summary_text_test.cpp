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

TEST(StudySummaryText, StoppedRunSaysHowToResumeAndWarningKindsAreCapped) {
  const StudySpec spec = base_spec(StudyKind::kOptimize);
  StudyResult r;
  r.status = study::StudyStatus::kStopped;
  r.evaluations = 12;
  r.least_infeasible = design(spec, 0.02, 1.2, "start 0");
  StudyReport rep;
  for (const char* kind : {"a", "b", "c", "d", "e", "f", "g"}) rep.warnings.push_back(std::string("remark ") + kind);
  const std::string text = study_summary_text(spec, r, rep, "out/x");
  EXPECT_NE(text.find("study synthetic (optimize): stopped\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  NO FEASIBLE DESIGN. Least infeasible design (start 0):\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  warnings:\n    remark a\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    remark e\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("remark f"), std::string::npos) << text;
  EXPECT_NE(text.find("    ... and 2 more kinds (report.md, summary.json)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  continue with: rackopt run synthetic.yaml --out out/x --resume\n"), std::string::npos)
      << text;
}

// The gantry study's case: 448 designs warn of an undercut, each with its
// own numbers. The summary shows the best design's own warnings under their
// own heading, then the undercut once with its count and first designs.
TEST(StudySummaryText, NearDuplicateWarningsAreOneLineAfterTheBestDesignsOwn) {
  const StudySpec spec = base_spec(StudyKind::kOptimize);
  const StudyResult r = near_duplicate_warnings_result(spec);
  StudyReport rep;
  rep.warnings = r.warnings;
  rep.warnings.push_back("gnuplot not found: wrote history.gp but no plot (install gnuplot-nox)");
  const std::string text = study_summary_text(spec, r, rep, "out/x");
  const std::size_t own = text.find("  warnings of the best design (evaluation 17):\n    pinion undercut: z = 18 < z_min = "
                                    "19.7\n    the best design's own remark\n");
  const std::size_t rest = text.find("  other warnings of the run, by kind:\n");
  ASSERT_NE(own, std::string::npos) << text;
  ASSERT_NE(rest, std::string::npos) << text;
  EXPECT_LT(own, rest);
  EXPECT_NE(text.find("    pinion undercut: z = … < z_min = … — 448 designs (evaluations 1, 2, 3, 4, 5, …)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("    gnuplot not found: wrote history.gp but no plot (install gnuplot-nox)\n"), std::string::npos)
      << text;
  EXPECT_EQ(occurrences_of(text, "pinion undercut"), 2u) << text;
  EXPECT_EQ(occurrences_of(text, "own remark"), 1u) << text;
}

}  // namespace
