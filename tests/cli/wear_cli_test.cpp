// `rackopt wear` end to end, and the seed 004 validation of issue 3: the
// shipped ship_lift problem reproduces the paper's reliability table
// (physics.md 12.2) within 0.05 and its 1000 lives pass the gamma fit at 5 %.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace {

struct CliResult {
  int code = -1;
  std::string out;
};

CliResult run(const std::string& args) {
  const std::string cmd = std::string("cd '") + RACKOPT_SOURCE_DIR + "' && '" + RACKOPT_CLI + "' " + args +
                          " 2>/dev/null";
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string tmp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("rackopt_wear_cli_test_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

// Seed 004's reliability table (physics.md 12.2). The 40-year row is not in
// the +-0.05 requirement (it is inconsistent with any fitted distribution);
// it is checked loosely below.
const std::map<double, double> kSeed004R{{55, 0.9743}, {60, 0.7949}, {65, 0.4054}, {75, 0.0135}};

TEST(WearCli, Seed004ShipLiftReproducesThePapersReliabilityTable) {
  const std::string dir = tmp_dir("seed004");
  const CliResult r = run("wear problems/ship_lift.yaml --json --out " + dir);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"life_cycles", "life_years", "life_at_R", "reliability", "fit", "timings"}) {
    ASSERT_TRUE(j.contains(key)) << key;
  }
  EXPECT_GT(j["life_cycles"].get<double>(), 0.0);
  EXPECT_NEAR(j["life_years"].get<double>(), j["life_cycles"].get<double>() / 1.0e4, 1e-6 * j["life_years"].get<double>());

  // R at every time of reliability.times (40, 55, 60, 65, 75 yr), from the
  // fitted distribution and from the exact quantile map.
  ASSERT_EQ(j["reliability"].size(), 5u);
  std::map<double, double> fit, exact, empirical;
  for (const auto& e : j["reliability"]) {
    fit[e["t_years"].get<double>()] = e["R"].get<double>();
    empirical[e["t_years"].get<double>()] = e["R_empirical"].get<double>();
  }
  for (const auto& e : j["exact"]["reliability"]) exact[e["t_years"].get<double>()] = e["R"].get<double>();
  for (const auto& [t, R] : kSeed004R) {
    ASSERT_TRUE(fit.count(t)) << t;
    EXPECT_NEAR(fit[t], R, 0.05) << "fitted R at " << t << " yr";
    EXPECT_NEAR(empirical[t], R, 0.05) << "empirical R at " << t << " yr";
    EXPECT_NEAR(exact[t], R, 0.05) << "exact R at " << t << " yr";
  }
  // 40 yr: the paper's 0.9992; ours is lowered by the ~1 % of samples drawn
  // above the largest possible contact ratio (problem file comment).
  EXPECT_NEAR(fit[40], 0.9992, 0.02);

  // The 1000 lives pass the gamma fit at 5 % (KS with bootstrap critical
  // value), and Weibull is the worst fit, as in the paper.
  bool gamma_seen = false;
  double weibull_ks = 0, gamma_ks = 1;
  for (const auto& c : j["candidates"]) {
    if (c["family"] == "gamma") {
      gamma_seen = true;
      EXPECT_TRUE(c["accepted"].get<bool>()) << c.dump();
      EXPECT_LT(c["ks_statistic"].get<double>(), c["ks_critical"].get<double>());
      gamma_ks = c["ks_statistic"].get<double>();
    }
    if (c["family"] == "weibull") weibull_ks = c["ks_statistic"].get<double>();
  }
  EXPECT_TRUE(gamma_seen);
  EXPECT_GT(weibull_ks, gamma_ks);
  // The chosen fit names its parameters and KS statistic.
  EXPECT_TRUE(j["fit"].contains("family"));
  EXPECT_TRUE(j["fit"].contains("ks_statistic"));
  EXPECT_TRUE(j["fit"]["accepted"].get<bool>());
  // life_at_R: one entry per R of the problem, decreasing in R.
  ASSERT_EQ(j["life_at_R"].size(), 3u);
  EXPECT_GT(j["life_at_R"]["0.9"].get<double>(), j["life_at_R"]["0.95"].get<double>());

  // Files: the three CSVs with a header, and no temporary files left behind.
  for (const char* f : {"wear_profile.csv", "life_samples.csv", "reliability.csv"}) {
    std::ifstream in(dir + "/" + f);
    ASSERT_TRUE(in.good()) << f;
    std::string header;
    std::getline(in, header);
    EXPECT_FALSE(header.empty()) << f;
  }
  long rows = -1;
  {
    std::ifstream in(dir + "/life_samples.csv");
    std::string line;
    while (std::getline(in, line)) ++rows;
  }
  EXPECT_EQ(rows, 1000);
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
}

TEST(WearCli, SamplesAndSeedOptionsAreReproducible) {
  const CliResult a = run("wear problems/ship_lift.yaml --json --samples 50 --seed 7 --threads 1 --out " + tmp_dir("a"));
  const CliResult b = run("wear problems/ship_lift.yaml --json --samples 50 --seed 7 --threads 2 --out " + tmp_dir("b"));
  ASSERT_EQ(a.code, 0);
  ASSERT_EQ(b.code, 0);
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(ja["reliability"], jb["reliability"]);
  EXPECT_EQ(ja["life_at_R"], jb["life_at_R"]);
  EXPECT_EQ(ja["seed"].get<long>(), 7);  // the seed in effect, not the problem's
  EXPECT_EQ(ja["samples"].get<long>(), 50);
  const CliResult c = run("wear problems/ship_lift.yaml --json --samples 50 --seed 8 --out " + tmp_dir("c"));
  ASSERT_EQ(c.code, 0);
  EXPECT_NE(ja["reliability"], nlohmann::json::parse(c.out)["reliability"]);
}

TEST(WearCli, ProblemWithoutWearIsBadInput) {
  const CliResult r = run("wear problems/rack_railway.yaml --out " + tmp_dir("nowear"));
  EXPECT_EQ(r.code, 2);
}

TEST(WearCli, ContactRatioSampledBelowOneFailsThoseSamplesOnly) {
  // Mean 1.0: about half the samples start below 1 and fail at once; the
  // run still completes and reports them.
  const CliResult r = run("wear problems/ship_lift.yaml --json --samples 200 --set 'reliability.random[0].mean=1.05' "
                          "--set 'reliability.random[0].sd=0.1' --out " + tmp_dir("below1"));
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["immediate_failures"].get<long>(), 50);
  EXPECT_EQ(j["failed_evaluations"].get<long>(), 0);
}

}  // namespace
