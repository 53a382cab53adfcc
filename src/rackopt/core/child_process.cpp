#include "rackopt/core/child_process.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "rackopt/core/interrupt.hpp"

extern char** environ;

namespace rackopt {

namespace fs = std::filesystem;

std::string find_program(const std::string& program) {
  if (program.empty()) return "";
  if (program.find('/') != std::string::npos) {
    std::error_code ec;
    const fs::path p = fs::absolute(program, ec);
    return !ec && ::access(p.c_str(), X_OK) == 0 && !fs::is_directory(p, ec) ? p.string() : std::string();
  }
  const char* path_env = std::getenv("PATH");
  std::stringstream dirs(path_env != nullptr ? path_env : "/usr/local/bin:/usr/bin:/bin");
  std::string d;
  while (std::getline(dirs, d, ':')) {
    const fs::path candidate = fs::path(d.empty() ? "." : d) / program;
    std::error_code ec;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate, ec)) return fs::absolute(candidate, ec).string();
  }
  return "";
}

ChildOutcome run_child(const ChildCommand& command) {
  ChildOutcome out;
  if (stop_requested()) {
    out.kind = ChildOutcome::Kind::stopped;
    out.message = stop_reason();
    return out;
  }
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  posix_spawn_file_actions_init(&actions);
  posix_spawnattr_init(&attr);
  // The opens below come after the chdir: relative log names are the child's.
  posix_spawn_file_actions_addchdir_np(&actions, command.working_dir.empty() ? "." : command.working_dir.c_str());
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  const auto redirect = [&](int fd, const std::string& file) {
    if (file.empty()) {
      posix_spawn_file_actions_addopen(&actions, fd, "/dev/null", O_WRONLY, 0);
    } else {
      posix_spawn_file_actions_addopen(&actions, fd, file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    }
  };
  redirect(STDOUT_FILENO, command.stdout_file);
  if (!command.stderr_file.empty() && command.stderr_file == command.stdout_file) {
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  } else {
    redirect(STDERR_FILENO, command.stderr_file);
  }
  // Its own process group: a terminal's Ctrl-C reaches only us, and we end
  // the whole group (the child and anything it started) ourselves.
  posix_spawnattr_setpgroup(&attr, 0);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

  std::vector<std::string> args;
  args.push_back(command.program);
  args.insert(args.end(), command.arguments.begin(), command.arguments.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_store = command.environment;
  std::vector<char*> envp;
  for (std::string& e : env_store) envp.push_back(e.data());
  for (char** e = environ; e != nullptr && *e != nullptr; ++e) envp.push_back(*e);
  envp.push_back(nullptr);

  pid_t pid = -1;
  const int spawn_rc = posix_spawn(&pid, command.program.c_str(), &actions, &attr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (spawn_rc != 0) {
    out.kind = ChildOutcome::Kind::not_started;
    out.message = "cannot start " + command.program + ": " + std::strerror(spawn_rc);
    return out;
  }
  set_child_process_group(pid);

  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  bool reaped = false;
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) {
      reaped = true;
      break;
    }
    if (r < 0 && errno != EINTR) break;  // lost it (cannot happen for our own child)
    const bool stop = stop_requested();
    const bool late = command.time_limit_seconds > 0 &&
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() >
                          command.time_limit_seconds;
    if (stop || late) {
      ::kill(-pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      out.kind = stop ? ChildOutcome::Kind::stopped : ChildOutcome::Kind::timed_out;
      if (stop) out.message = stop_reason();
      set_child_process_group(0);
      return out;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  set_child_process_group(0);
  ::kill(-pid, SIGKILL);  // anything the child left running in its group
  if (!reaped) {
    out.kind = ChildOutcome::Kind::signaled;
    out.message = std::string("lost the child: ") + std::strerror(errno);
  } else if (WIFEXITED(status)) {
    out.kind = ChildOutcome::Kind::exited;
    out.exit_code = WEXITSTATUS(status);
  } else {
    out.kind = ChildOutcome::Kind::signaled;
    out.message = WIFSIGNALED(status) ? std::string("killed by signal ") + std::to_string(WTERMSIG(status)) : "";
  }
  return out;
}

}  // namespace rackopt
