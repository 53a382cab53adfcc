#include "rackopt/core/interrupt.hpp"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstring>

#include <signal.h>
#include <unistd.h>

namespace rackopt {
namespace {

// Everything the handler touches is a lock-free atomic or a fixed buffer:
// only async-signal-safe calls (kill, unlink, write, _exit) happen in it.
std::atomic<int> g_signal{0};
std::atomic<bool> g_stop{false};
std::atomic<int> g_count{0};
std::atomic<pid_t> g_child_group{0};

constexpr int kSlots = 32;
constexpr std::size_t kPathMax = 4096;
// state: 0 free, 1 being filled or emptied, 2 holds a path to unlink.
std::atomic<int> g_slot_state[kSlots];
char g_slot_path[kSlots][kPathMax];

char g_notice[512];
std::size_t g_notice_len = 0;
std::atomic<int> g_immediate{0};
std::atomic<bool> g_embedded{false};  // EmbeddedStopHandlers: never end at once
char g_output[1024];
std::atomic<std::size_t> g_output_len{0};
std::size_t g_output_split = 0;  // where the signal's name goes

void say_to(int fd, const char* text, std::size_t n) {
  const ssize_t ignored = ::write(fd, text, n);
  (void)ignored;
}

void say(const char* text, std::size_t n) { say_to(STDERR_FILENO, text, n); }

extern "C" void on_stop_signal(int sig) {
  const int earlier = g_count.fetch_add(1);
  int expected = 0;
  g_signal.compare_exchange_strong(expected, sig);
  g_stop.store(true);
  const pid_t child = g_child_group.load();
  if (child > 0) ::kill(-child, SIGKILL);
  if (!g_embedded.load() && (earlier >= 1 || g_immediate.load() > 0)) {
    for (int i = 0; i < kSlots; ++i) {
      if (g_slot_state[i].load() == 2) ::unlink(g_slot_path[i]);
    }
    static const char msg[] = "\nrackopt: stopped at once; nothing partial was left\n";
    say(msg, sizeof msg - 1);
    const std::size_t n = g_output_len.load();
    if (n > 0) {
      static const char sigint[] = "SIGINT (Ctrl-C)";
      static const char sigterm[] = "SIGTERM";
      static const char sigusr1[] = "SIGUSR1 (forwarded by mpirun)";
      const std::size_t split = std::min(g_output_split, n);
      say_to(STDOUT_FILENO, g_output, split);
      if (sig == SIGINT) {
        say_to(STDOUT_FILENO, sigint, sizeof sigint - 1);
      } else if (sig == SIGUSR1) {
        say_to(STDOUT_FILENO, sigusr1, sizeof sigusr1 - 1);
      } else {
        say_to(STDOUT_FILENO, sigterm, sizeof sigterm - 1);
      }
      say_to(STDOUT_FILENO, g_output + split, n - split);
    }
    ::_exit(kInterruptedExit);
  }
  if (g_notice_len > 0) say(g_notice, g_notice_len);
}

// Installs on_stop_signal for SIGINT and SIGTERM; the earlier handlers go
// to `saved` ([0] SIGINT, [1] SIGTERM) when not null.
void install_handlers(const std::string& notice, struct sigaction* saved) {
  const std::size_t n = std::min(notice.size(), sizeof g_notice - 1);
  std::memcpy(g_notice, notice.data(), n);
  g_notice_len = n;
  clear_stop_request();
  struct sigaction sa{};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &sa, saved ? &saved[0] : nullptr);
  ::sigaction(SIGTERM, &sa, saved ? &saved[1] : nullptr);
}

}  // namespace

void install_interrupt_handlers(const std::string& notice) { install_handlers(notice, nullptr); }

void also_stop_on(int sig) {
  struct sigaction sa{};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  ::sigaction(sig, &sa, nullptr);
}

EmbeddedStopHandlers::EmbeddedStopHandlers(const std::string& notice) {
  g_embedded.store(true);
  install_handlers(notice, saved_);
}

EmbeddedStopHandlers::~EmbeddedStopHandlers() {
  ::sigaction(SIGINT, &saved_[0], nullptr);
  ::sigaction(SIGTERM, &saved_[1], nullptr);
  clear_stop_request();
  g_embedded.store(false);
}

bool stop_requested() { return g_stop.load(std::memory_order_relaxed); }

int stop_signal() { return g_signal.load(); }

std::string stop_reason() {
  switch (g_signal.load()) {
    case SIGINT: return "SIGINT (Ctrl-C)";
    case SIGTERM: return "SIGTERM";
    case SIGUSR1: return "SIGUSR1 (forwarded by mpirun)";
    default: return "a stop request";
  }
}

void request_stop() {
  g_count.fetch_add(1);
  g_stop.store(true);
}

void clear_stop_request() {
  g_stop.store(false);
  g_count.store(0);
  g_signal.store(0);
}

void throw_if_stop_requested(const std::string& what) {
  if (stop_requested()) throw Interrupted(what + ": stopped by " + stop_reason());
}

void set_child_process_group(pid_t pgid) { g_child_group.store(pgid); }

ImmediateStopScope::ImmediateStopScope() { g_immediate.fetch_add(1); }
ImmediateStopScope::~ImmediateStopScope() { g_immediate.fetch_sub(1); }

void set_immediate_stop_output(const std::string& before, const std::string& after) {
  g_output_len.store(0);
  const std::string text = before + after;
  if (text.size() > sizeof g_output) return;
  std::memcpy(g_output, text.data(), text.size());
  g_output_split = before.size();
  g_output_len.store(text.size());
}

TemporaryFileGuard::TemporaryFileGuard(const std::string& path) {
  if (path.size() >= kPathMax) return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!g_slot_state[i].compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_slot_path[i], path.c_str(), path.size() + 1);
    g_slot_state[i].store(2);
    slot_ = i;
    return;
  }
}

TemporaryFileGuard::~TemporaryFileGuard() {
  if (slot_ >= 0) g_slot_state[slot_].store(0);
}

}  // namespace rackopt
