// Plot scripts carry user text (problem and study names) inside gnuplot
// strings: a name with an apostrophe must stay one string. Drawing them is
// covered end to end by the CLI tests (the shipped rack railway's name has
// an apostrophe).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rackopt/output/file_check.hpp"
#include "rackopt/output/plot.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/output/wear_report.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt {
namespace {

TEST(PlotScripts, GnuplotQuoteDoublesTheQuote) {
  EXPECT_EQ(gnuplot_quote("plain"), "'plain'");
  EXPECT_EQ(gnuplot_quote("the paper's drive"), "'the paper''s drive'");
  EXPECT_EQ(gnuplot_quote("''"), "''''''");
  EXPECT_EQ(gnuplot_quote(""), "''");
}

TEST(PlotScripts, TitlesWithAnApostropheStayOneString) {
  const std::string name = "Mountain rack railway (the paper's drive)";
  // The scripts may add to the title: the quoted name without its closing quote.
  const std::string quoted = gnuplot_quote(name);
  const std::string opening = quoted.substr(0, quoted.size() - 1);
  for (const std::string& script : {wear_profile_gnuplot(name), life_histogram_gnuplot(name),
                                    reliability_gnuplot(name), stiffness_gnuplot(StiffnessCurve{}, name, "s.csv", "s.png")}) {
    EXPECT_NE(script.find(opening), std::string::npos) << script.substr(0, 400);
    EXPECT_EQ(script.find("paper's"), std::string::npos) << "the raw name, unescaped";
  }
}

// The load-share panel reads each pair slot's in_mesh and load_share
// columns of the CSV written beside it: the script's column numbers must be
// those of the CSV's header, for every slot.
TEST(PlotScripts, StiffnessPlotReadsEachSlotsOwnColumns) {
  StiffnessCurve c;
  c.max_pairs = 3;
  const std::string csv = stiffness_csv(c);
  std::vector<std::string> header;
  std::string cell;
  for (char ch : csv.substr(0, csv.find('\n'))) {
    if (ch == ',') {
      header.push_back(cell);
      cell.clear();
    } else {
      cell += ch;
    }
  }
  header.push_back(cell);
  auto column = [&](const std::string& name) {  // 1-based, as gnuplot counts
    return static_cast<int>(std::find(header.begin(), header.end(), name) - header.begin()) + 1;
  };
  const std::string gp = stiffness_gnuplot(c, "t", "s.csv", "s.png");
  for (int q = 0; q < 3; ++q) {
    const std::string slot = "pair" + std::to_string(q);
    const std::string expected = "using 1:($" + std::to_string(column(slot + "_in_mesh")) + ">0 ? $" +
                                 std::to_string(column(slot + "_load_share")) + " : 1/0) with lines title 'pair slot " +
                                 std::to_string(q) + "'";
    EXPECT_NE(gp.find(expected), std::string::npos) << expected << "\n" << gp;
  }
}

// One script, two images: the PNG by default, the same plot as SVG when
// gnuplot runs with rackopt_svg defined (what report.html inlines).
TEST(PlotScripts, OneScriptDrawsThePngAndTheSameSvg) {
  const std::string terminal = gnuplot_terminal("tiny.png.tmp", 400, 300, 13);
  EXPECT_NE(terminal.find("set terminal pngcairo size 400,300 noenhanced font ',13'"), std::string::npos) << terminal;
  EXPECT_NE(terminal.find("set output 'tiny.png.tmp'"), std::string::npos);
  EXPECT_NE(terminal.find("set terminal svg size 400,300 standalone"), std::string::npos);
  EXPECT_NE(terminal.find("set output 'tiny.svg.tmp'"), std::string::npos);
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
  const std::string dir = test_support::scratch_dir("png_and_svg");
  std::ofstream(dir + "/tiny.gp") << terminal << "plot x title 'x'\n";
  std::vector<std::string> warnings;
  const RenderedImages images = render_plot_images(dir, "tiny.gp", "tiny.png", "tiny.svg", warnings);
  const std::string png = images.png, svg = images.svg;
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(png, dir + "/tiny.png");
  EXPECT_EQ(svg, dir + "/tiny.svg");
  EXPECT_EQ(check_output_file(png, "tiny.png"), "");
  EXPECT_EQ(check_output_file(svg, "tiny.svg"), "");
  const std::string text = test_support::read_text(svg);
  EXPECT_NE(text.find("viewBox=\"0 0 400 300\""), std::string::npos);
  EXPECT_EQ(text.find("<script"), std::string::npos);  // standalone: no mousing code
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
}

// gnuplot_quote is the one way text enters a script: no text can leave the
// string or its line.
TEST(PlotScripts, GnuplotQuoteKeepsEveryTextOneStringOnItsLine) {
  EXPECT_EQ(gnuplot_quote("a\nsystem(\"id\")"), "'a system(\"id\")'");
  EXPECT_EQ(gnuplot_quote("cr\rlf\ntab\tvt\vff\fesc\x1b" "del\x7f" "nul"), "'cr lf tab vt ff esc del nul'");
  EXPECT_EQ(gnuplot_quote(std::string("a\0b", 3)), "'a b'");
  EXPECT_EQ(gnuplot_quote("`id` @m \\"), "'`id` @m \\'");  // inert inside single quotes (next test)
}

// Every script a run writes, with a title that tries each way to run a
// command: a line break, CR, backquotes, an @macro. gnuplot (when
// installed) runs each script in a scratch folder; no command may run.
TEST(PlotScripts, NoTitleRunsACommandInAnyScript) {
  const std::string dir = test_support::scratch_dir("hostile_titles");
  const std::string title = "drive\nsystem('touch owned_nl')\rsystem('touch owned_cr')\n`touch owned_bq` @m it's";
  const std::vector<std::pair<std::string, std::string>> scripts = {
      {"wear_profile.gp", wear_profile_gnuplot(title)},
      {"life_histogram.gp", life_histogram_gnuplot(title)},
      {"reliability.gp", reliability_gnuplot(title)},
      {"stiffness.gp", stiffness_gnuplot(StiffnessCurve{}, title, "s\nsystem('touch owned_csv').csv", "s.png.tmp")}};
  for (const auto& [name, script] : scripts) {
    for (std::size_t at = script.find('\n'); at != std::string::npos; at = script.find('\n', at + 1)) {
      EXPECT_NE(script.compare(at + 1, 6, "system"), 0) << name << ": a line starts a command\n" << script;
    }
    EXPECT_EQ(script.find('\r'), std::string::npos) << name;
    std::ofstream(dir + "/" + name) << "m = \"system('touch owned_macro')\"\n" << script;
  }
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot is not installed";
  for (const auto& [name, script] : scripts) {
    // the data files are missing: gnuplot stops at the first plot, after the titles
    const std::string command = "cd '" + dir + "' && gnuplot " + name + " >/dev/null 2>&1";
    EXPECT_GE(std::system(command.c_str()), 0);
  }
  for (const char* owned : {"owned_nl", "owned_cr", "owned_bq", "owned_macro", "owned_csv"}) {
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + owned)) << owned << ": gnuplot ran a command from a title";
  }
}

}  // namespace
}  // namespace rackopt
