// Running the rackopt program as a user does: from the source folder,
// through /bin/sh (so `args` and `env` are shell words), with its exit code,
// stdout and stderr captured.
#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>

#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt::test_support {

struct CliResult {
  int code = -1;        // exit status; 128 + the signal when a signal ended it, as a shell says
  std::string out;      // stdout; with merge_stderr, stderr interleaved as written
  std::string err;      // stderr; "" with merge_stderr
  double seconds = 0;   // wall time from start to exit
};

struct CliOptions {
  std::string env;            // "A=1 B='x y'": set for the program only
  bool merge_stderr = false;  // 2>&1: messages in their order relative to stdout
  // > 0: no file of the program or its children may grow past this many
  // bytes (RLIMIT_FSIZE, SIGXFSZ ignored): writes past it fail with EFBIG,
  // as on a full disk. The captured stdout and stderr are files too.
  long file_size_limit = 0;
};

// Starts the program with `args` in the background, stdout to `out_file`
// and stderr to `err_file` (both to `out_file` with merge_stderr), so a test
// can watch them while it runs. Returns its pid (the shell execs it).
inline pid_t start_cli(const std::string& args, const std::string& out_file, const std::string& err_file,
                       const CliOptions& options = {}) {
  const std::string redirect =
      " >'" + out_file + "'" + (options.merge_stderr ? std::string(" 2>&1") : " 2>'" + err_file + "'");
  const std::string cmd = "cd '" + std::string(RACKOPT_SOURCE_DIR) + "' && " + options.env + " exec '" + RACKOPT_CLI +
                          "' " + args + redirect;
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (options.file_size_limit > 0) {
      const rlimit lim{static_cast<rlim_t>(options.file_size_limit), static_cast<rlim_t>(options.file_size_limit)};
      ::setrlimit(RLIMIT_FSIZE, &lim);
      ::signal(SIGXFSZ, SIG_IGN);
    }
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

// Waits for `pid`: its exit status, or 128 + the signal that ended it.
inline int wait_exit(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

// Waits for a program start_cli started and collects what it wrote;
// `started` is when the time in `seconds` counts from.
inline CliResult finish_cli(pid_t pid, const std::string& out_file, const std::string& err_file,
                            std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now()) {
  CliResult r;
  r.code = wait_exit(pid);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  r.out = read_text(out_file);
  r.err = read_text(err_file);
  return r;
}

// Runs the program with `args` and waits for it.
inline CliResult run_cli(const std::string& args, const CliOptions& options = {}) {
  static std::atomic<long> runs{0};
  const std::filesystem::path folder = scratch_root() / "cli_output";
  std::filesystem::create_directories(folder);
  const std::string stem = (folder / std::to_string(runs++)).string();
  const std::string out_file = stem + ".stdout", err_file = stem + ".stderr";
  const auto t0 = std::chrono::steady_clock::now();
  CliResult r = finish_cli(start_cli(args, out_file, err_file, options), out_file, err_file, t0);
  std::filesystem::remove(out_file);
  std::filesystem::remove(err_file);
  return r;
}

}  // namespace rackopt::test_support
