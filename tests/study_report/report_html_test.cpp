// report.html: report.md rendered by cmark-gfm into one document that needs
// nothing else: its tables, every plot report.md shows inlined as SVG, no
// resource from the network or the folder, the study's own text never
// interpreted as HTML; and a browser (headless Chromium, when installed)
// finds the tables and the plots in the page it builds.
#include "rackopt/study_report/report_html.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rackopt/study_report/study_report.hpp"
#include "report_test_support.hpp"

namespace {

// The image targets of report.md: `![alt](target)`.
std::vector<std::string> markdown_images(const std::string& md) {
  std::vector<std::string> out;
  for (std::size_t at = md.find("!["); at != std::string::npos; at = md.find("![", at + 2)) {
    const std::size_t open = md.find("](", at);
    const std::size_t close = open == std::string::npos ? open : md.find(')', open);
    if (close == std::string::npos) break;
    out.push_back(md.substr(open + 2, close - open - 2));
  }
  return out;
}

// Every value of `attribute="..."` in `html`.
std::vector<std::string> attribute_values(const std::string& html, const std::string& attribute) {
  std::vector<std::string> out;
  const std::string key = " " + attribute + "=\"";
  for (std::size_t at = html.find(key); at != std::string::npos; at = html.find(key, at + key.size())) {
    const std::size_t end = html.find('"', at + key.size());
    if (end == std::string::npos) break;
    out.push_back(html.substr(at + key.size(), end - at - key.size()));
  }
  return out;
}

// A three-objective front: a multiplot Pareto figure and the hypervolume history.
StudySpec three_objective_spec() {
  StudySpec spec = base_spec(StudyKind::kPareto);
  spec.objectives.push_back(objective("supports_per_metre"));
  spec.objectives.push_back(objective("min_stiffness", true));
  return spec;
}

// What every report.html must be, whatever was plotted: a complete HTML
// document with the report's tables, nothing to load, no leftover image.
void expect_self_contained(const std::string& dir) {
  const std::string html = read_text(dir + "/report.html");
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<table>"), std::string::npos);
  EXPECT_NE(html.find("<style>"), std::string::npos);
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_TRUE(attribute_values(html, "src").empty());
  // Hyperlinks only: to places inside the page, or to the folder's files (relative).
  for (const auto& href : attribute_values(html, "href")) {
    if (href.rfind('#', 0) == 0) continue;
    EXPECT_EQ(href.find("://"), std::string::npos) << href;
    EXPECT_TRUE(fs::exists(fs::path(dir) / href)) << "report.html links a missing file: " << href;
  }
  // Each image of report.md is a figure with its SVG (the PNG stays a link in the file list).
  const std::string md = read_text(dir + "/report.md");
  EXPECT_EQ(occurrences_of(html, "<svg"), markdown_images(md).size());
  EXPECT_EQ(occurrences_of(html, "<figure class=\"plot\""), markdown_images(md).size());
}

TEST(ReportHtml, ParetoReportHasItsTablesAndEveryPlotInline) {
  const StudySpec spec = three_objective_spec();
  const StudyResult r = pareto_result(spec, 9, 4);
  const std::string dir = scratch_path("html_pareto");
  const StudyReport rep = write_study_report(spec, r, dir);
  expect_self_contained(dir);
  const auto j = nlohmann::json::parse(rep.summary_json);
  EXPECT_EQ(j["files"]["report_html"], dir + "/report.html");
  const std::string html = read_text(dir + "/report.html");
  EXPECT_NE(html.find("<title>Study: synthetic</title>"), std::string::npos);
  EXPECT_NE(html.find("<td><strong>chosen</strong></td>"), std::string::npos);  // the front's table
  if (!gnuplot_available()) return;
  const std::string md = read_text(dir + "/report.md");
  EXPECT_NE(md.find("](pareto.png)"), std::string::npos);
  EXPECT_NE(md.find("](history.png)"), std::string::npos);
  EXPECT_EQ(occurrences_of(html, "<svg"), 2u);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  EXPECT_NE(html.find("<figcaption>"), std::string::npos);
  // Each plot's ids are its own: the point symbols two plots define alike.
  EXPECT_NE(html.find("id='plot1-gpPt7'"), std::string::npos);
  EXPECT_NE(html.find("id='plot2-gpPt7'"), std::string::npos);
  EXPECT_EQ(html.find("id='gpPt"), std::string::npos);
  EXPECT_EQ(html.find("'#gpPt"), std::string::npos);
  // The SVGs stay next to the PNGs; summary.json lists the PNGs only.
  EXPECT_TRUE(fs::exists(dir + "/pareto.svg"));
  EXPECT_TRUE(fs::exists(dir + "/history.svg"));
  EXPECT_FALSE(j["files"].contains("pareto_svg"));
  for (const auto& w : rep.written) EXPECT_TRUE(fs::exists(w)) << w;
}

TEST(ReportHtml, WithoutGnuplotThePageHasNoPlotsAndSaysWhy) {
  const StudySpec spec = three_objective_spec();
  const StudyResult r = pareto_result(spec, 5, 1);
  const std::string dir = scratch_path("html_nognuplot");
  ::setenv("RACKOPT_GNUPLOT", "/nonexistent/gnuplot-for-rackopt-tests", 1);
  const StudyReport rep = write_study_report(spec, r, dir);
  ::unsetenv("RACKOPT_GNUPLOT");
  expect_self_contained(dir);
  const std::string html = read_text(dir + "/report.html");
  EXPECT_EQ(occurrences_of(html, "<svg"), 0u);
  EXPECT_NE(html.find("/nonexistent/gnuplot-for-rackopt-tests not found"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/pareto.svg"));
}

TEST(ReportHtml, NoReportNoHtml) {
  StudySpec spec = three_objective_spec();
  spec.output.report = false;
  const std::string dir = scratch_path("html_off");
  const StudyReport rep = write_study_report(spec, pareto_result(spec, 5, 1), dir);
  EXPECT_FALSE(fs::exists(dir + "/report.html"));
  EXPECT_FALSE(fs::exists(dir + "/pareto.svg"));
  EXPECT_TRUE(rep.files.get("report_html").empty());
}

// A study's description is the user's text: shown as written, never run,
// and an image in it that points elsewhere becomes a link, not a fetch.
TEST(ReportHtml, TheStudysOwnHtmlIsShownNotInterpreted) {
  const std::string md =
      "# Study: <b>bold</b>\n\nA <script>alert(1)</script> description.\n\n<div onclick=\"x()\">block</div>\n\n"
      "![remote](https://example.com/x.png) and ![local](pareto.png)\n\n| a | b |\n|---|---|\n| 1 & 2 | <i>3</i> |\n";
  const std::string html = report_html(md, "A <title> & more", {});
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_EQ(html.find("<div"), std::string::npos);
  EXPECT_EQ(html.find("<i>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("&lt;div onclick=&quot;x()&quot;&gt;block&lt;/div&gt;"), std::string::npos);
  EXPECT_NE(html.find("<title>A &lt;title&gt; &amp; more</title>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"https://example.com/x.png\">remote</a>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"pareto.png\">local</a>"), std::string::npos);
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_NE(html.find("<td>1 &amp; 2</td>"), std::string::npos);
  EXPECT_NE(html.find("Content-Security-Policy"), std::string::npos);
}

TEST(ReportHtml, AnImageWithItsSvgBecomesAFigure) {
  const std::string html = report_html("## Plots\n\n![Pareto <front>](pareto.png)\n\n*What to read.*\n",
                                       "t", {{"pareto.png", "<svg viewBox=\"0 0 1560 1120\"><g/></svg>"}});
  EXPECT_NE(html.find("<figure class=\"plot\" style=\"max-width: 1560px\">\n<svg viewBox=\"0 0 1560 1120\"><g/></svg>\n"
                      "<figcaption>Pareto &lt;front&gt;</figcaption>\n</figure>"),
            std::string::npos)
      << html;
  EXPECT_EQ(html.find("<p><figure"), std::string::npos);  // a figure cannot sit inside a paragraph
  EXPECT_NE(html.find("<p><em>What to read.</em></p>"), std::string::npos);
  EXPECT_EQ(html.rfind("</html>\n"), html.size() - 8);
}

TEST(InlineSvg, DropsThePrologScalesAndPrefixesIds) {
  const std::string file =
      "<?xml version=\"1.0\" encoding=\"utf-8\"  standalone=\"no\"?>\n<!DOCTYPE svg>\n<svg \n width=\"600\" "
      "height=\"400\"\n viewBox=\"0 0 600 400\"\n xmlns=\"http://www.w3.org/2000/svg\">\n<defs><path id='gpPt0' "
      "d='M0,0'/><use xlink:href='#gpPt0' id='gpPt1'/></defs>\n<rect width=\"600\" height=\"400\" "
      "fill=\"url(#grad)\"/>\n<text>id='gpPt0' &lt;a&gt; width=\"1\"</text>\n</svg>\n\n";
  const std::string s = inline_svg(file, "p1-");
  EXPECT_EQ(s.rfind("<svg", 0), 0u) << s;
  EXPECT_EQ(s.find("<?xml"), std::string::npos);
  EXPECT_EQ(s.find("DOCTYPE"), std::string::npos);
  EXPECT_EQ(s.find("width=\"600\" \n"), std::string::npos);
  EXPECT_NE(s.find("viewBox=\"0 0 600 400\""), std::string::npos);
  EXPECT_NE(s.find("<rect width=\"600\" height=\"400\""), std::string::npos);  // only the root loses its size
  EXPECT_NE(s.find("<path id='p1-gpPt0'"), std::string::npos);
  EXPECT_NE(s.find("xlink:href='#p1-gpPt0' id='p1-gpPt1'"), std::string::npos);
  EXPECT_NE(s.find("url(#p1-grad)"), std::string::npos);
  EXPECT_NE(s.find("<text>id='gpPt0' &lt;a&gt; width=\"1\"</text>"), std::string::npos);  // text stays text
  EXPECT_EQ(s.substr(s.size() - 6), "</svg>");
  EXPECT_EQ(inline_svg("not an svg <svgx>", "p"), "");
}

// The page as a browser builds it: Chromium's DOM of report.html holds the
// tables and one <svg> per plot. Skipped where Chromium is not installed.
TEST(ReportHtmlInChromium, TheBrowsersDomHoldsTheTablesAndThePlots) {
  const char* env = std::getenv("RACKOPT_CHROMIUM");
  const std::string chromium = env != nullptr && *env != '\0' ? env : "chromium";
  if (std::system(("command -v '" + chromium + "' >/dev/null 2>&1").c_str()) != 0) {
    GTEST_SKIP() << chromium << " not installed (Debian package chromium)";
  }
  const StudySpec spec = three_objective_spec();
  const std::string dir = scratch_path("html_chromium");
  write_study_report(spec, pareto_result(spec, 9, 4), dir);
  const std::string dom = dir + "/dom.html";
  // --no-sandbox: Chromium refuses to run as root (containers) with its sandbox;
  // a profile of its own keeps parallel runs and the user's profile apart.
  const std::string cmd = "timeout 120 '" + chromium +
                          "' --headless --no-sandbox --disable-gpu --user-data-dir='" + dir +
                          "/chromium-profile' --dump-dom 'file://" + fs::absolute(dir).string() +
                          "/report.html' >'" + dom + "' 2>'" + dir + "/chromium.log'";
  const auto t0 = std::chrono::steady_clock::now();
  const int code = std::system(cmd.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "chromium --dump-dom took " << seconds << " s\n";
  ASSERT_EQ(code, 0) << read_text(dir + "/chromium.log");
  const std::string html = read_text(dom);
  EXPECT_NE(html.find("<table>"), std::string::npos);
  if (gnuplot_available()) {
    EXPECT_NE(html.find("<figcaption>"), std::string::npos);
  }
  const std::size_t plots = markdown_images(read_text(dir + "/report.md")).size();
  EXPECT_EQ(occurrences_of(html, "<svg"), plots);
  EXPECT_EQ(occurrences_of(html, "<svg"), gnuplot_available() ? 2u : 0u);
  EXPECT_EQ(html.find("<img"), std::string::npos);
}

}  // namespace
