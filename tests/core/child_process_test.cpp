// The shared child-process runner (gnuplot, CalculiX): exit status, working
// folder, output files, environment, time limit and the stop request.
#include "rackopt/core/child_process.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "rackopt/core/interrupt.hpp"

namespace rackopt {
namespace {

namespace fs = std::filesystem;

struct Folder {
  fs::path path;
  Folder() {
    std::string pattern = (fs::temp_directory_path() / "rackopt-child-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp");
    path = pattern;
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ChildCommand shell(const std::string& script, const fs::path& dir) {
  ChildCommand c;
  c.program = find_program("sh");
  c.arguments = {"-c", script};
  c.working_dir = dir.string();
  return c;
}

TEST(ChildProcess, FindsProgramsOnPathAndByPath) {
  EXPECT_FALSE(find_program("sh").empty());
  EXPECT_EQ(find_program("sh").front(), '/');
  EXPECT_EQ(find_program("rackopt-no-such-program"), "");
  EXPECT_EQ(find_program("/nonexistent/sh"), "");
  EXPECT_EQ(find_program(""), "");
}

TEST(ChildProcess, RunsInItsFolderWithOutputFilesAndEnvironment) {
  const Folder dir;
  ChildCommand c = shell("pwd; echo \"$RACKOPT_CHILD_TEST\"; echo oops >&2; exit 3", dir.path);
  c.stdout_file = "out.log";
  c.stderr_file = "err.log";
  c.environment = {"RACKOPT_CHILD_TEST=hello"};
  const ChildOutcome o = run_child(c);
  EXPECT_EQ(o.kind, ChildOutcome::Kind::exited);
  EXPECT_EQ(o.exit_code, 3);
  EXPECT_FALSE(o.ok());
  EXPECT_EQ(read(dir.path / "out.log"), fs::canonical(dir.path).string() + "\nhello\n");
  EXPECT_EQ(read(dir.path / "err.log"), "oops\n");
  c.stderr_file = "out.log";  // one file for both
  run_child(c);
  EXPECT_NE(read(dir.path / "out.log").find("oops"), std::string::npos);
}

TEST(ChildProcess, TimeLimitKillsTheGroup) {
  const Folder dir;
  ChildCommand c = shell("sleep 30 & sleep 30", dir.path);
  c.time_limit_seconds = 0.2;
  const auto t0 = std::chrono::steady_clock::now();
  const ChildOutcome o = run_child(c);
  EXPECT_EQ(o.kind, ChildOutcome::Kind::timed_out);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
}

TEST(ChildProcess, StopRequestEndsItWhileItRuns) {
  const Folder dir;
  std::thread stopper([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    request_stop();
  });
  const auto t0 = std::chrono::steady_clock::now();
  const ChildOutcome o = run_child(shell("sleep 30", dir.path));
  stopper.join();
  clear_stop_request();
  EXPECT_EQ(o.kind, ChildOutcome::Kind::stopped);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
}

TEST(ChildProcess, MissingProgramIsNotStarted) {
  ChildCommand c;
  c.program = "/nonexistent/program";
  const ChildOutcome o = run_child(c);
  EXPECT_EQ(o.kind, ChildOutcome::Kind::not_started);
  EXPECT_NE(o.message.find("/nonexistent/program"), std::string::npos);
}

}  // namespace
}  // namespace rackopt
