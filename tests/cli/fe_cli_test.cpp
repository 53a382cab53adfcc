// `rackopt fe`: usage errors, a missing solver, an impossible design (each
// before any file is made), and one real run at the coarsest level.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/cli_process.hpp"
#include "support/scratch_dir.hpp"

namespace {

using rackopt::test_support::CliResult;
using rackopt::test_support::run_cli;
using rackopt::test_support::scratch_path;
using rackopt::test_support::scratch_root;

TEST(FeCli, BadPositionsLevelAndUnknownOptionsAreUsageErrors) {
  const std::string dir = scratch_path("usage");
  struct Case {
    const char* args;
    const char* says;
  };
  for (const Case& c : {Case{"--positions 0", "--positions needs a whole number in 1..64, got '0'"},
                        Case{"--positions 65", "in 1..64, got '65'"}, Case{"--positions two", "got 'two'"},
                        Case{"--level 7", "--level needs a whole number in 0..6, got '7'"},
                        Case{"--level -1", "got '-1'"}, Case{"--samples 10", "option --samples does not apply to 'fe'"},
                        Case{"--frobnicate", "unknown option --frobnicate"}}) {
    const CliResult r = run_cli(std::string("fe problems/gantry_axis.yaml --out ") + dir + " " + c.args, {.merge_stderr = true});
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.says), std::string::npos) << c.args << "\n" << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir));
  // --positions belongs to fe only.
  const CliResult s = run_cli("stiffness problems/gantry_axis.yaml --positions 3", {.merge_stderr = true});
  EXPECT_EQ(s.code, 2);
  EXPECT_NE(s.out.find("does not apply to 'stiffness'"), std::string::npos) << s.out;
  // With --json a usage error is one JSON object too.
  const CliResult j = run_cli("fe problems/gantry_axis.yaml --level 9 --json");
  EXPECT_EQ(j.code, 2);
  const auto o = nlohmann::json::parse(j.out);
  EXPECT_EQ(o["error"], "usage");
}

TEST(FeCli, AMissingCcxIsExitOneNamingThePackageAndLeavesNoFiles) {
  const std::string dir = scratch_path("no_ccx");
  const CliResult r = run_cli("fe problems/gantry_axis.yaml --positions 2 --out " + dir, {.env = "RACKOPT_CCX=/nonexistent", .merge_stderr = true});
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("calculix-ccx"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir));
  const CliResult j = run_cli("fe problems/gantry_axis.yaml --json --out " + dir, {.env = "RACKOPT_CCX=/nonexistent"});
  EXPECT_EQ(j.code, 1);
  const auto o = nlohmann::json::parse(j.out);
  EXPECT_EQ(o["ok"], false);
  EXPECT_EQ(o["error"], "ccx_not_found");
  EXPECT_NE(o["message"].get<std::string>().find("calculix-ccx"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(FeCli, AMissingGmshIsExitOneNamingThePackageAndLeavesNoFiles) {
  const std::string dir = scratch_path("no_gmsh");
  const CliResult j = run_cli("fe problems/gantry_axis.yaml --json --out " + dir, {.env = "RACKOPT_GMSH_LIBRARY=/nonexistent/libgmsh.so"});
  EXPECT_EQ(j.code, 1) << j.out;
  const auto o = nlohmann::json::parse(j.out);
  EXPECT_EQ(o["error"], "gmsh_not_found");
  EXPECT_NE(o["message"].get<std::string>().find("libgmsh-dev"), std::string::npos) << o["message"];
  EXPECT_NE(o["message"].get<std::string>().find("/nonexistent/libgmsh.so"), std::string::npos) << o["message"];
  EXPECT_FALSE(std::filesystem::exists(dir));
  // Commands that do not mesh never open Gmsh, so they do not miss it.
  const CliResult s = run_cli("stiffness problems/gantry_axis.yaml --json --out " + dir + "_stiffness", {.env = "RACKOPT_GMSH_LIBRARY=/nonexistent/libgmsh.so"});
  EXPECT_EQ(s.code, 0) << s.out;
}

TEST(FeCli, AnImpossibleDesignIsReportedAsTheOtherCommandsDoBeforeAnyFeWork) {
  const std::string dir = scratch_path("design");
  // Even with no solver: the design is refused first.
  const CliResult r = run_cli("fe problems/gantry_axis.yaml --set pinion.addendum=3 --json --out " + dir, {.env = "RACKOPT_CCX=/nonexistent"});
  EXPECT_EQ(r.code, 2) << r.out;
  const auto o = nlohmann::json::parse(r.out);
  EXPECT_EQ(o["error"], "design:pointed_tooth");
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(FeCli, AStudyAskingForFeVerificationWithoutCcxIsRefusedBeforeItRuns) {
  const std::string dir = scratch_path("study_no_ccx");
  std::filesystem::create_directories(scratch_root());
  const std::string study = (scratch_root() / "verify_study.yaml").string();
  std::ofstream(study) << "study: {name: verified, kind: evaluate}\n"
                       << "problem: " << RACKOPT_SOURCE_DIR << "/problems/gantry_axis.yaml\n"
                       << "report: [contact_ratio]\n"
                       << "verify: {method: fe, positions: 2}\n";
  const CliResult r = run_cli("run " + study + " --out " + dir, {.env = "RACKOPT_CCX=/nonexistent", .merge_stderr = true});
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("calculix-ccx"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir));
  // A bad verify key is bad input at its line and column.
  std::ofstream(study) << "study: {name: verified, kind: evaluate}\n"
                       << "problem: " << RACKOPT_SOURCE_DIR << "/problems/gantry_axis.yaml\n"
                       << "verify: {method: fe, level: 9}\n";
  const CliResult b = run_cli("run " + study + " --out " + dir, {.merge_stderr = true});
  EXPECT_EQ(b.code, 2) << b.out;
  EXPECT_NE(b.out.find("verify_study.yaml:3:29"), std::string::npos) << b.out;
  EXPECT_NE(b.out.find("verify.level"), std::string::npos) << b.out;
}

// The real solves, at the coarsest level on the smallest shipped drive, one
// position (each costs about 25 s of CPU), with the pictures: the files are there and whole, K of both
// codes is positive, the errors are what the numbers in the files say, and
// nothing is left behind (no solve folder either).
TEST(FeCli, RealSolvesOnTheGantryDriveAtLevelZero) {
  const std::string dir = scratch_path("real");
  const std::string work = scratch_path("real_work");
  std::filesystem::create_directories(work);
  const CliResult r = run_cli("fe problems/gantry_axis.yaml --positions 1 --level 0 --threads 2 --pictures --json --out " +
                              dir, {.env = "TMPDIR=" + work});
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(std::filesystem::is_empty(work));
  const auto j = nlohmann::json::parse(r.out);
  std::ifstream in(dir + "/fe.json");
  std::stringstream file;
  file << in.rdbuf();
  EXPECT_EQ(nlohmann::json::parse(file.str()), j);
  ASSERT_EQ(j["positions"].size(), 1u);
  for (const auto& p : j["positions"]) {
    const double fe = p["k_fe"].get<double>(), an = p["k_analytic"].get<double>();
    EXPECT_GT(fe, 0);
    EXPECT_GT(an, 0);
    EXPECT_NEAR(p["k_error"].get<double>(), (an - fe) / fe, 1e-12 * std::abs((an - fe) / fe) + 1e-15);
    ASSERT_FALSE(p["pairs"].empty());
    double shares = 0;
    for (const auto& q : p["pairs"]) {
      EXPECT_GT(q["pinion_fe"].get<double>(), 0);
      EXPECT_GT(q["rack_fe"].get<double>(), 0);
      shares += q["share_fe"].get<double>();
    }
    EXPECT_NEAR(shares, 1.0, 0.02);  // no extended contact asked for
  }
  EXPECT_GT(j["summary"]["time_ratio"].get<double>(), 1.0);
  std::ifstream csv(dir + "/fe.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("travel_m,k_fe_N_per_m,k_analytic_N_per_m,k_error,", 0), 0u);
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 1);
  EXPECT_TRUE(std::filesystem::exists(dir + "/fe_stiffness.gp"));
  // The pictures of the first position: listed, valid PNGs (signature and
  // IEND chunk), the magnification written in the JSON.
  EXPECT_EQ(j["pictures"]["travel"].get<double>(), j["positions"][0]["travel"].get<double>());
  EXPECT_GT(j["pictures"]["displacement_scale"].get<double>(), 1.0);
  EXPECT_GT(j["pictures"]["largest_displacement"].get<double>(), 0.0);
  for (const char* key : {"mesh_png", "deformed_png"}) {
    ASSERT_TRUE(j["files"][key].is_string()) << key;
    const std::string png = j["files"][key].get<std::string>();
    std::ifstream f(png, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 20u) << png;
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << png;
    EXPECT_EQ(bytes.substr(bytes.size() - 8, 4), "IEND") << png;
  }
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
}

// A solve that fails: exit 1 with the solver's own message and the kept
// deck, no result file.
TEST(FeCli, AFailingSolverIsExitOneWithItsMessageAndTheKeptDeck) {
  const std::string dir = scratch_path("ccx_fails");
  std::filesystem::create_directories(scratch_root());
  const std::string fake = (scratch_root() / "fake_ccx").string();
  std::ofstream(fake) << "#!/bin/sh\necho ' *ERROR in fake_ccx: the matrix is singular'\nexit 201\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const std::string work = (scratch_root() / "ccx_work").string();
  std::filesystem::create_directories(work);
  const CliResult r = run_cli("fe problems/gantry_axis.yaml --positions 1 --threads 1 --json --out " + dir, {.env = "RACKOPT_CCX=" + fake + " TMPDIR=" + work});
  EXPECT_EQ(r.code, 1) << r.out;
  const auto o = nlohmann::json::parse(r.out);
  EXPECT_EQ(o["error"], "fe_solver");
  const std::string msg = o["message"].get<std::string>();
  EXPECT_NE(msg.find("the matrix is singular"), std::string::npos) << msg;
  EXPECT_NE(msg.find("job.inp"), std::string::npos) << msg;
  for (const char* f : {"fe.csv", "fe.json", "fe_stiffness.png", "fe_stiffness.gp"}) {
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + f)) << f;
  }
}

}  // namespace
