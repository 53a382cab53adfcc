// The stop request and the second interrupt, in forked children (signal
// handlers are process-wide).
#include "rackopt/core/interrupt.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace rackopt {
namespace {

int child_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
}

TEST(Interrupt, FirstSignalRequestsAStopSecondEndsAtOnceAndUnlinksTemporaries) {
  const std::string tmp =
      (std::filesystem::temp_directory_path() / ("rackopt_interrupt_" + std::to_string(::getpid()) + ".tmp.1")).string();
  std::ofstream(tmp) << "partial";
  const pid_t pid = fork();
  if (pid == 0) {
    install_interrupt_handlers();
    const TemporaryFileGuard guard(tmp);
    raise(SIGINT);
    if (!stop_requested() || stop_signal() != SIGINT) _exit(3);  // the first one only asks
    try {
      throw_if_stop_requested("work");
      _exit(4);
    } catch (const Interrupted& e) {
      if (std::string(e.what()) != "work: stopped by SIGINT (Ctrl-C)") _exit(5);
    }
    raise(SIGTERM);  // the second ends the process in the handler
    _exit(6);
  }
  EXPECT_EQ(child_exit(pid), kInterruptedExit);
  EXPECT_FALSE(std::filesystem::exists(tmp));
  std::remove(tmp.c_str());
}

TEST(Interrupt, TheHandlerKillsTheRegisteredChildGroup) {
  const pid_t pid = fork();
  if (pid == 0) {
    install_interrupt_handlers();
    const pid_t child = fork();
    if (child == 0) {
      setpgid(0, 0);
      pause();
      _exit(0);
    }
    setpgid(child, child);
    set_child_process_group(child);
    raise(SIGINT);
    int status = 0;
    waitpid(child, &status, 0);
    _exit(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL ? 0 : 7);
  }
  EXPECT_EQ(child_exit(pid), 0);
}

// Embedded (Python's run_study): every signal only asks to stop, even a
// second one and one inside an ImmediateStopScope (the interpreter owns the
// process); the handler found before is back afterwards and the request is
// cleared.
std::atomic<int> g_embedding_program_signals{0};
extern "C" void embedding_program_handler(int) { g_embedding_program_signals.fetch_add(1); }

TEST(Interrupt, EmbeddedHandlersOnlyAskToStopAndGiveTheOldHandlerBack) {
  const pid_t pid = fork();
  if (pid == 0) {
    ::signal(SIGINT, embedding_program_handler);
    {
      const EmbeddedStopHandlers handlers;
      const ImmediateStopScope immediate;
      raise(SIGINT);
      raise(SIGTERM);
      raise(SIGINT);
      if (!stop_requested() || stop_signal() != SIGINT) _exit(3);
      if (g_embedding_program_signals.load() != 0) _exit(4);
    }
    if (stop_requested()) _exit(5);
    raise(SIGINT);  // the embedding program's own handler again
    _exit(g_embedding_program_signals.load() == 1 ? 0 : 6);
  }
  EXPECT_EQ(child_exit(pid), 0);
}

// Rank 0 under mpirun: SIGUSR1 (what mpirun forwards) is a stop like the
// others, named in the message, and a second one ends at once.
TEST(Interrupt, AnAddedStopSignalAsksToStopAndASecondEndsAtOnce) {
  const pid_t pid = fork();
  if (pid == 0) {
    install_interrupt_handlers();
    also_stop_on(SIGUSR1);
    raise(SIGUSR1);
    if (!stop_requested() || stop_signal() != SIGUSR1) _exit(3);
    try {
      throw_if_stop_requested("work");
      _exit(4);
    } catch (const Interrupted& e) {
      if (std::string(e.what()) != "work: stopped by SIGUSR1 (forwarded by mpirun)") _exit(5);
    }
    raise(SIGUSR1);
    _exit(6);
  }
  EXPECT_EQ(child_exit(pid), kInterruptedExit);
}

TEST(Interrupt, RequestAndClear) {
  clear_stop_request();
  EXPECT_FALSE(stop_requested());
  EXPECT_NO_THROW(throw_if_stop_requested("x"));
  request_stop();
  EXPECT_TRUE(stop_requested());
  EXPECT_THROW(throw_if_stop_requested("x"), Interrupted);
  clear_stop_request();
  EXPECT_FALSE(stop_requested());
}

}  // namespace
}  // namespace rackopt
