// The file-set writers `rackopt stiffness`, `rackopt wear` and the study
// report share: each writes the files it lists under their roles, the
// scripts only with plots, and a plot gnuplot cannot draw is a warning and
// no listed image.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/output/stiffness_files.hpp"
#include "rackopt/output/wear_files.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt {
namespace {

namespace fs = std::filesystem;

using test_support::scratch_dir;

// Plots are drawn by a program that does not exist: every plot is then a
// warning, whether or not the machine has gnuplot.
class NoGnuplot {
 public:
  NoGnuplot() { ::setenv("RACKOPT_GNUPLOT", "/nonexistent/gnuplot-for-rackopt-tests", 1); }
  ~NoGnuplot() { ::unsetenv("RACKOPT_GNUPLOT"); }
};

std::vector<std::string> roles_of(const WrittenFiles& f) {
  std::vector<std::string> roles;
  for (const auto& [role, path] : f.listed) roles.push_back(role);
  return roles;
}

// A 22-tooth, 10 mm module pinion on a 40 x 60 mm rack bar under 50 kN
// (built here: this folder's tests do not link the problem loader).
Drive small_drive() {
  Drive d;
  d.pinion.teeth = 22;
  d.pinion.module = 0.01;
  d.pinion.pressure_angle = 20 * M_PI / 180;
  d.pinion.bore_radius = 0.05;
  const double w = 0.04, h = 0.06;
  d.rack.body_height = h;
  d.rack.body_width = w;
  d.rack.section.area = w * h;
  d.rack.section.second_moment = w * h * h * h / 12;
  d.rack.section.shear_area = w * h / 1.2;
  d.rack.section.neutral_axis_depth = h / 2;
  d.load.force = 50e3;
  return d;
}

StiffnessCurve small_drive_curve() { return MeshStiffnessModel(small_drive()).curve(); }

// The same drive with Archard wear at constant hardness, a duty, and the
// wear coefficient scattered: a few Monte Carlo lives.
Drive small_wear_drive() {
  Drive d = small_drive();
  d.wear.coefficient = 3e-6;
  d.wear.pinion_hardness.surface = 600 * kPaPerHB;
  d.wear.rack_hardness.surface = 600 * kPaPerHB;
  d.wear.update_profile = false;
  d.duty.rack_meshes_per_year = 4000;
  RandomInput k;
  k.key = "wear.coefficient";
  k.distribution = RandomInput::Distribution::kLognormal;
  k.a = 1.0;  // median factor: the design's own coefficient
  k.b = 0.2;  // sigma of ln
  d.reliability.inputs.push_back(k);
  d.reliability.reliabilities = {0.9};
  d.reliability.times = {1.0e8};
  d.reliability.bootstrap_replicates = 10;
  d.reliability.life_table = false;
  return d;
}

WearReliabilityResult small_wear_result(const Drive& d) {
  WearReliabilityOptions opt = wear_reliability_options(d);
  opt.samples = 30;
  opt.threads = 1;
  return run_wear_reliability(d, opt);
}

TEST(StiffnessFiles, WritesTheTableAndScriptAndListsByRole) {
  const StiffnessCurve curve = small_drive_curve();
  const std::string dir = scratch_dir("stiffness");
  const NoGnuplot no_gnuplot;
  const WrittenFiles f = write_stiffness_files(curve, dir, "small drive");
  EXPECT_EQ(roles_of(f), std::vector<std::string>{"stiffness_csv"});
  EXPECT_EQ(f.path_of("stiffness_csv"), (fs::path(dir) / "stiffness.csv").string());
  EXPECT_EQ(f.path_of("stiffness_png"), "");
  EXPECT_EQ(f.written, (std::vector<std::string>{dir + "/stiffness.csv", dir + "/stiffness.gp"}));
  for (const auto& p : f.written) EXPECT_TRUE(fs::exists(p)) << p;
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("stiffness.gp"), std::string::npos) << f.warnings[0];
  EXPECT_FALSE(fs::exists(dir + "/stiffness.png"));
}

TEST(StiffnessFiles, WithoutPlotsOnlyTheTable) {
  const StiffnessCurve curve = small_drive_curve();
  const std::string dir = scratch_dir("stiffness_no_plots");
  const WrittenFiles f = write_stiffness_files(curve, dir, "small drive", PlotImages::kNone);
  EXPECT_EQ(roles_of(f), std::vector<std::string>{"stiffness_csv"});
  EXPECT_EQ(f.written, std::vector<std::string>{dir + "/stiffness.csv"});
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_FALSE(fs::exists(dir + "/stiffness.gp"));
}

TEST(WearFiles, WritesEveryTableOfAMonteCarloRunUnderItsRole) {
  const Drive d = small_wear_drive();
  const WearReliabilityResult r = small_wear_result(d);
  ASSERT_FALSE(r.lives.empty());
  const std::string dir = scratch_dir("wear");
  const NoGnuplot no_gnuplot;
  const WrittenFiles f = write_wear_files(d, r, dir, "small drive");
  EXPECT_EQ(roles_of(f), (std::vector<std::string>{"wear_profile_csv", "life_samples_csv", "reliability_csv",
                                                   "life_histogram_csv"}));
  for (const auto& p : f.written) EXPECT_TRUE(fs::exists(p)) << p;
  for (const char* script : {"wear_profile.gp", "life_histogram.gp", "reliability.gp"}) {
    EXPECT_TRUE(fs::exists(fs::path(dir) / script)) << script;
  }
  EXPECT_EQ(f.written.size(), 7u);  // four tables, three scripts
  EXPECT_EQ(f.warnings.size(), 3u);  // one per plot not drawn

  // wear_json's file list comes from the same roles.
  const WearFiles wf = wear_files_by_role(f.listed);
  EXPECT_EQ(wf.wear_profile_csv, dir + "/wear_profile.csv");
  EXPECT_EQ(wf.life_samples_csv, dir + "/life_samples.csv");
  EXPECT_EQ(wf.reliability_csv, dir + "/reliability.csv");
  EXPECT_EQ(wf.histogram_csv, dir + "/life_histogram.csv");
  EXPECT_EQ(wf.histogram_png, "");
}

TEST(WearFiles, WithoutRandomInputsOnlyTheProfile) {
  Drive d = small_wear_drive();
  d.reliability.inputs.clear();
  const WearReliabilityResult r = small_wear_result(d);
  const std::string dir = scratch_dir("wear_nominal");
  const WrittenFiles f = write_wear_files(d, r, dir, "small drive", PlotImages::kNone);
  EXPECT_EQ(roles_of(f), std::vector<std::string>{"wear_profile_csv"});
  EXPECT_EQ(f.written, std::vector<std::string>{dir + "/wear_profile.csv"});
  EXPECT_FALSE(fs::exists(dir + "/life_samples.csv"));
  EXPECT_FALSE(fs::exists(dir + "/wear_profile.gp"));
}

}  // namespace
}  // namespace rackopt
