// The command line's guarantees (docs/output.md, "Guarantees"): nothing
// lost, nothing hung, nothing silent. A full disk (RLIMIT_FSIZE, which makes
// writes past N bytes fail with EFBIG: real, deterministic and needs no
// root), a gnuplot that truncates its image or hangs, Ctrl-C while a plot
// renders or during one long Monte Carlo evaluation, a folder in use, stale
// temporary files, options that do not apply, the progress line.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "support/cli_process.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

using rackopt::test_support::CliOptions;
using rackopt::test_support::CliResult;
using rackopt::test_support::read_text;
using rackopt::test_support::run_cli;
using rackopt::test_support::scratch_dir;

// A background run keeps its stdout and stderr in `scratch`.
pid_t start(const std::string& args, const std::string& scratch, const CliOptions& options = {}) {
  return rackopt::test_support::start_cli(args, scratch + "/stdout.txt", scratch + "/stderr.txt", options);
}

CliResult finish(pid_t pid, const std::string& scratch, Clock::time_point t0 = Clock::now()) {
  return rackopt::test_support::finish_cli(pid, scratch + "/stdout.txt", scratch + "/stderr.txt", t0);
}

// An executable shell script `name` in `dir` with `body`.
std::string script(const std::string& dir, const std::string& name, const std::string& body) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << "#!/bin/sh\n" << body;
  fs::permissions(path, fs::perms::owner_all);
  return path;
}

// Waits up to `seconds` for `path` to exist with content.
bool wait_for_file(const std::string& path, double seconds) {
  const auto t0 = Clock::now();
  while (std::chrono::duration<double>(Clock::now() - t0).count() < seconds) {
    if (fs::exists(path) && !read_text(path).empty()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

bool process_alive(pid_t pid) { return kill(pid, 0) == 0; }

// Names in `dir` that look like temporary or partial files.
std::vector<std::string> leftovers(const std::string& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.find(".tmp") != std::string::npos) out.push_back(name);
  }
  return out;
}

// A gnuplot that writes only the first 4096 bytes of its image and exits 0,
// as the real one does on a full disk: `ulimit -f 8` (512-byte blocks) is
// RLIMIT_FSIZE for it alone, SIGXFSZ ignored so its writes fail with EFBIG.
std::string truncating_gnuplot(const std::string& dir) {
  return script(dir, "gnuplot_full_disk.sh", "ulimit -f 8\ntrap '' XFSZ\nexec gnuplot \"$@\"\n");
}

// A gnuplot that never finishes; it writes its pid first.
std::string hanging_gnuplot(const std::string& dir) {
  return script(dir, "gnuplot_hangs.sh", "echo $$ > '" + dir + "/gnuplot.pid'\nsleep 120\n");
}

TEST(OutputGuarantees, PlotTruncatedByAFullDiskIsAWarningAndNotPublished) {
  const std::string dir = scratch_dir("truncated_plot");
  const std::string gp = truncating_gnuplot(dir);
  const CliResult r = run_cli("stiffness problems/rack_railway.yaml --json --out " + dir + "/out", {.env = "RACKOPT_GNUPLOT='" + gp + "'"});
  ASSERT_EQ(r.code, 0) << r.err;  // a plot is a convenience: exit code unaffected
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["files"]["plot"].is_null()) << j["files"];  // not listed as written
  EXPECT_FALSE(fs::exists(dir + "/out/stiffness.png"));
  EXPECT_TRUE(leftovers(dir + "/out").empty());
  bool named = false;
  for (const auto& w : j["warnings"]) named = named || w.get<std::string>().find("stiffness.png") != std::string::npos;
  EXPECT_TRUE(named) << j["warnings"];
  EXPECT_NE(r.err.find("truncated PNG"), std::string::npos) << r.err;
  // The same gnuplot with room to write: the image is published.
  const CliResult ok = run_cli("stiffness problems/rack_railway.yaml --json --out " + dir + "/ok");
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(dir + "/ok/stiffness.png"));
}

TEST(OutputGuarantees, WearPlotsTruncatedByAFullDiskAreNotListed) {
  const std::string dir = scratch_dir("truncated_wear_plots");
  const std::string gp = truncating_gnuplot(dir);
  const CliResult r = run_cli("wear problems/ship_lift.yaml --samples 200 --json --out " + dir + "/out", {.env = "RACKOPT_GNUPLOT='" + gp + "'"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* png : {"wear_profile.png", "life_histogram.png", "reliability.png"}) {
    EXPECT_FALSE(fs::exists(dir + "/out/" + png)) << png;
    EXPECT_NE(r.err.find(png), std::string::npos) << png << ": " << r.err;
  }
  for (const auto& [role, path] : j["files"].items()) {
    if (path.is_string()) {
      EXPECT_TRUE(fs::exists(path.get<std::string>())) << role;
    }
  }
  EXPECT_TRUE(leftovers(dir + "/out").empty());
}

TEST(OutputGuarantees, ResultFileWriteFailureExitsOneAndPublishesNothingPartial) {
  const std::string dir = scratch_dir("full_disk");
  // stiffness.csv is 866 kB: it cannot be written under a 64 kB limit.
  const CliResult s = run_cli("stiffness problems/rack_railway.yaml --json --out " + dir + "/s", {.file_size_limit = 64 * 1024});
  EXPECT_EQ(s.code, 1) << s.err;
  const auto j = nlohmann::json::parse(s.out);
  EXPECT_FALSE(j["ok"].get<bool>());
  EXPECT_EQ(j["error"], "run");
  EXPECT_NE(j["message"].get<std::string>().find("stiffness.csv"), std::string::npos) << j;
  EXPECT_FALSE(fs::exists(dir + "/s/stiffness.csv"));
  EXPECT_TRUE(leftovers(dir + "/s").empty());

  // wear_profile.csv (160 kB) under the same limit.
  const CliResult w = run_cli("wear problems/ship_lift.yaml --samples 100 --json --out " + dir + "/w", {.file_size_limit = 64 * 1024});
  EXPECT_EQ(w.code, 1) << w.err;
  EXPECT_FALSE(fs::exists(dir + "/w/wear_profile.csv"));
  EXPECT_TRUE(leftovers(dir + "/w").empty());

  // A study: the evaluation store itself cannot grow past 8 kB.
  const std::string study = dir + "/tiny.yaml";
  std::ofstream(study) << "study: {name: tiny, kind: evaluate}\n"
                       << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                       << "report: [contact_ratio]\n";
  const CliResult r = run_cli("run '" + study + "' --json --out " + dir + "/r", {.file_size_limit = 8 * 1024});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_FALSE(nlohmann::json::parse(r.out)["ok"].get<bool>());
  EXPECT_FALSE(fs::exists(dir + "/r/summary.json"));
  EXPECT_FALSE(fs::exists(dir + "/r/report.md"));
  EXPECT_TRUE(leftovers(dir + "/r").empty());
}

TEST(OutputGuarantees, HungGnuplotIsKilledAtTheTimeLimit) {
  const std::string dir = scratch_dir("hung_plot");
  const std::string gp = hanging_gnuplot(dir);
  const CliResult r = run_cli("stiffness problems/rack_railway.yaml --json --out " + dir + "/out", {.env = "RACKOPT_PLOT_TIMEOUT=1 RACKOPT_GNUPLOT='" + gp + "'"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_LT(r.seconds, 20.0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["files"]["plot"].is_null());
  ASSERT_TRUE(wait_for_file(dir + "/gnuplot.pid", 1));
  const pid_t gp_pid = std::stoi(read_text(dir + "/gnuplot.pid"));
  EXPECT_FALSE(process_alive(gp_pid)) << "gnuplot still running";
  EXPECT_NE(r.err.find("stiffness.png not drawn: gnuplot did not finish within 1 s"), std::string::npos) << r.err;
}

TEST(OutputGuarantees, CtrlCWhilePlotRendersExits130AndEndsGnuplot) {
  const std::string dir = scratch_dir("sigint_plot");
  const std::string gp = hanging_gnuplot(dir);
  const pid_t pid = start("stiffness problems/rack_railway.yaml --json --out " + dir + "/out", dir, {.env = "RACKOPT_GNUPLOT='" + gp + "'"});
  ASSERT_GT(pid, 0);
  const bool rendering = wait_for_file(dir + "/gnuplot.pid", 60);
  const auto t0 = Clock::now();
  kill(pid, SIGINT);
  const CliResult r = finish(pid, dir, t0);
  ASSERT_TRUE(rendering) << r.err;
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_LT(r.seconds, 5.0);
  const pid_t gp_pid = std::stoi(read_text(dir + "/gnuplot.pid"));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(process_alive(gp_pid)) << "gnuplot still running";
  kill(gp_pid, SIGKILL);  // (in case)
  const auto j = nlohmann::json::parse(r.out);  // one JSON object, the error
  EXPECT_FALSE(j["ok"].get<bool>());
  EXPECT_EQ(j["error"], "interrupted");
  EXPECT_FALSE(fs::exists(dir + "/out/stiffness.png"));
  EXPECT_TRUE(leftovers(dir + "/out").empty());
}

TEST(OutputGuarantees, SigtermIsAStopToo) {
  const std::string dir = scratch_dir("sigterm_plot");
  const std::string gp = hanging_gnuplot(dir);
  const pid_t pid = start("stiffness problems/rack_railway.yaml --out " + dir + "/out", dir, {.env = "RACKOPT_GNUPLOT='" + gp + "'"});
  const bool rendering = wait_for_file(dir + "/gnuplot.pid", 60);
  kill(pid, SIGTERM);
  const CliResult r = finish(pid, dir);
  ASSERT_TRUE(rendering) << r.err;
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_NE(r.err.find("SIGTERM"), std::string::npos) << r.err;
  kill(std::stoi(read_text(dir + "/gnuplot.pid")), SIGKILL);
}

// A study whose report is being plotted when Ctrl-C comes: every evaluation
// is done, yet the run was interrupted: 130, and summary.json is complete.
TEST(OutputGuarantees, CtrlCAfterTheLastEvaluationExits130) {
  const std::string dir = scratch_dir("sigint_report");
  const std::string gp = hanging_gnuplot(dir);
  const std::string study = dir + "/sweep.yaml";
  std::ofstream(study) << "study: {name: small sweep, kind: sweep, seed: 3}\n"
                       << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                       << "variables:\n  rack.span: {lower: 1.2 m, upper: 3 m}\n"
                       << "report: [contact_ratio]\n"
                       << "sweep: {method: grid, levels: 3}\n"
                       << "output: {plots: on, report: on, stiffness_curve: off}\n";
  const pid_t pid = start("run '" + study + "' --json --out " + dir + "/out", dir, {.env = "RACKOPT_GNUPLOT='" + gp + "'"});
  const bool plotting = wait_for_file(dir + "/gnuplot.pid", 60);
  kill(pid, SIGINT);
  const CliResult r = finish(pid, dir);
  ASSERT_TRUE(plotting) << r.err;
  EXPECT_EQ(r.code, 130) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["evaluations"], 3);
  EXPECT_EQ(j, nlohmann::json::parse(read_text(dir + "/out/summary.json")));
  EXPECT_FALSE(fs::exists(dir + "/out/sweep.png"));
  bool named = false;
  for (const auto& w : j["warnings"]) named = named || w.get<std::string>().find("sweep.png not drawn") != std::string::npos;
  EXPECT_TRUE(named) << j["warnings"];
  EXPECT_TRUE(leftovers(dir + "/out").empty());
  kill(std::stoi(read_text(dir + "/gnuplot.pid")), SIGKILL);
}

// Ctrl-C during one long Monte Carlo evaluation (a million samples and their
// distribution fit, 90 to 160 s on one thread) ends within seconds.
TEST(OutputGuarantees, CtrlCDuringALongMonteCarloEndsPromptly) {
  const std::string dir = scratch_dir("sigint_wear");
  const pid_t pid = start("wear problems/ship_lift.yaml --samples 1000000 --threads 1 --json --out " + dir + "/out", dir);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const auto t0 = Clock::now();
  kill(pid, SIGINT);
  const CliResult r = finish(pid, dir, t0);
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_LT(r.seconds, 5.0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"], "interrupted");
  EXPECT_NE(j["message"].get<std::string>().find("SIGINT"), std::string::npos) << j;
  EXPECT_FALSE(fs::exists(dir + "/out/wear_profile.csv"));  // nothing half-done published
}

// A reliability study's Monte Carlo and distribution fits poll the stop
// request: the first Ctrl-C ends them promptly, and the study writes its
// stopped report (what the store committed stays; nothing of the abandoned
// analysis is published, no temporary file is left).
TEST(OutputGuarantees, CtrlCDuringTheMonteCarloOfAReliabilityStudyWritesTheStoppedReportPromptly) {
  const std::string dir = scratch_dir("sigint_reliability");
  const pid_t study = start("run studies/ship_lift_reliability.yaml --set metric_options.reliability_samples=1000000 "
                            "--threads 1 --json --out " + dir + "/study", dir);
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  const auto t1 = Clock::now();
  kill(study, SIGINT);
  const CliResult s = finish(study, dir, t1);
  EXPECT_EQ(s.code, 130) << s.err;
  EXPECT_LT(s.seconds, 5.0);
  const auto js = nlohmann::json::parse(s.out);  // the summary
  EXPECT_EQ(js["status"], "stopped") << js;
  EXPECT_NE(js["message"].get<std::string>().find("during the reliability analysis"), std::string::npos) << js;
  const auto summary = nlohmann::json::parse(read_text(dir + "/study/summary.json"));
  EXPECT_EQ(summary["status"], "stopped");
  const std::string md = read_text(dir + "/study/report.md");
  EXPECT_NE(md.find("stopped after"), std::string::npos) << md;
  EXPECT_NE(md.find("--resume"), std::string::npos) << md;
  EXPECT_TRUE(leftovers(dir + "/study").empty());
}

TEST(OutputGuarantees, FolderInUseIsExitTwoWithAJsonError) {
  const std::string dir = scratch_dir("in_use");
  const std::string gp = hanging_gnuplot(dir);
  const std::string first = dir + "/first";
  fs::create_directories(first);
  const pid_t pid = start("stiffness problems/rack_railway.yaml --out " + dir + "/out", first, {.env = "RACKOPT_GNUPLOT='" + gp + "'"});
  const bool holding = wait_for_file(dir + "/gnuplot.pid", 60);
  const CliResult second = run_cli("stiffness problems/rack_railway.yaml --json --out " + dir + "/out");
  kill(pid, SIGINT);
  finish(pid, first);
  ASSERT_TRUE(holding);
  EXPECT_EQ(second.code, 2) << second.err;
  const auto j = nlohmann::json::parse(second.out);
  EXPECT_FALSE(j["ok"].get<bool>());
  EXPECT_EQ(j["error"], "output_folder");
  EXPECT_NE(j["message"].get<std::string>().find("in use by another rackopt run (pid " + std::to_string(pid) + ")"),
            std::string::npos)
      << j;
  kill(std::stoi(read_text(dir + "/gnuplot.pid")), SIGKILL);
}

TEST(OutputGuarantees, ResumeRemovesStaleTemporaryFiles) {
  const std::string dir = scratch_dir("stale");
  const std::string study = dir + "/tiny.yaml";
  std::ofstream(study) << "study: {name: tiny, kind: evaluate}\n"
                       << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                       << "report: [contact_ratio]\n"
                       << "output: {plots: off}\n";
  const std::string out = dir + "/out";
  ASSERT_EQ(run_cli("run '" + study + "' --out " + out).code, 0);
  // What a kill -9 in the middle of writes leaves: our writers' temporaries.
  const std::vector<std::string> stale = {"summary.json.tmp.4194000", "report.md.tmp.1", "history.png.tmp",
                                          ".evaluations.csv.tmpAb3dE9"};
  for (const auto& name : stale) std::ofstream(out + "/" + name) << "partial";
  // Files that merely look alike are not ours and stay.
  const std::vector<std::string> kept = {"notes.tmp.txt", "summary.json.tmp.12a", "my.tmp"};
  for (const auto& name : kept) std::ofstream(out + "/" + name) << "mine";
  const CliResult r = run_cli("run '" + study + "' --resume --out " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const auto& name : stale) {
    EXPECT_FALSE(fs::exists(out + "/" + name)) << name;
    EXPECT_NE(r.err.find("removed " + name), std::string::npos) << r.err;
  }
  for (const auto& name : kept) EXPECT_TRUE(fs::exists(out + "/" + name)) << name;
}

TEST(OutputGuarantees, OptionsThatDoNotApplyAreUsageErrors) {
  const std::string dir = scratch_dir("options");
  const CliResult check = run_cli("check problems/rack_railway.yaml --samples 10");
  EXPECT_EQ(check.code, 2);
  EXPECT_NE(check.err.find("option --samples does not apply to 'check'"), std::string::npos) << check.err;
  const CliResult stiff = run_cli("stiffness problems/rack_railway.yaml --resume --out " + dir + "/s");
  EXPECT_EQ(stiff.code, 2);
  EXPECT_NE(stiff.err.find("option --resume does not apply to 'stiffness'"), std::string::npos) << stiff.err;
  EXPECT_FALSE(fs::exists(dir + "/s"));  // refused before anything was done
  EXPECT_EQ(run_cli("wear problems/ship_lift.yaml --progress --out " + dir + "/w").code, 2);
  EXPECT_EQ(run_cli("run studies/rack_railway_sizing.yaml --samples=5 --out " + dir + "/r").code, 2);
  EXPECT_EQ(run_cli("check problems/rack_railway.yaml --out=" + dir + "/c").code, 2);
  // Options a command does accept still work.
  EXPECT_EQ(run_cli("check problems/rack_railway.yaml --set 'rack.span=1.2 m' --json").code, 0);
}

TEST(OutputGuarantees, UsageErrorsPrintOneJsonObjectWithJson) {
  for (const std::string args : {"check problems/rack_railway.yaml --json --samples 3", "frobnicate x --json",
                                 "stiffness --json", "stiffness problems/rack_railway.yaml --json --bogus",
                                 "wear problems/ship_lift.yaml --json --samples 0"}) {
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.code, 2) << args;
    const auto j = nlohmann::json::parse(r.out);  // exactly one JSON value
    EXPECT_EQ(j, (nlohmann::json{{"ok", false}, {"error", "usage"}, {"message", j["message"]}})) << args;
    EXPECT_FALSE(j["message"].get<std::string>().empty());
  }
}

// The progress line of a study that ends long before its budget: while
// running it says the total is a budget, at the end it shows count/count and
// no time left, and no line is wider than COLUMNS - 1.
TEST(OutputGuarantees, ProgressLineEndsDoneAndFitsTheTerminal) {
  const std::string dir = scratch_dir("progress");
  const std::string study = dir + "/sweep.yaml";
  std::ofstream(study) << "study: {name: progress sweep, kind: sweep, seed: 3}\n"
                       << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                       << "problem_set:\n  numerics.positions_per_period: 800\n"
                       << "variables:\n  rack.span: {lower: 1.2 m, upper: 3 m}\n"
                       << "  pinion.pressure_angle: {lower: 17 deg, upper: 25 deg}\n"
                       << "objectives:\n  - {metric: stiffness_fluctuation, scale: 1}\n"
                       << "sweep: {method: grid, levels: 22}\n"
                       << "output: {plots: off, report: off, stiffness_curve: off}\n";
  const CliResult r = run_cli("run '" + study + "' --progress --threads 1 --out " + dir + "/out", {.env = "COLUMNS=52"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> lines;
  std::string cur;
  for (char c : r.err) {
    if (c == '\r' || c == '\n') {
      if (!cur.empty()) lines.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  std::vector<std::string> bar_lines;
  for (const auto& l : lines) {
    if (l.find(" evaluations") != std::string::npos && l.find("s") != std::string::npos) bar_lines.push_back(l);
  }
  ASSERT_GE(bar_lines.size(), 2u) << r.err;  // the run lasts over a second
  for (const auto& l : bar_lines) {
    // (trailing blanks only clear a longer previous line)
    std::string t = l;
    while (!t.empty() && t.back() == ' ') t.pop_back();
    EXPECT_LE(t.size(), 51u) << "[" << l << "]";
  }
  const std::string last = bar_lines.back();
  EXPECT_NE(last.find("484/484 evaluations"), std::string::npos) << last;  // 22 x 22
  EXPECT_NE(last.find("done in"), std::string::npos) << last;
  EXPECT_EQ(last.find("left"), std::string::npos) << last;
}

}  // namespace
