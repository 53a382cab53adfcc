#include "rackopt/output/plot.hpp"

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
#include "rackopt/output/atomic_file.hpp"

extern char** environ;

namespace rackopt {
namespace {

namespace fs = std::filesystem;

// `program` as an absolute path: as given when it has a slash (made
// absolute, gnuplot runs in another folder), else the first executable of
// that name on PATH; "" when there is none.
std::string find_program(const std::string& program) {
  if (program.find('/') != std::string::npos) {
    std::error_code ec;
    const fs::path p = fs::absolute(program, ec);
    return !ec && ::access(p.c_str(), X_OK) == 0 ? p.string() : std::string();
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

std::string seconds_text(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

}  // namespace

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

double plot_time_limit_seconds() {
  const char* env = std::getenv("RACKOPT_PLOT_TIMEOUT");
  if (env != nullptr && *env != '\0') {
    char* end = nullptr;
    const double v = std::strtod(env, &end);
    if (end != env && *end == '\0' && v > 0) return v;
  }
  return 60.0;
}

std::string render_plot(const std::string& dir_name, const std::string& script, const std::string& png,
                        std::vector<std::string>& warnings) {
  const fs::path dir(dir_name.empty() ? std::string(".") : dir_name);
  const std::string png_path = (dir / png).string();
  const std::string tmp_path = png_path + ".tmp";
  const char* env = std::getenv("RACKOPT_GNUPLOT");
  const std::string program = env != nullptr && *env != '\0' ? env : "gnuplot";
  const std::string exe = find_program(program);
  if (exe.empty()) {
    warnings.push_back(program + " not found: wrote " + (dir / script).string() + " but no plot (install gnuplot-nox)");
    return "";
  }
  if (stop_requested()) {
    warnings.push_back("plot " + png_path + " not drawn: stopped by " + stop_reason());
    return "";
  }
  std::error_code ec;
  fs::remove(tmp_path, ec);  // a stale image from a killed run must not be taken for ours
  const TemporaryFileGuard guard(tmp_path);
  const std::string log = script + ".log";

  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  posix_spawn_file_actions_init(&actions);
  posix_spawnattr_init(&attr);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // Its own process group: a terminal's Ctrl-C reaches only us, and we end
  // the whole group (gnuplot and anything it started) ourselves.
  posix_spawnattr_setpgroup(&attr, 0);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::string arg0 = exe, arg1 = script;
  char* argv[] = {arg0.data(), arg1.data(), nullptr};
  pid_t pid = -1;
  const int spawn_rc = posix_spawn(&pid, exe.c_str(), &actions, &attr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (spawn_rc != 0) {
    warnings.push_back("plot " + png_path + " not drawn: cannot start " + exe + ": " + std::strerror(spawn_rc));
    return "";
  }
  set_child_process_group(pid);

  const double limit = plot_time_limit_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  std::string failure;
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) {
      failure = std::string("lost gnuplot: ") + std::strerror(errno);
      break;
    }
    const bool stop = stop_requested();
    const bool late = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > limit;
    if (stop || late) {
      ::kill(-pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      failure = stop ? "stopped by " + stop_reason()
                     : "gnuplot did not finish within " + seconds_text(limit) +
                           " s (RACKOPT_PLOT_TIMEOUT) and was killed";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  set_child_process_group(0);
  ::kill(-pid, SIGKILL);  // anything gnuplot left running in its group

  if (failure.empty() && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
    failure = "gnuplot failed on " + script + ": see " + (dir / log).string();
  }
  if (failure.empty()) {
    const std::string why = publish_verified(tmp_path, png_path);
    if (!why.empty()) failure = "the image gnuplot wrote is not valid (" + why + ")";
  }
  if (!failure.empty()) {
    fs::remove(tmp_path, ec);
    if (fs::exists(dir / log, ec) && fs::file_size(dir / log, ec) == 0) fs::remove(dir / log, ec);  // nothing to see
    warnings.push_back("plot " + png_path + " not drawn: " + failure);
    return "";
  }
  fs::remove(dir / log, ec);
  return png_path;
}

}  // namespace rackopt
