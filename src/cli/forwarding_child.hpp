// A launcher such as mpirun run as a child that keeps the terminal's output
// but not its Ctrl-C: the child gets a process group of its own, so a Ctrl-C
// in the terminal (SIGINT to the foreground group) reaches only this
// process, which forwards it to the child as the signal the child takes for
// a clean stop. `rackopt run --ranks N` uses it for mpirun, which ends the
// job with its own status 1 on a SIGINT or SIGTERM but forwards SIGUSR1 to
// every rank, where rank 0 takes it as its stop (docs/output.md, "Ctrl-C and
// SIGTERM").
#pragma once

#include <string>
#include <vector>

namespace rackopt::cli {

// How the child ended, and whether we forwarded a stop to it.
struct ForwardedChildOutcome {
  bool started = false;
  std::string error;      // !started: why not
  int exit_code = -1;     // its exit status, or 128 + the signal that ended it (as a shell says)
  int stop_signal = 0;    // the first SIGINT or SIGTERM we forwarded; 0 = none came
  bool printed = false;   // relay_stdout: the child wrote something on its stdout
};

// Starts `program` (an absolute path) with `arguments` (argv[1..], passed
// as they are: no shell) in a process group of its own, stdin /dev/null (a
// background group reading the terminal would be stopped by SIGTTIN),
// stdout and stderr ours (with `relay_stdout` its stdout is a pipe we copy
// to ours as it comes, so that we know whether it printed anything: the
// one JSON object of --json), SIGINT, SIGTERM and SIGUSR1 at their defaults,
// and waits for it. Meanwhile the first and the second SIGINT or SIGTERM
// we get are sent to the child as `stop_as` (mpirun: the first a clean
// stop, the second the at-once end, as for a program run alone), a third
// and any later one as SIGTERM (mpirun: abort the whole job). Our own
// SIGINT and SIGTERM handlers are put back before it returns. One child at
// a time; call from the main thread.
ForwardedChildOutcome run_forwarding_stops(const std::string& program, const std::vector<std::string>& arguments,
                                           int stop_as, bool relay_stdout = false);

}  // namespace rackopt::cli
