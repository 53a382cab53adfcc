#include "forwarding_child.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rackopt::cli {
namespace {

// Read by the handler: only lock-free atomics and kill() there.
std::atomic<pid_t> g_child{0};
std::atomic<int> g_stop_as{SIGUSR1};
std::atomic<int> g_count{0};
std::atomic<int> g_first{0};

extern "C" void forward_stop(int sig) {
  const int n = g_count.fetch_add(1) + 1;
  int none = 0;
  g_first.compare_exchange_strong(none, sig);
  const pid_t child = g_child.load();
  if (child > 0) ::kill(child, n <= 2 ? g_stop_as.load() : SIGTERM);
}

}  // namespace

ForwardedChildOutcome run_forwarding_stops(const std::string& program, const std::vector<std::string>& arguments,
                                           int stop_as) {
  ForwardedChildOutcome out;
  g_child.store(0);
  g_stop_as.store(stop_as);
  g_count.store(0);
  g_first.store(0);

  // Blocked from before the handler is installed until the child's pid is
  // known, so that a signal in between is forwarded (when unblocked), not lost.
  sigset_t stops, saved_mask;
  sigemptyset(&stops);
  sigaddset(&stops, SIGINT);
  sigaddset(&stops, SIGTERM);
  ::sigprocmask(SIG_BLOCK, &stops, &saved_mask);
  struct sigaction sa{}, saved_int{}, saved_term{};
  sa.sa_handler = forward_stop;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &sa, &saved_int);
  ::sigaction(SIGTERM, &sa, &saved_term);

  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  posix_spawn_file_actions_init(&actions);
  posix_spawnattr_init(&attr);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawnattr_setpgroup(&attr, 0);
  // A shell starts a background command with SIGINT ignored; the child must
  // not inherit that, nor our blocked mask.
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigaddset(&defaults, SIGUSR1);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

  std::vector<std::string> args;
  args.push_back(program);
  args.insert(args.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  pid_t pid = -1;
  const int rc = posix_spawn(&pid, program.c_str(), &actions, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) {
    out.error = "cannot start " + program + ": " + std::strerror(rc);
  } else {
    out.started = true;
    g_child.store(pid);
    ::sigprocmask(SIG_SETMASK, &saved_mask, nullptr);  // pending stops are forwarded here
    // Wait without reaping, so that the handler never signals a pid the
    // system could already have given to another process.
    siginfo_t info{};
    while (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
    }
    ::sigprocmask(SIG_BLOCK, &stops, nullptr);
    g_child.store(0);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 1;
  }
  out.stop_signal = g_first.load();
  ::sigaction(SIGINT, &saved_int, nullptr);
  ::sigaction(SIGTERM, &saved_term, nullptr);
  ::sigprocmask(SIG_SETMASK, &saved_mask, nullptr);
  return out;
}

}  // namespace rackopt::cli
