// `mpirun -np 2 rackopt run` and `rackopt run --ranks 2`: the same record
// and results as a serial run, a rank that cannot start is named, and the
// stops. Skipped when the build has no MPI.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_process.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace {

using namespace rackopt::test_support;
namespace fs = std::filesystem;

#if defined(RACKOPT_WITH_MPI) && defined(RACKOPT_MPIRUN)
constexpr bool kHaveMpi = true;
const std::string kMpirun = RACKOPT_MPIRUN;
#else
constexpr bool kHaveMpi = false;
const std::string kMpirun;
#endif

// As root (CI) and with more ranks than free cores, OpenMPI needs these.
const std::string kMpiEnv = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1";

struct Shell {
  int code = -1;
  std::string output;
};

// Runs `command` from the source folder under a time limit, output merged.
Shell shell(const std::string& command, int seconds = 300) {
  const std::string log = scratch_dir("mpi_shell") + "/output.log";
  const std::string full = "cd '" + std::string(RACKOPT_SOURCE_DIR) + "' && timeout -s KILL " +
                           std::to_string(seconds) + " sh -c '" + command + "' >'" + log + "' 2>&1";
  Shell r;
  const int status = std::system(full.c_str());
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.output = read_text(log);
  return r;
}

// evaluations.csv without the per-evaluation wall time.
std::vector<std::string> record_rows(const std::string& out_dir) {
  std::istringstream in(read_text(out_dir + "/evaluations.csv"));
  std::vector<std::string> rows;
  std::string line;
  std::size_t seconds_column = std::string::npos;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted) {
        cells.push_back(cell);
        cell.clear();
      } else {
        cell += c;
      }
    }
    cells.push_back(cell);
    if (seconds_column == std::string::npos) {
      for (std::size_t i = 0; i < cells.size(); ++i)
        if (cells[i] == "seconds_s") seconds_column = i;
    }
    std::string row;
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (i != seconds_column) row += cells[i] + ",";
    rows.push_back(row);
  }
  return rows;
}

TEST(MpiCli, TwoRanksGiveTheRecordOfASerialRun) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  struct Case {
    std::string study, sets;
  };
  const std::vector<Case> cases = {
      {"studies/spall_severity_sweep.yaml", ""},  // a sweep: chunks of designs
      {"studies/ship_lift_four_objectives.yaml",  // NSGA-II: generations
       "--set solver.population=24 --set solver.max_evaluations=192 --set pareto.points=8"},
      {"studies/rack_railway_sizing.yaml",  // Ipopt: batches of finite-difference probes
       "--set solver.library=ipopt --set solver.max_evaluations=40"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.study);
    const std::string serial = scratch_path("mpi_serial"), ranks = scratch_path("mpi_ranks");
    const Shell s = shell(std::string(RACKOPT_CLI) + " run " + c.study + " " + c.sets + " --out " + serial);
    ASSERT_EQ(s.code, 0) << s.output;
    const Shell m = shell(kMpiEnv + " " + kMpirun + " -np 2 " + std::string(RACKOPT_CLI) + " run " + c.study + " " +
                          c.sets + " --out " + ranks);
    ASSERT_EQ(m.code, 0) << m.output;
    const auto a = record_rows(serial), b = record_rows(ranks);
    ASSERT_GT(a.size(), 10u);
    EXPECT_EQ(a, b);
    // Rank 0 alone writes: one report, one store.
    EXPECT_TRUE(fs::exists(ranks + "/report.md"));
    EXPECT_TRUE(fs::exists(ranks + "/evaluations.sqlite"));
  }
}

TEST(MpiCli, AReliabilityStudysMonteCarloIsSharedByTheRanksWithTheSameSamples) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string study = "studies/ship_lift_reliability.yaml --set metric_options.reliability_samples=300";
  const std::string serial = scratch_path("mpi_mc_serial"), ranks = scratch_path("mpi_mc_ranks");
  const Shell s = shell(std::string(RACKOPT_CLI) + " run " + study + " --out " + serial);
  ASSERT_EQ(s.code, 0) << s.output;
  const Shell m =
      shell(kMpiEnv + " " + kMpirun + " -np 2 " + std::string(RACKOPT_CLI) + " run " + study + " --out " + ranks);
  ASSERT_EQ(m.code, 0) << m.output;
  // Every sample's life and criterion, in order, and the summary built on them.
  const std::string lives = read_text(serial + "/life_samples.csv");
  EXPECT_GT(std::count(lives.begin(), lives.end(), '\n'), 300);
  EXPECT_EQ(lives, read_text(ranks + "/life_samples.csv"));
  EXPECT_EQ(read_text(serial + "/reliability.csv"), read_text(ranks + "/reliability.csv"));
  // ... computed by both ranks.
  EXPECT_NE(read_text(ranks + "/report.md").find("on each of 2 MPI ranks"), std::string::npos);
  EXPECT_EQ(read_text(serial + "/report.md").find("MPI ranks"), std::string::npos);
}

TEST(MpiCli, ARankThatCannotLoadTheStudyIsNamedAndNothingIsWritten) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string out = scratch_path("mpi_refused");
  // Two programs in one job (MPMD): rank 1 is given a study that is not there.
  const Shell m = shell(kMpiEnv + " " + kMpirun + " -np 1 " + std::string(RACKOPT_CLI) +
                        " run studies/spall_severity_sweep.yaml --out " + out + " : -np 1 " + RACKOPT_CLI +
                        " run studies/no_such_study.yaml --out " + out);
  EXPECT_EQ(m.code, 1) << m.output;
  EXPECT_NE(m.output.find("MPI rank 1 could not start"), std::string::npos) << m.output;
  EXPECT_NE(m.output.find("no_such_study.yaml"), std::string::npos) << m.output;
  EXPECT_FALSE(fs::exists(out + "/evaluations.sqlite"));
}

TEST(MpiCli, AKilledRunResumesWithNothingRepeatedAndNothingLost) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string serial = scratch_path("mpi_kill_serial"), ranks = scratch_path("mpi_kill_ranks");
  // NSGA-II, about 4 ms a design: the kill lands inside the run.
  const std::string study =
      "studies/ship_lift_four_objectives.yaml --set solver.population=24 --set solver.max_evaluations=960 "
      "--set pareto.points=8";
  ASSERT_EQ(shell(std::string(RACKOPT_CLI) + " run " + study + " --out " + serial).code, 0);
  // Killed (SIGKILL, the whole job) once rank 0 has committed rows: the
  // store's write-ahead log has grown by a few pages.
  const std::string wal = ranks + "/evaluations.sqlite-wal";
  const Shell killed = shell(kMpiEnv + " " + kMpirun + " -np 2 " + std::string(RACKOPT_CLI) + " run " + study +
                             " --out " + ranks + " & job=$!; " + "for i in $(seq 600); do [ -s " + wal +
                             " ] && [ $(stat -c %s " + wal + ") -gt 65536 ] && break; sleep 0.05; done; kill -9 $job; " +
                             "pkill -9 -f \"" + ranks + "\"; wait $job; true");
  (void)killed;
  const Shell resumed =
      shell(kMpiEnv + " " + kMpirun + " -np 2 " + std::string(RACKOPT_CLI) + " run " + study + " --out " + ranks +
            " --resume");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  // The kill came in the middle: some designs were in the store, some not.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(resumed.output, m, std::regex(R"(evaluations: (\d+) \(\d+ failed, (\d+) from the store\))")))
      << resumed.output;
  const long total = std::stol(m[1]), reused = std::stol(m[2]);
  EXPECT_GT(reused, 0);
  EXPECT_LT(reused, total);
  EXPECT_EQ(record_rows(serial), record_rows(ranks));
}

// Rank 0 owns the stop: SIGINT to rank 0 (what a Ctrl-C is to `rackopt run`
// alone) while a design's Monte Carlo life at R runs on the ranks. Every
// rank stops, rank 0 writes the whole stopped report, and mpirun ends with
// rank 0's exit status, 130. (A SIGINT to mpirun itself is OpenMPI's:
// docs/output.md, "Ctrl-C and SIGTERM".)
TEST(MpiCli, SigintToRankZeroStopsEveryRankWithTheStoppedReport) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string out = scratch_path("mpi_sigint"), printed = scratch_dir("mpi_sigint_json") + "/stdout.json";
  const std::string study =
      "studies/gantry_sizing.yaml --set metric_options.exact_quantile=off --set metric_options.reliability_samples=2000 "
      "--set output.plots=off";
  const std::string wal = out + "/evaluations.sqlite-wal";
  // Once the store has rows (its write-ahead log is not empty), SIGINT to
  // the child of mpirun whose environment says it is rank 0 (none found:
  // the job is killed, and the test fails without waiting for the study).
  const Shell m = shell(kMpiEnv + " " + kMpirun + " -np 2 " + std::string(RACKOPT_CLI) + " run " + study +
                        " --json --out " + out + " >" + printed + " & job=$!; " +
                        "for i in $(seq 1200); do [ -s " + wal + " ] && break; sleep 0.05; done; sleep 1; " +
                        "sent=0; for p in $(pgrep -P $job); do grep -qxz OMPI_COMM_WORLD_RANK=0 /proc/$p/environ && "
                        "kill -INT $p && sent=1; done; [ $sent = 1 ] || kill -KILL $job; "
                        "wait $job; echo mpirun_exit=$?");
  EXPECT_NE(m.output.find("mpirun_exit=130"), std::string::npos) << m.output;
  ASSERT_TRUE(fs::exists(out + "/summary.json")) << m.output;
  const auto summary = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(summary["status"], "stopped");
  EXPECT_EQ(nlohmann::json::parse(read_text(printed)), summary);
  EXPECT_NE(read_text(out + "/report.md").find("stopped"), std::string::npos);
}

// A SIGINT to mpirun itself: OpenMPI aborts the job (exit status 1, its
// own), sends every rank SIGTERM a second later and SIGKILL a second after
// that. The workers leave the stop to rank 0, which writes the whole stopped
// report in that second (a sweep of 4 ms designs, plots skipped when
// stopped).
TEST(MpiCli, SigintToMpirunLeavesTheWholeStoppedReport) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string out = scratch_path("mpi_sigint_mpirun");
  const std::string wal = out + "/evaluations.sqlite-wal";
  const Shell m = shell(kMpiEnv + " " + kMpirun + " -np 2 " + std::string(RACKOPT_CLI) +
                        " run studies/spall_severity_sweep.yaml --set sweep.levels=40 --out " + out + " & job=$!; " +
                        "for i in $(seq 1200); do [ -s " + wal + " ] && break; sleep 0.05; done; sleep 1; " +
                        "kill -INT $job; wait $job; echo mpirun_exit=$?");
  EXPECT_NE(m.output.find("mpirun_exit=1\n"), std::string::npos) << m.output;
  ASSERT_TRUE(fs::exists(out + "/summary.json")) << m.output;
  const auto summary = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(summary["status"], "stopped");
  EXPECT_LT(summary["evaluations"].get<long>(), 6400);
  EXPECT_NE(read_text(out + "/report.md").find("stopped"), std::string::npos);
}

// The stop to send mpirun itself: SIGUSR1, which mpirun forwards to every
// rank (a SIGINT or SIGTERM it keeps for its own abort, exit status 1).
// Rank 0 takes it as its stop, the workers ignore it, and mpirun ends with
// rank 0's status, 130, after the whole stopped report.
TEST(MpiCli, SigusrOneToMpirunStopsEveryRankWithTheStoppedReportAndExit130) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string out = scratch_path("mpi_sigusr1_mpirun"), printed = scratch_dir("mpi_sigusr1_json") + "/stdout.json";
  const std::string wal = out + "/evaluations.sqlite-wal";
  const Shell m = shell(kMpiEnv + " " + kMpirun + " -np 2 " + std::string(RACKOPT_CLI) +
                            " run studies/spall_severity_sweep.yaml --set sweep.levels=40 --json --out " + out + " >" +
                            printed + " & job=$!; " + "for i in $(seq 1200); do [ -s " + wal +
                            " ] && break; sleep 0.05; done; sleep 1; " + "kill -USR1 $job; wait $job; echo mpirun_exit=$?",
                        180);
  EXPECT_NE(m.output.find("mpirun_exit=130\n"), std::string::npos) << m.output;
  ASSERT_TRUE(fs::exists(out + "/summary.json")) << m.output;
  const auto summary = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(summary["status"], "stopped");
  EXPECT_LT(summary["evaluations"].get<long>(), 6400);
  EXPECT_EQ(nlohmann::json::parse(read_text(printed)), summary);
  EXPECT_NE(read_text(out + "/report.md").find("stopped"), std::string::npos);
}

// `rackopt run --ranks 2` starts mpirun -np 2 with this program and the
// other options as they were given (an argv, no shell: a folder name with
// two spaces and a '*' arrives whole), and the record is a serial run's.
TEST(MpiCli, RanksOptionRunsMpirunWithTheOptionsUnchangedAndGivesTheRecordOfASerialRun) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string dir = scratch_dir("mpi_ranks_option");
  const std::string serial = dir + "/serial", ranks = dir + "/ranks  out*";
  // An mpirun that writes the arguments it was given, one a line, then is mpirun.
  const std::string logger = dir + "/mpirun_logger.sh";
  {
    std::ofstream f(logger);
    f << "#!/bin/sh\nprintf '%s\\n' \"$@\" >\"" << dir << "/mpirun_args.txt\"\nexec " << kMpirun << " \"$@\"\n";
  }
  fs::permissions(logger, fs::perms::owner_all);
  const std::string study = "studies/spall_severity_sweep.yaml";
  ASSERT_EQ(shell(std::string(RACKOPT_CLI) + " run " + study + " --out " + serial).code, 0);
  const Shell m = shell(kMpiEnv + " RACKOPT_MPIRUN=" + logger + " " + RACKOPT_CLI + " run " + study +
                        " --ranks 2 --set sweep.levels=6 --ranks=2 --out \"" + ranks + "\" --json");
  ASSERT_EQ(m.code, 0) << m.output;
  EXPECT_EQ(record_rows(serial), record_rows(ranks));
  EXPECT_EQ(nlohmann::json::parse(read_text(ranks + "/summary.json"))["status"], "ok");
  const std::string expected = "-np\n2\n" + fs::canonical(RACKOPT_CLI).string() + "\nrun\n" + study +
                               "\n--set\nsweep.levels=6\n--out\n" + ranks + "\n--json\n";
  EXPECT_EQ(read_text(dir + "/mpirun_args.txt"), expected);
}

// --ranks 1 runs in this process (no mpirun, not even a missing one);
// --ranks 0 and a missing mpirun are exit 2 with a message that says why;
// an mpirun that fails on its own is exit 1 (with --json its one object).
TEST(MpiCli, RanksOptionRefusesZeroAndAMissingMpirunAndRunsOneRankInProcess) {
  const std::string fake = "RACKOPT_MPIRUN=/no/such/mpirun ";
  const std::string study = std::string(RACKOPT_CLI) + " run studies/spall_severity_sweep.yaml";
  const Shell zero = shell(study + " --ranks 0 --out " + scratch_path("mpi_ranks_zero"));
  EXPECT_EQ(zero.code, 2) << zero.output;
  EXPECT_NE(zero.output.find("--ranks needs a whole number in 1..65536, got '0'"), std::string::npos) << zero.output;
  const Shell missing = shell(fake + study + " --ranks 2 --json --out " + scratch_path("mpi_ranks_missing"));
  EXPECT_EQ(missing.code, 2) << missing.output;
  EXPECT_NE(missing.output.find("\"error\":\"mpi_unavailable\""), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find(kHaveMpi ? "/no/such/mpirun" : "built with MPI"), std::string::npos) << missing.output;
  const std::string one_out = scratch_path("mpi_ranks_one");
  const Shell one = shell(fake + study + " --ranks 1 --out " + one_out);
  EXPECT_EQ(one.code, 0) << one.output;
  EXPECT_TRUE(fs::exists(one_out + "/summary.json"));
  if (kHaveMpi) {
    // An mpirun that fails before rank 0 printed: --json still prints one object.
    const Shell failed = shell("RACKOPT_MPIRUN=false " + study + " --ranks 2 --json --out " +
                               scratch_path("mpi_ranks_failed") + " 2>/dev/null");
    EXPECT_EQ(failed.code, 1) << failed.output;
    const auto object = nlohmann::json::parse(failed.output);
    EXPECT_EQ(object["error"], "run");
    EXPECT_NE(object["message"].get<std::string>().find("mpirun ended with status 1 before rank 0 printed"),
              std::string::npos);
  }
  if (kHaveMpi) {  // under mpirun, --ranks is mpirun's -np
    const Shell nested = shell(kMpiEnv + " " + kMpirun + " -np 1 " + study + " --ranks 2 --out " +
                               scratch_path("mpi_ranks_nested"));
    EXPECT_NE(nested.code, 0) << nested.output;
    EXPECT_NE(nested.output.find("under mpirun leave it out"), std::string::npos) << nested.output;
  }
}

// A Ctrl-C in the terminal goes to the foreground process group: here the
// whole group of the --ranks program (setsid makes one), as a terminal would
// send it. mpirun, in a group of its own, does not get it; the program
// forwards it as SIGUSR1, every rank stops, rank 0 writes the whole stopped
// report, and the exit status is 130. `--resume` then completes the study
// from the store. (Mirrors SigusrOneToMpirunStopsEveryRankWithTheStoppedReportAndExit130.)
TEST(MpiCli, CtrlCToRanksOptionStopsWithTheStoppedReportAndExit130AndResumeCompletes) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string out = scratch_path("mpi_ranks_ctrl_c"), printed = scratch_dir("mpi_ranks_ctrl_c_json") + "/stdout.json";
  const std::string wal = out + "/evaluations.sqlite-wal";
  // 30 x 30 x 4 designs of about 4 ms: the stop lands after a few hundred.
  const std::string run = std::string(RACKOPT_CLI) + " run studies/spall_severity_sweep.yaml --set sweep.levels=30 " +
                          "--ranks 2 --json --out " + out;
  const Shell m = shell(kMpiEnv + " setsid " + run + " >" + printed + " & job=$!; " + "for i in $(seq 1200); do [ -s " +
                            wal + " ] && break; sleep 0.05; done; sleep 1; " +
                            "kill -INT -$job; wait $job; echo rackopt_exit=$?",
                        180);
  EXPECT_NE(m.output.find("rackopt_exit=130\n"), std::string::npos) << m.output;
  // The 130 is mpirun's own (rank 0's status), not ours after mpirun aborted
  // the job on a SIGINT of its own.
  EXPECT_EQ(m.output.find("mpirun ended with status"), std::string::npos) << m.output;
  ASSERT_TRUE(fs::exists(out + "/summary.json")) << m.output;
  const auto summary = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(summary["status"], "stopped");
  const long stopped_at = summary["evaluations"].get<long>();
  EXPECT_LT(stopped_at, 3600);
  EXPECT_EQ(nlohmann::json::parse(read_text(printed)), summary);
  EXPECT_NE(read_text(out + "/report.md").find("stopped"), std::string::npos);

  const Shell resumed = shell(kMpiEnv + " " + run + " --resume", 180);
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  const auto done = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(done["status"], "ok");
  EXPECT_EQ(done["evaluations"].get<long>(), 3600);
  std::smatch r;
  ASSERT_TRUE(std::regex_search(resumed.output, r, std::regex(R"(\((\d+) failed, (\d+) from the store\))")))
      << resumed.output;
  EXPECT_EQ(std::stol(r[2]), stopped_at);
}

// SIGTERM to the --ranks program (a job scheduler's or `kill`'s, to its pid
// alone) is a stop as a Ctrl-C is: forwarded, the stopped report, exit 130.
TEST(MpiCli, SigtermToRanksOptionStopsWithTheStoppedReportAndExit130) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string out = scratch_path("mpi_ranks_sigterm");
  const std::string wal = out + "/evaluations.sqlite-wal";
  const Shell m = shell(kMpiEnv + " " + RACKOPT_CLI + " run studies/spall_severity_sweep.yaml --set sweep.levels=30 " +
                            "--ranks 2 --out " + out + " & job=$!; for i in $(seq 1200); do [ -s " + wal +
                            " ] && break; sleep 0.05; done; sleep 1; kill -TERM $job; wait $job; echo rackopt_exit=$?",
                        180);
  EXPECT_NE(m.output.find("rackopt_exit=130\n"), std::string::npos) << m.output;
  EXPECT_EQ(m.output.find("mpirun ended with status"), std::string::npos) << m.output;
  ASSERT_TRUE(fs::exists(out + "/summary.json")) << m.output;
  const auto summary = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(summary["status"], "stopped");
  EXPECT_LT(summary["evaluations"].get<long>(), 3600);
}

// A second Ctrl-C is forwarded too: rank 0 ends at once (the --json error
// object, exit 130) inside a design's Monte Carlo, and no rank is left running.
TEST(MpiCli, SecondCtrlCToRanksOptionEndsAtOnceWithExit130AndNoRankLeft) {
  if (!kHaveMpi) GTEST_SKIP() << "built without MPI";
  const std::string out = scratch_path("mpi_ranks_twice"), printed = scratch_dir("mpi_ranks_twice_json") + "/stdout.json";
  const std::string wal = out + "/evaluations.sqlite-wal";
  const std::string study =
      "studies/gantry_sizing.yaml --set metric_options.exact_quantile=off --set metric_options.reliability_samples=2000 "
      "--set output.plots=off";
  const Shell m = shell(kMpiEnv + " setsid " + RACKOPT_CLI + " run " + study + " --ranks 2 --json --out " + out + " >" +
                        printed + " & job=$!; " + "for i in $(seq 1200); do [ -s " + wal +
                        " ] && break; sleep 0.05; done; sleep 1; " +
                        "kill -INT -$job; sleep 0.05; kill -INT -$job; wait $job; echo rackopt_exit=$?");
  EXPECT_NE(m.output.find("rackopt_exit=130\n"), std::string::npos) << m.output;
  EXPECT_EQ(m.output.find("mpirun ended with status"), std::string::npos) << m.output;
  // The two Ctrl-Cs race with the first one's clean stop: either the second
  // ended rank 0 at once (the JSON error object) or the first had already
  // written the stopped report; one JSON object and exit 130 either way.
  const auto printed_json = nlohmann::json::parse(read_text(printed));
  if (printed_json.contains("error")) {
    EXPECT_EQ(printed_json["error"], "interrupted");
    EXPECT_NE(m.output.find("stopped at once"), std::string::npos) << m.output;
  } else {
    EXPECT_EQ(printed_json["status"], "stopped") << read_text(printed);
  }
  // "[m]pi_ranks_twice": the pattern does not match the shell that runs pgrep.
  const std::string left = shell("pgrep -f \"[m]pi_ranks_twice\" || true").output;
  EXPECT_EQ(left, "") << left;
}

}  // namespace
