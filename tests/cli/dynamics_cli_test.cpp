// `rackopt dynamics` end to end (docs/cli.md, docs/output.md): the JSON it
// promises, the files, the sweep on request, the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_process.hpp"
#include "support/scratch_dir.hpp"

namespace {

using rackopt::test_support::CliResult;
using rackopt::test_support::run_cli;
using rackopt::test_support::scratch_path;

TEST(DynamicsCli, ResponseAtTheOperatingSpeedWithItsFiles) {
  const std::string dir = scratch_path("dynamics_gantry");
  const CliResult r = run_cli("dynamics problems/gantry_axis.yaml --json --out " + dir);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["ok"].get<bool>());
  const auto f = j["natural_frequencies_hz"];
  ASSERT_EQ(f.size(), 2u);  // the gantry has a drive spring
  EXPECT_LT(f[0].get<double>(), f[1].get<double>());
  EXPECT_TRUE(j["kv_curve"].empty()) << "no sweep unless asked";
  const auto& d = j["dynamics"];
  EXPECT_DOUBLE_EQ(j["kv_max"].get<double>(), d["response"]["kv"].get<double>());
  EXPECT_GE(j["kv_max"].get<double>(), 1.0);
  EXPECT_NEAR(d["response"]["mesh_force_max_N"].get<double>() / j["static_mesh_force_N"].get<double>(),
              j["kv_max"].get<double>(), 1e-12);
  EXPECT_DOUBLE_EQ(d["response"]["speed_m_per_s"].get<double>(), 2.0);  // load.speed
  for (const char* file : {"dynamics.json", "dynamics_response.csv", "dynamics_spectrum.csv", "dynamics_campbell.csv",
                           "dynamics.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + file)) << file;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/dynamics_sweep.csv"));
}

TEST(DynamicsCli, SweepsTheSpeedRangeWhenAsked) {
  const std::string dir = scratch_path("dynamics_sweep");
  const CliResult r = run_cli(
      "dynamics problems/gantry_axis.yaml --sweep --speed '1.5 m/s' --json --out " + dir +
      " --set 'dynamics.speed_range.from=90 m/min' --set 'dynamics.speed_range.to=2.1 m/s' "
      "--set dynamics.speed_range.points=3");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& c = j["kv_curve"];
  ASSERT_EQ(c.size(), 3u);
  EXPECT_DOUBLE_EQ(c[0]["speed_m_per_s"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(c[2]["speed_m_per_s"].get<double>(), 2.1);
  double kv_max = 0;
  for (const auto& p : c) kv_max = std::max(kv_max, p["kv"].get<double>());
  EXPECT_DOUBLE_EQ(j["kv_max"].get<double>(), kv_max);
  // --speed sets the response's speed: the first point of the sweep.
  EXPECT_NEAR(j["dynamics"]["response"]["kv"].get<double>(), c[0]["kv"].get<double>(), 1e-5 * kv_max);
  EXPECT_TRUE(std::filesystem::exists(dir + "/dynamics_sweep.csv"));
}

TEST(DynamicsCli, RefusesWhatItCannotRun) {
  // The paper's problem has no dynamics section.
  const CliResult no_mass = run_cli("dynamics problems/rack_railway_paper.yaml --json --out " +
                                    scratch_path("dynamics_paper"));
  EXPECT_EQ(no_mass.code, 2) << no_mass.out;
  EXPECT_NE(no_mass.out.find("dynamics.moving_mass"), std::string::npos) << no_mass.out;
  const CliResult bad_speed = run_cli("dynamics problems/gantry_axis.yaml --speed -1 --json");
  EXPECT_EQ(bad_speed.code, 2) << bad_speed.out;
  const CliResult bad_unit = run_cli("dynamics problems/gantry_axis.yaml --speed '3 kg' --json");
  EXPECT_EQ(bad_unit.code, 2) << bad_unit.out;
}

}  // namespace
