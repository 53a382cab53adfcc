#include "forwarding_child.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>

#include <fcntl.h>
#include <poll.h>
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

// Copies `from` to our stdout until it ends, or until the child `pid` has
// ended and nothing more is waiting (a process the child left behind may
// hold the pipe open). Whether anything came.
bool relay(int from, pid_t pid) {
  bool any = false;
  char buf[65536];
  for (;;) {
    pollfd p{from, POLLIN, 0};
    const int ready = ::poll(&p, 1, 100);
    if (ready < 0 && errno != EINTR) return any;
    if (ready > 0) {
      const ssize_t n = ::read(from, buf, sizeof buf);
      if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) return any;
      for (ssize_t done = 0; n > 0 && done < n;) {
        const ssize_t w = ::write(STDOUT_FILENO, buf + done, static_cast<std::size_t>(n - done));
        if (w < 0 && errno != EINTR) break;  // our stdout is gone: keep draining the child's
        if (w > 0) done += w;
      }
      any = any || n > 0;
      continue;
    }
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid) {
      return any;  // ended, and the last poll found nothing left
    }
  }
}

}  // namespace

ForwardedChildOutcome run_forwarding_stops(const std::string& program, const std::vector<std::string>& arguments,
                                           int stop_as, bool relay_stdout) {
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
  int pipe_fds[2] = {-1, -1};  // close-on-exec: the child has only its dup on stdout
  if (relay_stdout && ::pipe2(pipe_fds, O_CLOEXEC) == 0) {
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  } else {
    relay_stdout = false;  // no pipe: the child writes to our stdout itself
  }
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
  if (relay_stdout) ::close(pipe_fds[1]);
  if (rc != 0) {
    out.error = "cannot start " + program + ": " + std::strerror(rc);
  } else {
    out.started = true;
    g_child.store(pid);
    ::sigprocmask(SIG_SETMASK, &saved_mask, nullptr);  // pending stops are forwarded here
    if (relay_stdout) out.printed = relay(pipe_fds[0], pid);
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
  if (relay_stdout) ::close(pipe_fds[0]);
  out.stop_signal = g_first.load();
  ::sigaction(SIGINT, &saved_int, nullptr);
  ::sigaction(SIGTERM, &saved_term, nullptr);
  ::sigprocmask(SIG_SETMASK, &saved_mask, nullptr);
  return out;
}

}  // namespace rackopt::cli
