// PlotBatch: several plots from one gnuplot process, each one drawn, checked
// and reported on its own as render_plot_images would draw it alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rackopt/output/file_check.hpp"
#include "rackopt/output/plot_batch.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt {
namespace {

bool have_gnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

// A script drawing `name`.png (and .svg with rackopt_svg) with `body` after the terminal.
void write_script(const std::string& dir, const std::string& name, const std::string& body) {
  std::ofstream(dir + "/" + name + ".gp") << gnuplot_terminal(name + ".png.tmp", 400, 300) << body;
}

bool has_tmp(const std::string& dir) {
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
  }
  return false;
}

TEST(PlotBatch, DrawsEveryPlotAsDrawnAlone) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const std::string dir = test_support::scratch_dir("batch_all");
  const std::string alone = test_support::scratch_dir("batch_alone");
  // The first script leaves settings, a variable and a datablock behind: the
  // second must be drawn as by a fresh gnuplot (`reset session`).
  const std::string first = "set logscale y\nset grid\nleft_over = 3\n$data << EOD\n1 2\n2 4\nEOD\n"
                            "plot $data with lines title 'a'\n";
  const std::string second = "if (exists('left_over')) { set title 'leaked' }\nplot x**2 title 'b'\n";
  for (const std::string& d : {dir, alone}) {
    write_script(d, "one", first);
    write_script(d, "two", second);
  }
  std::vector<std::string> warnings;
  PlotBatch batch(dir);
  const RenderedImages listed1 = draw_or_queue(&batch, dir, "one.gp", "one.png", "one.svg", warnings);
  const RenderedImages listed2 = draw_or_queue(&batch, dir, "two.gp", "two.png", "two.svg", warnings);
  EXPECT_EQ(listed1.png, dir + "/one.png");
  EXPECT_EQ(listed2.svg, dir + "/two.svg");
  EXPECT_FALSE(std::filesystem::exists(dir + "/one.png"));  // queued, not drawn yet
  const std::vector<std::string> missing = batch.render(warnings);
  EXPECT_TRUE(missing.empty()) << missing.front();
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  for (const char* image : {"one.png", "one.svg", "two.png", "two.svg"}) {
    EXPECT_EQ(check_output_file(dir + "/" + image, image), "") << image;
  }
  EXPECT_FALSE(has_tmp(dir));  // no temporary image and no batch log left
  // The PNGs are the ones each script draws alone, byte for byte.
  std::vector<std::string> alone_warnings;
  render_plot_images(alone, "one.gp", "one.png", "one.svg", alone_warnings);
  render_plot_images(alone, "two.gp", "two.png", "two.svg", alone_warnings);
  ASSERT_TRUE(alone_warnings.empty()) << alone_warnings.front();
  for (const char* image : {"one.png", "two.png", "one.svg"}) {
    EXPECT_EQ(test_support::read_text(dir + "/" + image), test_support::read_text(alone + "/" + image)) << image;
  }
  EXPECT_EQ(test_support::read_text(dir + "/two.svg").find("leaked"), std::string::npos);
}

// A script with an error ends gnuplot: the plot is named in a warning (and
// keeps its log), the plots before and after it are drawn all the same.
TEST(PlotBatch, OneFailingPlotIsNamedAndTheOthersAreDrawn) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const std::string dir = test_support::scratch_dir("batch_failing");
  write_script(dir, "first", "plot x title 'first'\n");
  write_script(dir, "broken", "plot x title 'broken'\nthis_is_not_a_command\n");
  write_script(dir, "last", "plot sin(x) title 'last'\n");
  std::vector<std::string> warnings;
  PlotBatch batch(dir);
  for (const std::string name : {"first", "broken", "last"}) {
    draw_or_queue(&batch, dir, name + ".gp", name + ".png", name + ".svg", warnings);
  }
  const std::vector<std::string> missing = batch.render(warnings);
  EXPECT_EQ(missing, (std::vector<std::string>{dir + "/broken.png", dir + "/broken.svg"}));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("plot " + dir + "/broken.png not drawn: gnuplot failed on broken.gp"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find(dir + "/broken.svg"), std::string::npos) << warnings[1];
  EXPECT_TRUE(std::filesystem::exists(dir + "/broken.gp.log"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/broken.png"));
  for (const char* image : {"first.png", "first.svg", "last.png", "last.svg"}) {
    EXPECT_EQ(check_output_file(dir + "/" + image, image), "") << image;
  }
  EXPECT_FALSE(has_tmp(dir));
}

// A missing gnuplot starts nothing: one warning per plot, as unbatched.
TEST(PlotBatch, WithoutGnuplotEachPlotWarns) {
  const std::string dir = test_support::scratch_dir("batch_no_gnuplot");
  write_script(dir, "a", "plot x\n");
  write_script(dir, "b", "plot x\n");
  const char* old = std::getenv("RACKOPT_GNUPLOT");
  const std::string saved = old != nullptr ? old : "";
  ::setenv("RACKOPT_GNUPLOT", "/nonexistent/gnuplot", 1);
  std::vector<std::string> warnings;
  PlotBatch batch(dir);
  draw_or_queue(&batch, dir, "a.gp", "a.png", "", warnings);
  draw_or_queue(&batch, dir, "b.gp", "b.png", "", warnings);
  const std::vector<std::string> missing = batch.render(warnings);
  if (old != nullptr) {
    ::setenv("RACKOPT_GNUPLOT", saved.c_str(), 1);
  } else {
    ::unsetenv("RACKOPT_GNUPLOT");
  }
  EXPECT_EQ(missing, (std::vector<std::string>{dir + "/a.png", dir + "/b.png"}));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("a.gp but no plot"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("b.gp but no plot"), std::string::npos) << warnings[1];
}

}  // namespace
}  // namespace rackopt
