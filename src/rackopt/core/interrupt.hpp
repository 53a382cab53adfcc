// Ctrl-C and SIGTERM for the whole program, so that an interrupt is never
// swallowed and never leaves a half-written file or a stray child behind
// (docs/output.md, "Guarantees").
//
//  * The first SIGINT/SIGTERM sets a process-wide stop request. Long work
//    polls stop_requested() (a study between evaluations, the Monte Carlo
//    of a life at R between samples and through its distribution fits, a
//    plot while gnuplot runs) and ends cleanly; the command line then exits
//    kInterruptedExit.
//  * The handler itself kills the process group of the registered child
//    (gnuplot), so a hung child cannot keep the program alive.
//  * A second signal ends the process at once: the registered temporary
//    files are unlinked, the child group killed, then _exit(kInterruptedExit).
//    So does the first one inside an ImmediateStopScope. Neither happens
//    under EmbeddedStopHandlers (a library call inside another program).
#pragma once

#include <stdexcept>
#include <string>

#include <signal.h>
#include <sys/types.h>

namespace rackopt {

// Exit status of a run ended by SIGINT or SIGTERM (128 + SIGINT, what a shell
// reports for a program ended by Ctrl-C; the same for SIGTERM).
constexpr int kInterruptedExit = 130;

// Thrown by work that noticed the stop request and gave up part-way; nothing
// it was producing has been published. Catch it before std::exception.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Installs the SIGINT and SIGTERM handlers described above (idempotent) and
// clears any earlier stop request. `notice`, when not empty, is written to
// stderr by the first signal (e.g. "stopping after the current evaluation").
void install_interrupt_handlers(const std::string& notice = "");

// Makes `sig` a stop signal too, handled as SIGINT and SIGTERM are (call
// after install_interrupt_handlers). Rank 0 under mpirun: SIGUSR1, which
// mpirun forwards to every rank, whereas a SIGINT or SIGTERM to mpirun
// aborts the job with OpenMPI's own exit status (docs/output.md).
void also_stop_on(int sig);

// True once SIGINT or SIGTERM arrived (or request_stop() was called).
bool stop_requested();
// The signal that asked to stop (SIGINT, SIGTERM, one of also_stop_on()),
// 0 when none did.
int stop_signal();
// "SIGINT (Ctrl-C)", "SIGTERM", "SIGUSR1 (forwarded by mpirun)" or "a stop request".
std::string stop_reason();
// Sets the stop request as a first signal would (tests, embedding programs).
void request_stop();
// Forgets the stop request (tests).
void clear_stop_request();
// Throws Interrupted("<what>: stopped by <reason>") when a stop was requested.
void throw_if_stop_requested(const std::string& what);

// The process group the handler kills on a signal (a child started in its
// own group: pgid = its pid); 0 = none. One at a time.
void set_child_process_group(pid_t pgid);

// rackopt's SIGINT/SIGTERM handler for the life of the object, inside a
// program that owns the process and its own handlers (the Python module's
// run_study, whose interpreter's handler cannot run while the call holds no
// GIL): clears the stop request, then every signal only sets it (and kills
// the registered child's group), never ending the process at once, not even
// in an ImmediateStopScope. On the way out the stop request is cleared (so
// that later calls of the embedding program run) and the handlers found
// are put back: read stop_requested() before. Make it on the thread that
// gets the signals (the main thread); one at a time.
class EmbeddedStopHandlers {
 public:
  explicit EmbeddedStopHandlers(const std::string& notice = "");
  ~EmbeddedStopHandlers();
  EmbeddedStopHandlers(const EmbeddedStopHandlers&) = delete;
  EmbeddedStopHandlers& operator=(const EmbeddedStopHandlers&) = delete;

 private:
  struct sigaction saved_[2] = {};  // the handlers found: SIGINT's, SIGTERM's
};

// While one of these lives, the first signal already ends the process at
// once (as a second one does): for long computations that have nothing to
// report when stopped (`rackopt wear`'s analysis, which publishes nothing
// until it ends).
class ImmediateStopScope {
 public:
  ImmediateStopScope();
  ~ImmediateStopScope();
  ImmediateStopScope(const ImmediateStopScope&) = delete;
  ImmediateStopScope& operator=(const ImmediateStopScope&) = delete;
};

// What an at-once end writes to stdout before exiting (the --json error
// object): `before`, the signal's name ("SIGINT (Ctrl-C)", "SIGTERM"), then
// `after`; both "" for nothing. Clear it before printing the run's own output.
void set_immediate_stop_output(const std::string& before, const std::string& after = "");

// Registers a temporary file the second signal must unlink, for the life of
// the object. At most 32 at once (further ones are simply not registered).
class TemporaryFileGuard {
 public:
  explicit TemporaryFileGuard(const std::string& path);
  ~TemporaryFileGuard();
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace rackopt
