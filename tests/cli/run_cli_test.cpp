// `rackopt run` end to end: the shipped sizing study, --json, bad study files,
// a study with no feasible design, Ctrl-C and kill -9 followed by --resume.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <sqlite3.h>

#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/studyfile/study_loader.hpp"
#include "support/cli_process.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;

using rackopt::test_support::CliResult;
using rackopt::test_support::read_text;
using rackopt::test_support::run_cli;
using rackopt::test_support::scratch_dir;
using rackopt::test_support::start_cli;
using rackopt::test_support::wait_exit;

// Largest evaluation count the progress bar has drawn so far: N of "N/M
// evaluations" (a planned number) or of "N evaluations (budget M)" (optimize
// and pareto).
long progress_done(const std::string& err_file) {
  // (no std::regex: GCC 12 warns inside it under the sanitizer build)
  const std::string text = read_text(err_file);
  long best = 0;
  for (std::size_t at = text.find(" evaluations"); at != std::string::npos; at = text.find(" evaluations", at + 1)) {
    std::size_t slash = at;
    while (slash > 0 && std::isdigit(static_cast<unsigned char>(text[slash - 1]))) --slash;
    if (slash == at) continue;
    if (text.compare(at, 21, " evaluations (budget ") == 0) {
      best = std::max(best, std::stol(text.substr(slash, at - slash)));
      continue;
    }
    if (slash == 0 || text[--slash] != '/') continue;  // not "N/M evaluations"
    std::size_t begin = slash;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(text[begin - 1]))) --begin;
    if (begin < slash) best = std::max(best, std::stol(text.substr(begin, slash - begin)));
  }
  return best;
}

// Waits until the background run has drawn at least `done` evaluations (or
// ended); false when it ended first or 60 s passed.
bool wait_for_progress(pid_t pid, const std::string& err_file, long done) {
  const auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60)) {
    if (progress_done(err_file) >= done) return true;
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// A 20 x 20 grid sweep on the rack railway paper's problem with a fine travel sampling
// (a few ms per design, so that a run lasts long enough to be interrupted: the
// progress bar, which the interrupting tests wait for, starts drawing after
// one second).
// The objective has a fixed scale, so no start design is evaluated: the
// study needs exactly kSweepSize evaluations.
constexpr std::size_t kSweepSize = 400;
std::string write_sweep_study(const std::string& dir) {
  const std::string path = dir + "/sweep.yaml";
  std::ofstream(path) << "study: {name: resume sweep, kind: sweep, seed: 3}\n"
                      << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                      << "problem_set:\n  numerics.positions_per_period: 2000\n"
                      << "variables:\n"
                      << "  rack.span: {lower: 1.2 m, upper: 3 m}\n"
                      << "  pinion.pressure_angle: {lower: 17 deg, upper: 25 deg}\n"
                      << "objectives:\n  - {metric: stiffness_fluctuation, scale: 1}\n"
                      << "constraints:\n  - {metric: contact_ratio, min: 1.6}\n"
                      << "sweep: {method: grid, levels: 20}\n"
                      << "output: {plots: off, report: on, stiffness_curve: off}\n";
  return path;
}

// Every x of the store, checked for repeats through the record API.
void expect_store_complete(const std::string& study_file, const std::string& out_dir) {
  const rackopt::study::StudySpec spec = rackopt::studyfile::load_study_file(study_file);
  std::vector<std::string> names;
  for (const auto& v : spec.variables) names.push_back(v.key);
  auto store = rackopt::record::EvaluationStore::open(out_dir + "/evaluations.sqlite",
                                                      rackopt::study::study_fingerprint(spec), names, true,
                                                      {.fingerprint_format = rackopt::study::kStudyFingerprintFormat});
  const auto all = store.all();
  EXPECT_EQ(all.size(), kSweepSize);
  std::set<std::vector<double>> xs;
  for (const auto& e : all) EXPECT_TRUE(xs.insert(e.x).second) << "evaluated twice: id " << e.id;
  EXPECT_EQ(xs.size(), kSweepSize);
}

TEST(RunCli, ShippedSizingStudyPrintsTheSummaryObject) {
  const std::string dir = scratch_dir("sizing");
  const CliResult r = run_cli("run studies/rack_railway_sizing.yaml --json --out " + dir + "/out");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // exactly one JSON value on stdout
  EXPECT_EQ(j["kind"], "optimize");
  EXPECT_EQ(j["study"], "rack railway sizing");
  for (const char* key : {"status", "best", "evaluations", "failed_evaluations", "reused_evaluations", "timings",
                          "files", "warnings"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  ASSERT_TRUE(j["best"].is_object());
  EXPECT_TRUE(j["best"]["feasible"].get<bool>());
  // the constraints of the study file, checked on the reported design
  EXPECT_GE(j["best"]["metrics"]["contact_ratio"]["value"].get<double>(), 1.3 - 1e-6);
  EXPECT_LE(j["best"]["metrics"]["supports_per_metre"]["value"].get<double>(), 0.5 + 1e-6);
  const double span = j["best"]["variables"]["rack.span"]["value"].get<double>();
  EXPECT_GE(span, 1.2);
  EXPECT_LE(span, 3.0);
  EXPECT_GT(j["evaluations"].get<long>(), 0);
  EXPECT_EQ(j["reused_evaluations"], 0);
  EXPECT_GT(j["timings"]["seconds"].get<double>(), 0.0);
  // What --json printed is summary.json.
  EXPECT_EQ(j, nlohmann::json::parse(read_text(dir + "/out/summary.json")));
  for (const auto& [role, path] : j["files"].items()) EXPECT_TRUE(fs::exists(path.get<std::string>())) << role;
  EXPECT_TRUE(j["files"].contains("database"));
  EXPECT_TRUE(j["files"].contains("best_csv"));
  // People's text went to stderr.
  EXPECT_NE(r.err.find("best design"), std::string::npos) << r.err;
}

TEST(RunCli, BadStudyFileIsExit2WithFileLineColumn) {
  const std::string dir = scratch_dir("bad");
  const std::string path = dir + "/bad.yaml";
  std::ofstream(path) << "study: {name: bad, kind: optimize}\n"
                      << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                      << "variables:\n"
                      << "  rack.span: {lower: 3 m, upper: 1.2 m}\n"
                      << "objectives: [stiffness_fluctuation]\n";
  const CliResult r = run_cli("run '" + path + "' --json --out " + dir + "/out");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("bad.yaml:4:"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["ok"].get<bool>());
  EXPECT_EQ(j["error"], "input");

  const CliResult missing = run_cli("run '" + dir + "/nothing.yaml' --out " + dir + "/out2");
  EXPECT_EQ(missing.code, 2);
  const CliResult unknown_set = run_cli("run '" + path + "' --set solver.no_such_key=3 --out " + dir + "/out3");
  EXPECT_EQ(unknown_set.code, 2);
}

TEST(RunCli, NoFeasiblePointExitsZeroAndShowsTheLeastInfeasibleDesign) {
  const std::string dir = scratch_dir("infeasible");
  const std::string path = dir + "/infeasible.yaml";
  std::ofstream(path) << "study: {name: impossible, kind: optimize}\n"
                      << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                      << "variables:\n  rack.span: {lower: 1.2 m, upper: 3 m}\n"
                      << "objectives: [stiffness_fluctuation]\n"
                      << "constraints:\n  - {metric: contact_ratio, min: 5}\n"
                      << "solver: {algorithm: LN_COBYLA, max_evaluations: 15}\n";
  const CliResult r = run_cli("run '" + path + "' --json --out " + dir + "/out");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "no_feasible_point");
  ASSERT_TRUE(j.contains("least_infeasible"));
  EXPECT_GT(j["least_infeasible"]["max_violation"].get<double>(), 0.0);
  EXPECT_LT(j["least_infeasible"]["metrics"]["contact_ratio"]["value"].get<double>(), 5.0);
  EXPECT_NE(r.err.find("NO FEASIBLE DESIGN"), std::string::npos) << r.err;
}

TEST(RunCli, KillNineThenResumeLosesNothingAndRepeatsNothing) {
  const std::string dir = scratch_dir("kill");
  const std::string study = write_sweep_study(dir);

  // Reference: uninterrupted, in its own folder.
  const CliResult ref = run_cli("run '" + study + "' --json --threads 2 --out " + dir + "/ref");
  ASSERT_EQ(ref.code, 0) << ref.err;
  const auto jref = nlohmann::json::parse(ref.out);
  ASSERT_EQ(jref["evaluations"], kSweepSize);
  ASSERT_TRUE(jref["best"].is_object());

  const std::string out = dir + "/run";
  const pid_t pid = start_cli("run '" + study + "' --json --progress --threads 1 --out " + out, dir + "/o1.txt",
                          dir + "/e1.txt");
  ASSERT_GT(pid, 0);
  const bool mid_run = wait_for_progress(pid, dir + "/e1.txt", 60);
  if (mid_run) kill(pid, SIGKILL);
  const int code = wait_exit(pid);
  ASSERT_TRUE(mid_run) << "the sweep ended before it could be killed (exit " << code << ")";
  EXPECT_EQ(code, 128 + SIGKILL);

  const CliResult resumed = run_cli("run '" + study + "' --json --resume --threads 2 --out " + out);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const auto j = nlohmann::json::parse(resumed.out);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["evaluations"], kSweepSize);
  EXPECT_GT(j["reused_evaluations"].get<long>(), 0);
  EXPECT_LT(j["reused_evaluations"].get<long>(), static_cast<long>(kSweepSize));
  EXPECT_EQ(j["best"], jref["best"]);
  EXPECT_EQ(j["sweep_points"], jref["sweep_points"]);
  EXPECT_EQ(j["feasible_points"], jref["feasible_points"]);
  EXPECT_EQ(read_text(out + "/sweep.csv"), read_text(dir + "/ref/sweep.csv"));
  expect_store_complete(study, out);
}

TEST(RunCli, CtrlCStopsCleanlyWritesResultsAndResumeFinishes) {
  const std::string dir = scratch_dir("sigint");
  const std::string study = write_sweep_study(dir);
  const std::string out = dir + "/run";
  const pid_t pid = start_cli("run '" + study + "' --json --progress --threads 1 --out " + out, dir + "/o1.txt",
                          dir + "/e1.txt");
  ASSERT_GT(pid, 0);
  const bool mid_run = wait_for_progress(pid, dir + "/e1.txt", 40);
  if (mid_run) kill(pid, SIGINT);
  const int code = wait_exit(pid);
  ASSERT_TRUE(mid_run) << "the sweep ended before it could be interrupted (exit " << code << ")";
  EXPECT_EQ(code, 130);
  const auto stopped = nlohmann::json::parse(read_text(dir + "/o1.txt"));
  EXPECT_EQ(stopped["status"], "stopped");
  EXPECT_NE(stopped["message"].get<std::string>().find("--resume"), std::string::npos);
  EXPECT_LT(stopped["evaluations"].get<long>(), static_cast<long>(kSweepSize));
  EXPECT_GT(stopped["evaluations"].get<long>(), 0);
  EXPECT_TRUE(fs::exists(out + "/summary.json"));
  EXPECT_TRUE(fs::exists(out + "/report.md"));
  EXPECT_NE(read_text(dir + "/e1.txt").find("--resume"), std::string::npos);

  const CliResult resumed = run_cli("run '" + study + "' --json --resume --out " + out);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const auto j = nlohmann::json::parse(resumed.out);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["evaluations"], kSweepSize);
  // Everything the stopped run recorded was committed (a clean stop flushes).
  EXPECT_EQ(j["reused_evaluations"], stopped["evaluations"]);
  expect_store_complete(study, out);
}

// Starts `rackopt run STUDY ARGS --json --progress --threads 1` into `out`,
// sends SIGINT once the progress bar has counted `done` evaluations, and
// checks what every stopped run leaves: exit 130 (not the at-once end), the
// --json object, and a summary.json and a report.md that say "stopped".
void interrupt_and_expect_stopped_report(const std::string& study_args, const std::string& dir, long done) {
  const std::string out = dir + "/run";
  const pid_t pid = start_cli("run " + study_args + " --json --progress --threads 1 --out " + out, dir + "/o1.txt",
                              dir + "/e1.txt");
  EXPECT_GT(pid, 0);
  const bool mid_run = wait_for_progress(pid, dir + "/e1.txt", done);
  if (mid_run) kill(pid, SIGINT);
  const int code = wait_exit(pid);
  EXPECT_TRUE(mid_run) << "the study ended before it could be interrupted (exit " << code << ")";
  const std::string err = read_text(dir + "/e1.txt");
  EXPECT_EQ(code, 130) << err;
  EXPECT_EQ(err.find("stopped at once"), std::string::npos) << err;
  const std::string printed = read_text(dir + "/o1.txt");
  EXPECT_TRUE(nlohmann::json::accept(printed)) << printed << err;
  if (!nlohmann::json::accept(printed)) return;
  const auto stopped = nlohmann::json::parse(printed);
  EXPECT_EQ(stopped["status"], "stopped") << printed;
  EXPECT_GT(stopped["evaluations"].get<long>(), 0);
  EXPECT_TRUE(fs::exists(out + "/summary.json"));
  if (fs::exists(out + "/summary.json")) {
    EXPECT_EQ(nlohmann::json::parse(read_text(out + "/summary.json"))["status"], "stopped");
  }
  EXPECT_TRUE(fs::exists(out + "/report.md"));
  EXPECT_NE(read_text(out + "/report.md").find("stopped"), std::string::npos);
  EXPECT_NE(err.find("--resume"), std::string::npos) << err;
}

// Ctrl-C while a design's Monte Carlo life at R runs gives up that
// evaluation (rackopt::Interrupted from the samples) and must still end in
// the stopped report. The gantry's one random input is sampled (not its
// exact quantile) with many samples, so that the Monte Carlo is nearly all
// of each evaluation's time: the signal lands inside one.
TEST(RunCli, CtrlCInsideALifeAtRMonteCarloOfAnOptimizeStudyWritesTheStoppedReport) {
  const std::string dir = scratch_dir("sigint_life_at_r_optimize");
  interrupt_and_expect_stopped_report(
      "studies/gantry_sizing.yaml --set metric_options.exact_quantile=off "
      "--set metric_options.reliability_samples=2000 --set output.plots=off",
      dir, 1);
}

TEST(RunCli, CtrlCInsideALifeAtRMonteCarloOfAParetoStudyWritesTheStoppedReport) {
  const std::string dir = scratch_dir("sigint_life_at_r_pareto");
  interrupt_and_expect_stopped_report(
      "studies/ship_lift_wear_tradeoff.yaml --set metric_options.exact_quantile=off "
      "--set metric_options.reliability_samples=2000 --set output.plots=off",
      dir, 3);
}

// The sweep of write_sweep_study from 15 deg with the pressure angle varying
// slowest: the 22-tooth pinion is undercut at the first four angles (15 to
// 16.58 deg: z_min = 27.4 down to 22.7 for the railway problem's cutter) and
// not from 17.1 deg on, so every undercut warning of the study comes from its
// first 80 designs; the best design is the first one (15 deg, 1.2 m).
std::string write_undercut_first_study(const std::string& dir) {
  const std::string path = dir + "/undercut_first.yaml";
  std::ofstream(path) << "study: {name: undercut first, kind: sweep, seed: 3}\n"
                      << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                      << "problem_set:\n  numerics.positions_per_period: 2000\n"
                      << "variables:\n"
                      << "  pinion.pressure_angle: {lower: 15 deg, upper: 25 deg}\n"
                      << "  rack.span: {lower: 1.2 m, upper: 3 m}\n"
                      << "objectives:\n  - {metric: stiffness_fluctuation, scale: 1}\n"
                      << "constraints:\n  - {metric: contact_ratio, min: 1.6}\n"
                      << "sweep: {method: grid, levels: 20}\n"
                      << "output: {plots: off, report: on, stiffness_curve: off}\n";
  return path;
}

// report.md from "## Warnings" (either heading) up to the next section.
std::string warnings_section(const std::string& md) {
  const std::size_t begin = md.find("## Warnings");
  if (begin == std::string::npos) return "";
  return md.substr(begin, md.find("## Files", begin) - begin);
}

TEST(RunCli, ResumedRunReportsTheWarningsOfAnUninterruptedOne) {
  const std::string dir = scratch_dir("warnings");
  const std::string study = write_undercut_first_study(dir);
  const CliResult ref = run_cli("run '" + study + "' --json --threads 2 --out " + dir + "/ref");
  ASSERT_EQ(ref.code, 0) << ref.err;
  const auto jref = nlohmann::json::parse(ref.out);
  std::size_t undercut = 0;
  for (const auto& w : jref["warnings"]) undercut += w.get<std::string>().find("pinion undercut") == 0 ? 1 : 0;
  ASSERT_EQ(undercut, 4u) << jref["warnings"];
  ASSERT_FALSE(jref["best"]["warnings"].empty()) << jref["best"];

  // Stopped (Ctrl-C flushes every evaluation) after the undercut designs.
  const std::string out = dir + "/run";
  const pid_t pid = start_cli("run '" + study + "' --json --progress --threads 1 --out " + out, dir + "/o1.txt",
                          dir + "/e1.txt");
  ASSERT_GT(pid, 0);
  const bool mid_run = wait_for_progress(pid, dir + "/e1.txt", 88);
  if (mid_run) kill(pid, SIGINT);
  const int code = wait_exit(pid);
  ASSERT_TRUE(mid_run) << "the sweep ended before it could be interrupted (exit " << code << ")";
  ASSERT_EQ(code, 130);
  const auto stopped = nlohmann::json::parse(read_text(dir + "/o1.txt"));
  ASSERT_GE(stopped["evaluations"].get<long>(), 80);
  ASSERT_LT(stopped["evaluations"].get<long>(), static_cast<long>(kSweepSize));

  const CliResult resumed = run_cli("run '" + study + "' --json --resume --out " + out);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const auto j = nlohmann::json::parse(resumed.out);
  EXPECT_EQ(j["reused_evaluations"], stopped["evaluations"]);
  // The undercut designs (the best one among them) all came from the store,
  // yet the run lists their warnings as the uninterrupted run does, in the
  // same order, and the best design carries its own.
  EXPECT_EQ(j["warnings"], jref["warnings"]);
  ASSERT_TRUE(j["best"].is_object());
  EXPECT_EQ(j["best"]["warnings"], jref["best"]["warnings"]);
  const auto on_disk = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(on_disk["warnings"], jref["warnings"]);
  const std::string section = warnings_section(read_text(out + "/report.md"));
  EXPECT_NE(section.find("pinion undercut"), std::string::npos) << section;
  EXPECT_EQ(section, warnings_section(read_text(dir + "/ref/report.md")));
}

TEST(RunCli, UsedFolderWithoutResumeIsRefused) {
  const std::string dir = scratch_dir("reuse");
  const std::string path = dir + "/tiny.yaml";
  std::ofstream(path) << "study: {name: tiny, kind: evaluate}\n"
                      << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                      << "report: [contact_ratio]\n";
  ASSERT_EQ(run_cli("run '" + path + "' --out " + dir + "/out").code, 0);
  const CliResult again = run_cli("run '" + path + "' --out " + dir + "/out");
  EXPECT_EQ(again.code, 2);  // a user decision, like bad input: --resume or another --out
  EXPECT_NE(again.err.find("--resume"), std::string::npos) << again.err;
  // Another study in the same folder is refused the same way.
  std::ofstream(path) << "study: {name: tiny, kind: evaluate}\n"
                      << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                      << "report: [contact_ratio, supports_per_metre]\n";
  const CliResult other = run_cli("run '" + path + "' --out " + dir + "/out --resume");
  EXPECT_EQ(other.code, 2);
  EXPECT_NE(other.err.find("another study"), std::string::npos) << other.err;
}

// The default output folder comes from the study's name: a name no file
// system takes is the study's fault, said at study.name (exit 2), before
// anything is written.
TEST(RunCli, AStudyNameTooLongForTheDefaultFolderIsBadInput) {
  const std::string name(300, 'n');
  const CliResult r = run_cli("run studies/rack_railway_sizing.yaml --json --set study.name=" + name);
  EXPECT_EQ(r.code, 2) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"], "input");
  const std::string message = j["message"];
  EXPECT_NE(message.find("study.name"), std::string::npos) << message;
  EXPECT_NE(message.find("at most 255"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(std::string(RACKOPT_SOURCE_DIR) + "/out/" + name));
}

// Flips one bit of one recorded row's objectives, with SQLite directly as
// a failing disk or a hand edit would.
void flip_a_bit_of_row(const std::string& db_path, int id) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
  sqlite3_stmt* read = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT objectives FROM evaluation_records WHERE id = ?1", -1, &read, nullptr),
            SQLITE_OK);
  sqlite3_bind_int(read, 1, id);
  ASSERT_EQ(sqlite3_step(read), SQLITE_ROW);
  const auto* p = static_cast<const char*>(sqlite3_column_blob(read, 0));
  std::string blob(p, static_cast<std::size_t>(sqlite3_column_bytes(read, 0)));
  sqlite3_finalize(read);
  ASSERT_GE(blob.size(), 8u);
  // The top bit of the exponent: a positive objective of a few units
  // becomes about 1e-308, the best of the sweep if it were believed.
  blob[7] = static_cast<char>(blob[7] ^ 0x40);
  sqlite3_stmt* write = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "UPDATE evaluation_records SET objectives = ?1 WHERE id = ?2", -1, &write, nullptr),
            SQLITE_OK);
  sqlite3_bind_blob(write, 1, blob.data(), static_cast<int>(blob.size()), SQLITE_TRANSIENT);
  sqlite3_bind_int(write, 2, id);
  EXPECT_EQ(sqlite3_step(write), SQLITE_DONE);
  sqlite3_finalize(write);
  sqlite3_close(db);
}

TEST(RunCli, ADamagedRecordedRowIsRecomputedOnResume) {
  const std::string dir = scratch_dir("checksum");
  const std::string path = dir + "/grid.yaml";
  std::ofstream(path) << "study: {name: checksum grid, kind: sweep, seed: 3}\n"
                      << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                      << "variables:\n  rack.span: {lower: 1.2 m, upper: 3 m}\n"
                      << "objectives:\n  - {metric: stiffness_fluctuation, scale: 1}\n"
                      << "sweep: {method: grid, levels: 5}\n"
                      << "output: {plots: off, report: on, stiffness_curve: off}\n";
  const std::string out = dir + "/out";
  const CliResult first = run_cli("run '" + path + "' --json --out " + out);
  ASSERT_EQ(first.code, 0) << first.err;
  const auto before = nlohmann::json::parse(first.out);
  ASSERT_EQ(before["evaluations"], 5);
  // Resumed as recorded: every row checks out and is reused.
  fs::remove(out + "/summary.json");
  const CliResult clean = run_cli("run '" + path + "' --json --resume --out " + out);
  ASSERT_EQ(clean.code, 0) << clean.err;
  EXPECT_EQ(nlohmann::json::parse(clean.out)["reused_evaluations"], 5);
  EXPECT_EQ(nlohmann::json::parse(clean.out)["damaged_records_recomputed"], 0);

  flip_a_bit_of_row(out + "/evaluations.sqlite", 3);
  const CliResult resumed = run_cli("run '" + path + "' --json --resume --out " + out);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const auto j = nlohmann::json::parse(resumed.out);
  EXPECT_EQ(j["damaged_records_recomputed"], 1);
  EXPECT_EQ(j["reused_evaluations"], 4);  // the damaged one was computed again
  EXPECT_EQ(j["evaluations"], 5);
  EXPECT_EQ(j["best"], before["best"]);  // reused, the damaged row would have been the best
  EXPECT_NE(resumed.err.find("1 recorded evaluation failed its checksum and was recomputed"), std::string::npos)
      << resumed.err;
  EXPECT_NE(read_text(out + "/report.md").find("1 recorded evaluation failed its checksum and was recomputed"),
            std::string::npos);
}

}  // namespace

namespace {

// A study file must never run commands: a line break in the study's name
// that would end a gnuplot statement and start `system(...)` in every plot
// script stays inside the title; the run succeeds and shows the name on one line.
TEST(RunCli, AStudyNameRunsNoCommand) {
  const std::string dir = scratch_dir("name_injection");
  const std::string owned = fs::absolute(dir + "/owned").string();
  const std::string path = dir + "/hostile.yaml";
  std::ofstream(path) << "study: {name: \"pwn\\nsystem(\\\"touch " << owned << "\\\")\\n`touch " << owned
                      << "` @x\", kind: optimize}\n"
                      << "problem: " << RACKOPT_SOURCE_DIR << "/problems/rack_railway.yaml\n"
                      << "variables:\n  rack.span: {lower: 1.2 m, upper: 3 m}\n"
                      << "objectives: [stiffness_fluctuation]\n"
                      << "solver: {algorithm: LN_COBYLA, max_evaluations: 6}\n";
  const CliResult r = run_cli("run '" + path + "' --out " + dir + "/out");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(owned)) << "gnuplot ran a command from the study's name";
  const std::string shown = "study pwn system(\"touch " + owned + "\") `touch " + owned + "` @x (optimize)";
  EXPECT_NE((r.out + r.err).find(shown), std::string::npos) << r.out << r.err;
  EXPECT_TRUE(fs::exists(dir + "/out/history.gp"));
}

}  // namespace
