// Running an external program (gnuplot for plots, CalculiX ccx for the FE
// reference) as a child that can never hang rackopt and never outlive it:
// the child runs in its own process group, registered with the interrupt
// handler (a Ctrl-C or SIGTERM kills the whole group), with an optional time
// limit after which the group is killed; stdin is /dev/null, stdout and
// stderr go to files.
#pragma once

#include <string>
#include <vector>

namespace rackopt {

// `program` as an absolute path: as given when it has a slash (made absolute,
// the child may run in another folder), else the first executable of that
// name on PATH; "" when there is none.
std::string find_program(const std::string& program);

// What to run. `program` must be an absolute path (find_program).
struct ChildCommand {
  std::string program;
  std::vector<std::string> arguments;      // argv[1..]
  std::string working_dir = ".";           // the child's cwd
  // Files for the child's stdout and stderr, relative to working_dir or
  // absolute; "" = /dev/null. The same name for both appends both to one file.
  std::string stdout_file;
  std::string stderr_file;
  // Extra "NAME=value" entries put before the inherited environment (so they win).
  std::vector<std::string> environment;
  double time_limit_seconds = 0;  // <= 0: no limit
};

// How the child ended.
struct ChildOutcome {
  enum class Kind { exited, signaled, timed_out, stopped, not_started };
  Kind kind = Kind::not_started;
  int exit_code = -1;   // Kind::exited
  std::string message;  // not_started: why; stopped: stop_reason(); else ""
  bool ok() const { return kind == Kind::exited && exit_code == 0; }
};

// Starts `command` and waits for it, polling the stop request
// (stop_requested()) and the time limit every 10 ms; on either the child's
// process group is killed (SIGKILL) and reaped. Whatever the child left
// running in its group is killed when it ends. One child at a time per
// process (the interrupt handler knows one process group).
ChildOutcome run_child(const ChildCommand& command);

}  // namespace rackopt
