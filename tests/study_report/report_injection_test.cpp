// A study file must never run commands: the user's text (the study's name,
// its description, messages) reaches gnuplot scripts, report.md,
// report.html and the CSV tables as text only. Each test writes a whole
// report with hostile text and looks at what each target got.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/study/best_design_curve.hpp"
#include "rackopt/study_report/markdown_text.hpp"
#include "rackopt/study_report/report_html.hpp"
#include "rackopt/study_report/study_report.hpp"
#include "report_test_support.hpp"

namespace {

// A name that ends a gnuplot statement and starts commands of its own, in
// each way gnuplot has: a new line, CR, backquotes, an @macro.
const std::string kHostileName =
    "rack\nsystem(\"touch owned_nl\")\rsystem(\"touch owned_cr\")\n`touch owned_bq` @rackopt_svg it's";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::string line;
  for (char c : text) {
    if (c == '\n') {
      out.push_back(line);
      line.clear();
    } else {
      line += c;
    }
  }
  if (!line.empty()) out.push_back(line);
  return out;
}

std::string lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Every .gp script of `dir`: the name sits inside one quoted string on a
// title line, and no line anywhere starts a command of the name's; when
// gnuplot ran (the report draws in `dir`), no command ran.
void expect_scripts_hold_the_name_as_text(const std::string& dir, std::size_t expected_scripts) {
  std::size_t scripts = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".gp") continue;
    ++scripts;
    const std::string gp = read_text(entry.path().string());
    for (const std::string& line : lines_of(gp)) {
      if (line.find("owned") == std::string::npos) continue;
      // the one statement that carries the name, as one quoted string
      EXPECT_TRUE(line.rfind("set title 'rack system(", 0) == 0 || line.rfind("set multiplot ", 0) == 0)
          << entry.path() << ": " << line;
      EXPECT_NE(line.find("'rack system(\"touch owned_nl\") system(\"touch owned_cr\") `touch owned_bq` "
                          "@rackopt_svg it''s"),
                std::string::npos)
          << line;
      EXPECT_EQ(line.find('\r'), std::string::npos) << line;
    }
  }
  EXPECT_EQ(scripts, expected_scripts) << dir;
  for (const char* owned : {"owned_nl", "owned_cr", "owned_bq"}) {
    EXPECT_FALSE(fs::exists(fs::path(dir) / owned)) << owned << " was created: gnuplot ran the name";
  }
}

TEST(ReportInjection, AStudyNameRunsNoCommandInAnyPlotOfAnOptimizeStudy) {
  StudySpec spec = base_spec(StudyKind::kOptimize);
  spec.name = kHostileName;
  StudyResult r;
  r.status = study::StudyStatus::kConverged;
  r.best = design(spec, 0.025, 2.0, "start 0");
  r.evaluations = 10;
  for (int i = 0; i < 10; ++i) r.best_history.push_back(1.0 / (i + 1));
  r.best_drive = std::make_shared<const Drive>(load_problem(spec.problem_path));
  attach_best_design_curve(spec, r);
  const std::string dir = scratch_path("injection_optimize");
  write_study_report(spec, r, dir);
  expect_scripts_hold_the_name_as_text(dir, 2);  // history.gp, stiffness.gp
}

TEST(ReportInjection, AStudyNameRunsNoCommandInAnyPlotOfAParetoStudy) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.objectives.push_back(objective("min_stiffness", true));
  spec.name = kHostileName;
  const std::string dir = scratch_path("injection_pareto");
  write_study_report(spec, pareto_result(spec, 6, 2), dir);
  expect_scripts_hold_the_name_as_text(dir, 2);  // pareto.gp, history.gp (hypervolume)
}

TEST(ReportInjection, AStudyNameRunsNoCommandInTheSweepPlot) {
  StudySpec spec = base_spec(StudyKind::kSweep);
  spec.name = kHostileName;
  StudyResult r;
  r.status = study::StudyStatus::kOk;
  for (int a = 0; a < 3; ++a) r.sweep_points.push_back(design(spec, 0.02 + 0.003 * a, 1.5, "sweep"));
  r.best = r.sweep_points[0];
  r.evaluations = 3;
  const std::string dir = scratch_path("injection_sweep");
  write_study_report(spec, r, dir);
  expect_scripts_hold_the_name_as_text(dir, 1);  // sweep.gp
}

// report.md: the name is the text of one heading; report.html's <h1> and
// <title> show it.
TEST(ReportInjection, AStudyNameIsOneHeadingInReportMdAndHtml) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.name = "x\n# Injected heading\n<script>alert(1)</script>\n| a |\n|---|\n[l](javascript:alert(1))";
  const std::string dir = scratch_path("injection_heading");
  write_study_report(spec, pareto_result(spec, 4, 1), dir);
  const std::string md = read_text(dir + "/report.md");
  EXPECT_EQ(md.rfind("# Study: " + markdown_text(spec.name) + "\n\n", 0), 0u) << md.substr(0, 300);
  EXPECT_EQ(md.find("\n# Injected"), std::string::npos);
  const std::string html = read_text(dir + "/report.html");
  EXPECT_EQ(occurrences_of(html, "<h1>"), 1u);
  EXPECT_NE(html.find("<h1>Study: x # Injected heading &lt;script&gt;alert(1)&lt;/script&gt; | a | |---| "
                      "[l](javascript:alert(1))</h1>"),
            std::string::npos)
      << html.substr(0, 3000);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("href=\"javascript"), std::string::npos);
}

// An HTML comment opened in a description closes at the end of the
// description: every table report.md writes after it is still a table.
TEST(ReportInjection, AnHtmlCommentInTheDescriptionDoesNotSwallowThePage) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  const std::string plain_dir = scratch_path("injection_comment_plain");
  write_study_report(spec, pareto_result(spec, 4, 1), plain_dir);
  const std::size_t tables = occurrences_of(read_text(plain_dir + "/report.html"), "<table>");
  ASSERT_GT(tables, 1u);

  spec.description = "Before the comment.\n\n<!-- never closed\n\n```\nnor is this fence";
  const std::string dir = scratch_path("injection_comment");
  write_study_report(spec, pareto_result(spec, 4, 1), dir);
  const std::string html = read_text(dir + "/report.html");
  EXPECT_EQ(occurrences_of(html, "<table>"), tables) << html.substr(0, 3000);
  EXPECT_NE(html.find("&lt;!-- never closed"), std::string::npos);
  EXPECT_EQ(html.find("<!--"), std::string::npos);
  EXPECT_NE(html.find("<h2>Outcome</h2>"), std::string::npos);
}

// Links in a description: relative, http(s) and mailto survive; every other
// scheme, however written, leaves neither report.md nor report.html.
TEST(ReportInjection, OnlySafeLinksOfADescriptionSurvive) {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.description =
      "[ok](https://example.org) [mail](mailto:a@b.org) [rel](notes.md)\n\n"
      "[a](javascript:alert(1)) [b](JaVaScRiPt:alert(1)) [c](jav&#x61;script:alert(1)) [d](&#106;avascript:x) "
      "[e](<java\tscript:x>) [f](vbscript:x) [g](data:text/html;base64,PHNjcmlwdD4=) ![h](data:image/svg+xml,x) "
      "[i][r]\n\n[r]: javascript:alert(2)\n";
  const std::string dir = scratch_path("injection_links");
  write_study_report(spec, pareto_result(spec, 4, 1), dir);
  for (const char* file : {"/report.md", "/report.html"}) {
    const std::string text = lowercase(read_text(dir + file));
    for (const char* scheme : {"javascript:", "vbscript:", "data:", "&#106;avascript", "jav&#x61;script"}) {
      EXPECT_EQ(text.find(scheme), std::string::npos) << file << " carries " << scheme;
    }
  }
  const std::string html = read_text(dir + "/report.html");
  EXPECT_NE(html.find("<a href=\"https://example.org\">ok</a>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"mailto:a@b.org\">mail</a>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"notes.md\">rel</a>"), std::string::npos);
}

// report.html checks links itself, whatever Markdown it is given.
TEST(ReportInjection, ReportHtmlDropsForbiddenLinksOfAnyMarkdown) {
  const std::string html = report_html(
      "[a](javascript:alert(1)) [b](JAVASCRIPT:x) ![c](vbscript:x) [d](data:text/html,x) [ok](https://x.org) "
      "<javascript:alert(2)>\n",
      "t", {});
  EXPECT_EQ(html.find("href=\"javascript"), std::string::npos) << html;
  EXPECT_EQ(lowercase(html).find("href=\"javascript"), std::string::npos) << html;
  EXPECT_EQ(html.find("vbscript:"), std::string::npos) << html;
  EXPECT_EQ(html.find("data:"), std::string::npos) << html;
  EXPECT_NE(html.find("<a href=\"https://x.org\">ok</a>"), std::string::npos) << html;
  EXPECT_EQ(occurrences_of(html, "<a href"), 1u) << html;
}

// Paths, --set overrides and messages: one code span or one table cell each.
TEST(ReportInjection, PathsOverridesAndMessagesStayOneSpanOrCell) {
  StudySpec spec = base_spec(StudyKind::kOptimize);
  spec.file = "a`b\n# x.yaml";
  spec.problem_overrides = {"k=`v`|\n- y"};
  StudyResult r;
  r.status = study::StudyStatus::kConverged;
  r.best = design(spec, 0.025, 2.0, "start 0");
  r.best->message = "m|n\n| x |";
  r.evaluations = 1;
  const std::string dir = scratch_path("injection_cells");
  write_study_report(spec, r, dir);
  const std::string md = read_text(dir + "/report.md");
  EXPECT_NE(md.find("\n- study file: ``a`b # x.yaml``\n"), std::string::npos) << md;
  EXPECT_NE(md.find("\n- problem override: ``k=`v`| - y``\n"), std::string::npos) << md;
  EXPECT_NE(md.find("\n| message | m\\|n \\| x \\| |\n"), std::string::npos) << md;
  EXPECT_EQ(md.find("\n# x.yaml"), std::string::npos);
  EXPECT_EQ(md.find("\n- y"), std::string::npos);
  const std::string html = read_text(dir + "/report.html");
  EXPECT_NE(html.find("<code>a`b # x.yaml</code>"), std::string::npos) << html.substr(0, 2000);
  EXPECT_NE(html.find("<code>k=`v`| - y</code>"), std::string::npos);
  EXPECT_NE(html.find("<td>m|n | x |</td>"), std::string::npos);
}

// A message that a spreadsheet would run as a formula is written as text.
TEST(ReportInjection, AFormulaInAMessageStaysTextInTheCsv) {
  StudySpec spec = base_spec(StudyKind::kSweep);
  StudyResult r;
  r.status = study::StudyStatus::kOk;
  for (int a = 0; a < 2; ++a) r.sweep_points.push_back(design(spec, 0.02 + 0.003 * a, 1.5, "sweep"));
  r.sweep_points[1].message = "=HYPERLINK(\"http://x\",\"y\")";
  r.best = r.sweep_points[0];
  r.evaluations = 2;
  const std::string dir = scratch_path("injection_csv");
  write_study_report(spec, r, dir);
  const std::string csv = read_text(dir + "/sweep.csv");
  EXPECT_NE(csv.find("\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\""), std::string::npos) << csv;
  EXPECT_EQ(csv.find(",=HYPERLINK"), std::string::npos) << csv;
}

}  // namespace
