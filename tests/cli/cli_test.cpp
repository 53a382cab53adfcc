// The rackopt program end to end: exit codes, files written, --json output.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_process.hpp"
#include "support/scratch_dir.hpp"

namespace {

using rackopt::test_support::CliResult;
using rackopt::test_support::run_cli;
using rackopt::test_support::scratch_path;

TEST(Cli, CheckPrintsGeometryAndSucceeds) {
  const CliResult r = run_cli("check problems/rack_railway.yaml");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("contact ratio"), std::string::npos);
  EXPECT_NE(r.out.find("UNDERCUT"), std::string::npos);  // the rack railway paper's pinion is undercut (docs/models/geometry.md)
}

TEST(Cli, StiffnessJsonIsOneObjectWithTheContractKeys) {
  const std::string dir = scratch_path("json");
  const CliResult r = run_cli("stiffness problems/rack_railway.yaml --json --out " + dir);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);  // throws if not exactly one JSON value
  ASSERT_TRUE(j.is_object());
  for (const char* key : {"contact_ratio", "k_min", "k_max", "k_mean", "k_fluctuation", "zones", "warnings", "timings"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_GT(j["k_min"].get<double>(), 0.0);
  EXPECT_NEAR(j["k_fluctuation"].get<double>(),
              (j["k_max"].get<double>() - j["k_min"].get<double>()) / j["k_mean"].get<double>(),
              1e-8 * j["k_fluctuation"].get<double>());
  EXPECT_TRUE(j["zones"].is_object());
  EXPECT_TRUE(j["warnings"].is_array());
  // The CSV is there, with a header and one row per sample.
  std::ifstream csv(dir + "/stiffness.csv");
  ASSERT_TRUE(csv.good());
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("travel_m,stiffness_N_per_m", 0), 0u);
  long rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, j["samples"].get<long>());
  // No temporary files left behind.
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
}

// Mesh ripple and transmission error in the JSON, the deflection column in
// the CSV (F/K without relief), and a relief given with --set.
TEST(Cli, StiffnessReportsRippleAndTransmissionError) {
  const std::string dir = scratch_path("te");
  const CliResult r = run_cli("stiffness problems/rack_railway.yaml --json --set effects.rack_span=rigid "
                          "--set effects.hertz=linear --set effects.rack_foundation=off "
                          "--set effects.fillet_calibration=off --set effects.pair_coupling=off --out " + dir);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const double F = 50e3;  // load.force of rack_railway.yaml
  EXPECT_NEAR(j["mesh_ripple_max"].get<double>(), j["k_fluctuation"].get<double>(), 1e-6);  // rigid: periodic
  const double pp = j["transmission_error"]["peak_to_peak"].get<double>();
  EXPECT_NEAR(pp, F * (1 / j["k_min"].get<double>() - 1 / j["k_max"].get<double>()), 1e-7 * pp);
  EXPECT_EQ(j["mesh_ripple"].size(), 24u);
  std::ifstream csv(dir + "/stiffness.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_EQ(header.rfind("travel_m,stiffness_N_per_m,rigid_body_stiffness_N_per_m,pairs_in_mesh,"
                         "body_equivalent_compliance_m_per_N,transmission_error_m,pair0_in_mesh", 0), 0u);
  std::istringstream cells(row);
  std::string cell;
  std::vector<double> v;
  while (std::getline(cells, cell, ',') && v.size() < 6) v.push_back(std::stod(cell));
  ASSERT_EQ(v.size(), 6u);
  EXPECT_NEAR(v[5], F / v[1], 1e-8 * v[5]);

  // The relief was sized on the papers' tooth model (constant contact term,
  // clamped rack tooth, Sainsot's foundation): the same model on both sides.
  const CliResult relieved = run_cli("stiffness problems/rack_railway.yaml --json --set effects.rack_span=rigid "
                                 "--set effects.hertz=linear --set effects.rack_foundation=off "
                                 "--set effects.fillet_calibration=off --set effects.pair_coupling=off "
                                 "--set 'pinion.tip_relief.amount=42 um' --set pinion.tip_relief.length=1.72 "
                                 "--set 'pinion.root_relief.amount=42 um' --set pinion.root_relief.length=1.72 --out " +
                                 scratch_path("te_relief"));
  ASSERT_EQ(relieved.code, 0) << relieved.out;
  const auto k = nlohmann::json::parse(relieved.out);
  EXPECT_LT(k["transmission_error"]["peak_to_peak"].get<double>(), 0.25 * pp);  // 22.1 -> 4.1 um
  EXPECT_EQ(run_cli("stiffness problems/rack_railway.yaml --set 'pinion.tip_relief.amount=42 um' --out " +
                scratch_path("te_bad")).code, 2);  // no length
}

TEST(Cli, SetOverridesAKey) {
  const CliResult a = run_cli("stiffness problems/rack_railway.yaml --json --out " + scratch_path("a"));
  const CliResult b = run_cli("stiffness problems/rack_railway.yaml --json --set 'rack.span=1.2 m' --out " + scratch_path("b"));
  ASSERT_EQ(a.code, 0);
  ASSERT_EQ(b.code, 0);
  EXPECT_GT(nlohmann::json::parse(b.out)["k_min"].get<double>(), nlohmann::json::parse(a.out)["k_min"].get<double>());
}

TEST(Cli, BadInputExitsTwoWithLocation) {
  const std::string dir = scratch_path("bad");
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir + "/bad.yaml");
    f << "pinion:\n  teeth: 22\n  module: 31.831 mm\n  modul: 3\n";
  }
  const CliResult r = run_cli("check " + dir + "/bad.yaml", {.merge_stderr = true});
  EXPECT_EQ(r.code, 2);
  const std::string& err = r.out;
  EXPECT_NE(err.find("bad.yaml:4:3"), std::string::npos) << err;
  EXPECT_NE(err.find("pinion.modul"), std::string::npos) << err;
}

TEST(Cli, ImpossibleDesignExitsTwoWithCode) {
  // A 1 mm pinion tip thickness budget: 8 teeth with a large shift is pointed.
  const CliResult r = run_cli("stiffness problems/ship_lift.yaml --json --set pinion.teeth=8 --set pinion.profile_shift=1.0 --out " +
                    scratch_path("pointed"));
  EXPECT_EQ(r.code, 2);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["ok"].get<bool>());
  EXPECT_EQ(j["error"].get<std::string>().rfind("design:", 0), 0u);
}

// --samples has the limit of reliability.samples (kMaxReliabilitySamples), so
// the command line cannot ask for more than a problem file may.
TEST(Cli, SamplesLimitIsTheProblemFilesLimit) {
  const CliResult r = run_cli("wear problems/ship_lift.yaml --samples 1000001", {.merge_stderr = true});
  EXPECT_EQ(r.code, 2);
  const std::string& err = r.out;
  EXPECT_NE(err.find("--samples needs a whole number in 1..1000000"), std::string::npos) << err;
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run_cli("").code, 2);
  EXPECT_EQ(run_cli("frobnicate x.yaml").code, 2);
  EXPECT_EQ(run_cli("stiffness").code, 2);
  EXPECT_EQ(run_cli("stiffness problems/rack_railway.yaml --bogus").code, 2);
  EXPECT_EQ(run_cli("check does/not/exist.yaml").code, 2);
}

}  // namespace

// A usage error names what is wrong in one line; the whole usage text is for a
// command line without a command.
TEST(Cli, UsageErrorIsOneLineUnlessTheCommandIsMissing) {
  auto stderr_of = [](const std::string& args) { return run_cli(args).err; };
  const std::string with_command = stderr_of("check problems/ship_lift.yaml --bogus");
  EXPECT_NE(with_command.find("unknown option --bogus"), std::string::npos) << with_command;
  EXPECT_EQ(with_command.find("usage:"), std::string::npos) << with_command;
  EXPECT_LE(std::count(with_command.begin(), with_command.end(), '\n'), 2) << with_command;
  const std::string without = stderr_of("--bogus");
  EXPECT_NE(without.find("usage:"), std::string::npos) << without;
}
