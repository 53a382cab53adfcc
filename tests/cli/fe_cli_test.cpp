// `rackopt fe`: usage errors, a missing solver, an impossible design (each
// before any file is made), and one real run at the coarsest level.
#include <unistd.h>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace {

struct CliResult {
  int code = -1;
  std::string out;  // stdout, then stderr when `with_stderr`
};

CliResult run(const std::string& args, bool with_stderr = false, const std::string& env = "") {
  const std::string cmd = std::string("cd '") + RACKOPT_SOURCE_DIR + "' && " + env + " '" + RACKOPT_CLI + "' " + args +
                          (with_stderr ? " 2>&1" : " 2>/dev/null");
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

std::filesystem::path tmp_root() {
  return std::filesystem::temp_directory_path() / ("rackopt_fe_cli_test_" + std::to_string(::getpid()));
}

std::string tmp_dir(const std::string& name) {
  const auto dir = tmp_root() / name;
  std::filesystem::remove_all(dir);
  return dir.string();
}

class RemoveTmpRoot : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(tmp_root(), ec);
  }
};
[[maybe_unused]] ::testing::Environment* const remove_tmp_root = ::testing::AddGlobalTestEnvironment(new RemoveTmpRoot);

TEST(FeCli, BadPositionsLevelAndUnknownOptionsAreUsageErrors) {
  const std::string dir = tmp_dir("usage");
  struct Case {
    const char* args;
    const char* says;
  };
  for (const Case& c : {Case{"--positions 0", "--positions needs a whole number in 1..64, got '0'"},
                        Case{"--positions 65", "in 1..64, got '65'"}, Case{"--positions two", "got 'two'"},
                        Case{"--level 7", "--level needs a whole number in 0..6, got '7'"},
                        Case{"--level -1", "got '-1'"}, Case{"--samples 10", "option --samples does not apply to 'fe'"},
                        Case{"--frobnicate", "unknown option --frobnicate"}}) {
    const CliResult r = run(std::string("fe problems/gantry_axis.yaml --out ") + dir + " " + c.args, true);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.says), std::string::npos) << c.args << "\n" << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir));
  // --positions belongs to fe only.
  const CliResult s = run("stiffness problems/gantry_axis.yaml --positions 3", true);
  EXPECT_EQ(s.code, 2);
  EXPECT_NE(s.out.find("does not apply to 'stiffness'"), std::string::npos) << s.out;
  // With --json a usage error is one JSON object too.
  const CliResult j = run("fe problems/gantry_axis.yaml --level 9 --json");
  EXPECT_EQ(j.code, 2);
  const auto o = nlohmann::json::parse(j.out);
  EXPECT_EQ(o["error"], "usage");
}

TEST(FeCli, AMissingCcxIsExitOneNamingThePackageAndLeavesNoFiles) {
  const std::string dir = tmp_dir("no_ccx");
  const CliResult r = run("fe problems/gantry_axis.yaml --positions 2 --out " + dir, true, "RACKOPT_CCX=/nonexistent");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("calculix-ccx"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir));
  const CliResult j = run("fe problems/gantry_axis.yaml --json --out " + dir, false, "RACKOPT_CCX=/nonexistent");
  EXPECT_EQ(j.code, 1);
  const auto o = nlohmann::json::parse(j.out);
  EXPECT_EQ(o["ok"], false);
  EXPECT_EQ(o["error"], "ccx_not_found");
  EXPECT_NE(o["message"].get<std::string>().find("calculix-ccx"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(FeCli, AnImpossibleDesignIsReportedAsTheOtherCommandsDoBeforeAnyFeWork) {
  const std::string dir = tmp_dir("design");
  // Even with no solver: the design is refused first.
  const CliResult r = run("fe problems/gantry_axis.yaml --set pinion.addendum=3 --json --out " + dir, false,
                          "RACKOPT_CCX=/nonexistent");
  EXPECT_EQ(r.code, 2) << r.out;
  const auto o = nlohmann::json::parse(r.out);
  EXPECT_EQ(o["error"], "design:pointed_tooth");
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(FeCli, AStudyAskingForFeVerificationWithoutCcxIsRefusedBeforeItRuns) {
  const std::string dir = tmp_dir("study_no_ccx");
  std::filesystem::create_directories(tmp_root());
  const std::string study = (tmp_root() / "verify_study.yaml").string();
  std::ofstream(study) << "study: {name: verified, kind: evaluate}\n"
                       << "problem: " << RACKOPT_SOURCE_DIR << "/problems/gantry_axis.yaml\n"
                       << "report: [contact_ratio]\n"
                       << "verify: {method: fe, positions: 2}\n";
  const CliResult r = run("run " + study + " --out " + dir, true, "RACKOPT_CCX=/nonexistent");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("calculix-ccx"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir));
  // A bad verify key is bad input at its line and column.
  std::ofstream(study) << "study: {name: verified, kind: evaluate}\n"
                       << "problem: " << RACKOPT_SOURCE_DIR << "/problems/gantry_axis.yaml\n"
                       << "verify: {method: fe, level: 9}\n";
  const CliResult b = run("run " + study + " --out " + dir, true);
  EXPECT_EQ(b.code, 2) << b.out;
  EXPECT_NE(b.out.find("verify_study.yaml:3:29"), std::string::npos) << b.out;
  EXPECT_NE(b.out.find("verify.level"), std::string::npos) << b.out;
}

}  // namespace
