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
  for (const std::string& script : {wear_profile_gnuplot(name, WearLifeResult{}), life_histogram_gnuplot(name),
                                    reliability_gnuplot(name), stiffness_gnuplot(StiffnessCurve{}, name, "s.csv", "s.png")}) {
    EXPECT_NE(script.find(opening), std::string::npos) << script.substr(0, 400);
    EXPECT_EQ(script.find("paper's"), std::string::npos) << "the raw name, unescaped";
  }
}

// Splits `line` at `separator`, keeping empty cells.
std::vector<std::string> cells_of(const std::string& line, char separator) {
  std::vector<std::string> cells(1);
  for (char ch : line) {
    if (ch == separator) {
      cells.emplace_back();
    } else {
      cells.back() += ch;
    }
  }
  return cells;
}

// The stiffness plot draws from the columns it needs, inline in its script:
// every sample of the CSV is there (none dropped), with the CSV's values in
// the units drawn, and the load-share panel reads each pair slot's own
// load_share column (NaN out of mesh).
TEST(PlotScripts, StiffnessPlotDataHoldsEveryPlottedCsvValue) {
  StiffnessCurve c;
  c.max_pairs = 3;
  for (int i = 0; i < 7; ++i) {
    MeshState s;
    s.travel = 0.001 * i + 1e-7;
    s.stiffness = 2.5e8 + 1.234567e6 * i;
    s.local_stiffness = 1.5e9 - 3.3e5 * i;
    s.approach = 1.7e-5 + 1e-8 * i;
    for (int q = 0; q < 3; ++q) {
      if ((i + q) % 3 == 0) continue;  // each slot leaves the mesh somewhere
      PairState p;
      p.slot = q;
      p.load_share = 0.1 * q + 0.01 * i + 0.123456789;
      s.pairs.push_back(p);
    }
    c.samples.push_back(s);
  }
  std::vector<std::vector<std::string>> csv;
  for (const std::string& line : cells_of(stiffness_csv(c), '\n')) {
    if (!line.empty()) csv.push_back(cells_of(line, ','));
  }
  const std::vector<std::string>& header = csv.front();
  auto csv_column = [&](const std::string& name) {  // 0-based
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::string gp = stiffness_gnuplot(c, "t", "s.csv", "s.png");
  const std::string begin = "$rackopt_stiffness << EOD\n";
  const std::size_t data_at = gp.find(begin);
  ASSERT_NE(data_at, std::string::npos) << gp;
  const std::size_t data_end = gp.find("\nEOD\n", data_at);
  ASSERT_NE(data_end, std::string::npos) << gp;
  std::vector<std::vector<std::string>> block;
  for (const std::string& line : cells_of(gp.substr(data_at + begin.size(), data_end - data_at - begin.size()), '\n')) {
    std::vector<std::string> row;
    for (const std::string& cell : cells_of(line, ' ')) {
      if (!cell.empty()) row.push_back(cell);
    }
    block.push_back(row);
  }
  ASSERT_EQ(block.size() + 1, csv.size());  // every sample, the header aside
  // Datablock column (1-based, as the script's `using` counts) -> CSV column
  // name and the factor the plot scales it by (the CSV's digits parsed, then
  // one multiplication: what gnuplot computed from the CSV).
  struct Plotted {
    int column;
    std::string name;
    double factor;
  };
  std::vector<Plotted> plotted = {{1, "travel_m", 1.0},
                                  {2, "stiffness_N_per_m", 1e-6},
                                  {3, "rigid_body_stiffness_N_per_m", 1e-6},
                                  {4, "transmission_error_m", 1e6}};
  for (int q = 0; q < 3; ++q) {
    plotted.push_back({5 + q, "pair" + std::to_string(q) + "_load_share", 1.0});
    const std::string expected =
        "using 1:" + std::to_string(5 + q) + " with lines title 'pair slot " + std::to_string(q) + "'";
    EXPECT_NE(gp.find(expected), std::string::npos) << expected << "\n" << gp;
  }
  EXPECT_NE(gp.find("using 1:2 with lines lw 2 title 'coupled mesh'"), std::string::npos);
  EXPECT_NE(gp.find("using 1:3 with lines dt 2 title 'rigid rack body'"), std::string::npos);
  EXPECT_NE(gp.find("using 1:4 with lines lw 2 title 'mesh deflection under load'"), std::string::npos);
  // No expression per point: gnuplot's per-evaluation signal calls made
  // those the plot's largest cost (docs/performance.md).
  EXPECT_EQ(gp.find("using 1:($"), std::string::npos) << gp;
  for (std::size_t r = 0; r < block.size(); ++r) {
    ASSERT_EQ(block[r].size(), 7u) << "row " << r;
    for (const Plotted& p : plotted) {
      const std::string& in_csv = csv[r + 1][csv_column(p.name)];
      const std::string& in_block = block[r][static_cast<std::size_t>(p.column - 1)];
      if (p.name.find("_load_share") != std::string::npos && in_csv.empty()) {
        EXPECT_EQ(in_block, "NaN") << "row " << r << " " << p.name;  // not in mesh: a gap in the line
      } else if (p.factor == 1.0) {
        EXPECT_EQ(in_block, in_csv) << "row " << r << " " << p.name;
      } else {
        const double from_csv = std::stod(in_csv);
        const double expected = p.factor < 1 ? from_csv / (1 / p.factor) : from_csv * p.factor;
        EXPECT_EQ(std::stod(in_block), expected) << "row " << r << " " << p.name << " " << in_block;
      }
    }
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
      {"wear_profile.gp", wear_profile_gnuplot(title, WearLifeResult{})},
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
