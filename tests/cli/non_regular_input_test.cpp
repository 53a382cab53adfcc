// A FIFO (or any file that is not a regular file) given where rackopt reads
// an input is refused at once with exit 2 and a message naming the file: a
// FIFO without a writer would otherwise block open() for ever, out of reach
// of Ctrl-C's stop request (docs/input_limits.md). Every way in: the problem
// file of check, stiffness and wear, the study file of run, and the problem
// a study file names.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#include "support/cli_process.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace {

using namespace rackopt::test_support;

// Runs the program with `args`; a run still going after 20 s (blocked on the
// FIFO) is killed and reported as -1, so a regression fails instead of
// hanging.
CliResult run_cli_bounded(const std::string& args, const std::string& dir) {
  const std::string out_file = dir + "/stdout.txt", err_file = dir + "/stderr.txt";
  const pid_t pid = start_cli(args, out_file, err_file);
  const auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(20)) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      CliResult r;
      r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      r.out = read_text(out_file);
      r.err = read_text(err_file);
      return r;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGKILL);
  wait_exit(pid);
  CliResult r;
  r.err = "still running after 20 s (blocked on the FIFO): " + read_text(err_file);
  return r;
}

std::string make_fifo(const std::string& dir, const std::string& name) {
  const std::string path = dir + "/" + name;
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
  return path;
}

void expect_refused_as_fifo(const CliResult& r, const std::string& fifo) {
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(fifo), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("FIFO"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
}

TEST(NonRegularInput, AFifoAsTheProblemFileIsRefusedByEveryCommand) {
  const std::string dir = scratch_dir("fifo_problem");
  const std::string fifo = make_fifo(dir, "problem.yaml");
  for (const std::string command : {"check", "stiffness", "wear"}) {
    SCOPED_TRACE(command);
    const std::string out = command == "check" ? std::string() : " --out " + dir + "/" + command;
    expect_refused_as_fifo(run_cli_bounded(command + " '" + fifo + "'" + out, dir), fifo);
  }
}

TEST(NonRegularInput, AFifoAsTheStudyFileIsRefusedAndNothingIsWritten) {
  const std::string dir = scratch_dir("fifo_study");
  const std::string fifo = make_fifo(dir, "study.yaml");
  const CliResult r = run_cli_bounded("run '" + fifo + "' --out " + dir + "/out", dir);
  expect_refused_as_fifo(r, fifo);
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/summary.json"));
}

TEST(NonRegularInput, AFifoAsTheProblemAStudyNamesIsRefused) {
  const std::string dir = scratch_dir("fifo_study_problem");
  const std::string fifo = make_fifo(dir, "problem.yaml");
  const std::string study = dir + "/study.yaml";
  std::ofstream(study) << "study: {name: fifo problem, kind: evaluate}\n"
                       << "problem: " << fifo << "\n"
                       << "objectives: [stiffness_fluctuation]\n";
  expect_refused_as_fifo(run_cli_bounded("run '" + study + "' --out " + dir + "/out", dir), fifo);
}

TEST(NonRegularInput, ACharacterDeviceIsRefusedNamingItsKind) {
  const CliResult r = run_cli_bounded("check /dev/null", scratch_dir("device_problem"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("/dev/null"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("character device"), std::string::npos) << r.err;
}

}  // namespace
