// What a run costs beyond its computation (docs/performance.md, "Program
// start and plots"): which libraries a program start loads, how many gnuplot
// processes a study's plots take, and which files a study computes at all.
// The times themselves are measured in docs/performance.md, not here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_process.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using rackopt::test_support::CliResult;
using rackopt::test_support::read_text;
using rackopt::test_support::run_cli;
using rackopt::test_support::scratch_dir;

// The shipped gantry study with pagmo's GACO and one generation: a small
// run of a pagmo algorithm.
const std::string kPagmoRun =
    "run studies/gantry_sizing.yaml --set solver.library=pagmo --set solver.algorithm=gaco "
    "--set solver.max_evaluations=40 --set output.plots=off --set output.report=off";

TEST(ProgramStart, VersionLoadsNeitherPagmoNorItsModule) {
  // LD_DEBUG=files: the dynamic linker names every object it opens on stderr.
  const CliResult r = run_cli("--version", {.env = "LD_DEBUG=files"});
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_NE(r.err.find("libstdc++"), std::string::npos) << "LD_DEBUG gave no list of libraries:\n" << r.err;
  EXPECT_EQ(r.err.find("pagmo"), std::string::npos) << r.err;
}

TEST(ProgramStart, APagmoAlgorithmOpensThePagmoModule) {
  const std::string dir = scratch_dir("pagmo_module_opened");
  const CliResult r = run_cli(kPagmoRun + " --out " + dir + "/out", {.env = "LD_DEBUG=files"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("librackopt_pagmo.so"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("libpagmo.so"), std::string::npos) << r.err;
}

TEST(ProgramStart, AMissingPagmoModuleIsAnErrorThatSaysWhereItLooked) {
  const std::string dir = scratch_dir("pagmo_module_missing");
  const std::string missing = dir + "/no_such_librackopt_pagmo.so";
  const CliResult r = run_cli(kPagmoRun + " --out " + dir + "/out", {.env = "RACKOPT_PAGMO_MODULE='" + missing + "'"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("pagmo module"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("RACKOPT_PAGMO_MODULE"), std::string::npos) << r.err;
}

// Every plot of a study's folder, PNG and SVG, from one gnuplot process
// (PlotBatch): gnuplot's start is paid once per folder.
TEST(StudyPlots, OneGnuplotRunDrawsEveryPlotsPngAndSvg) {
  const std::string dir = scratch_dir("one_gnuplot_per_plot");
  // A gnuplot that notes each start, then is the real one.
  const std::string gp = dir + "/gnuplot_counting.sh";
  {
    std::ofstream f(gp);
    f << "#!/bin/sh\necho run >> '" << dir << "/gnuplot_runs'\nexec gnuplot \"$@\"\n";
  }
  fs::permissions(gp, fs::perms::owner_all);
  const CliResult r =
      run_cli("run studies/rack_railway_sizing.yaml --out " + dir + "/out", {.env = "RACKOPT_GNUPLOT='" + gp + "'"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::size_t pngs = 0;
  for (const auto& e : fs::directory_iterator(dir + "/out")) {
    if (e.path().extension() != ".png") continue;
    ++pngs;
    EXPECT_TRUE(fs::exists(fs::path(e.path()).replace_extension(".svg"))) << e.path();
  }
  ASSERT_GE(pngs, 2u);
  const std::string runs = read_text(dir + "/gnuplot_runs");
  EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 1);
  EXPECT_NE(read_text(dir + "/out/report.html").find("<svg"), std::string::npos);
}

// An evaluate study of the gantry drive that reports `report_metric` (no
// other metric of it reads the stiffness curve).
std::string gantry_evaluation(const std::string& dir, const std::string& report_metric) {
  const std::string path = dir + "/" + report_metric + ".yaml";
  std::ofstream f(path);
  f << "study: {name: no stiffness metric, kind: evaluate}\n"
       "problem: "
    << RACKOPT_SOURCE_DIR
    << "/problems/gantry_axis.yaml\n"
       "objectives: [pinion_mass]\n"
       "constraints: [{metric: contact_ratio, min: 1.2}]\n"
       "report: ["
    << report_metric
    << "]\n"
       "output: {plots: on, report: on}\n";
  return path;
}

TEST(StudyStiffnessCurve, AStudyWithoutStiffnessMetricsWritesNoCurveUnlessItsOutputAsks) {
  const std::string dir = scratch_dir("no_stiffness_metric");
  const std::string study = gantry_evaluation(dir, "root_bending_safety");
  const CliResult plain = run_cli("run '" + study + "' --out " + dir + "/plain");
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_TRUE(fs::exists(dir + "/plain/summary.json"));
  EXPECT_FALSE(fs::exists(dir + "/plain/stiffness.csv"));
  EXPECT_FALSE(fs::exists(dir + "/plain/stiffness.png"));

  const CliResult asked = run_cli("run '" + study + "' --set output.stiffness_curve=on --out " + dir + "/asked");
  ASSERT_EQ(asked.code, 0) << asked.err;
  EXPECT_TRUE(fs::exists(dir + "/asked/stiffness.csv"));
  EXPECT_TRUE(fs::exists(dir + "/asked/stiffness.png"));

  // A stiffness metric brings the curve without being asked.
  const CliResult metric = run_cli("run '" + gantry_evaluation(dir, "min_stiffness") + "' --out " + dir + "/metric");
  ASSERT_EQ(metric.code, 0) << metric.err;
  EXPECT_TRUE(fs::exists(dir + "/metric/stiffness.csv"));
}

}  // namespace
