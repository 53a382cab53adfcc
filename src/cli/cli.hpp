// Shared pieces of the rackopt command line: arguments and the commands.
#pragma once

#include <chrono>
#include <stdexcept>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/output/folder_lock.hpp"
#include "rackopt/output/plot.hpp"

namespace rackopt::cli {

constexpr int kOk = 0;
constexpr int kRunFailed = 1;
constexpr int kBadInput = 2;

struct Args {
  std::string command;
  std::string file;
  std::vector<std::string> overrides;
  std::string out_dir;
  bool json = false;
  std::optional<long> samples;  // --samples N (wear): overrides reliability.samples
  std::optional<long> seed;     // --seed S (wear): overrides reliability.seed
  int threads = 0;         // --threads N (wear, run, fe): 0 = all cores
  bool resume = false;     // --resume (run): continue a study from its evaluation store
  bool progress = false;   // --progress (run): progress bar even when stderr is not a terminal
  int ranks = 0;           // --ranks N (run): N MPI ranks under an mpirun of our own; 0 = not given
  std::vector<std::string> arguments;  // argv[1..] as given (what `run --ranks` hands the ranks)
  int positions = -1;      // --positions N (fe): 1..64; -1 = 4
  int level = -1;          // --level L (fe): 0..6; -1 = 0
  bool extended_contact = false;  // --extended-contact (fe)
  bool pictures = false;          // --pictures (fe): mesh and deformed shape of the first position
  bool rack_supports = false;     // --rack-supports (fe)
  std::optional<double> speed;    // --speed V (dynamics): the operating speed [m/s]; absent = load.speed
  bool sweep = false;             // --sweep (dynamics): K_V over the speed range
  bool stability = false;         // --stability (dynamics): Floquet over the speed range
};

struct UsageError : std::runtime_error {
  explicit UsageError(const std::string& message, std::string command_name = "")
      : std::runtime_error(message), command(std::move(command_name)) {}
  std::string command;  // the command whose command line is wrong; "" before one was recognised
};

// `run --ranks N` cannot start the ranks: a build without MPI, no mpirun,
// or --ranks under an mpirun already (exit 2, JSON error "mpi_unavailable").
struct MpiUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What the command line asks for: a command to run, or a text to print on
// stdout before exiting with kOk (--help, --version).
struct CommandLine {
  Args args;
  std::string text;
};

// Parses argv (command_line.cpp: every command, its options with their
// meaning, range and default, and the help built from them). Throws
// UsageError for an unknown command or option (with the nearest valid one),
// an option the command does not accept, a missing FILE or a bad value:
// options are never silently ignored.
CommandLine parse_command_line(int argc, char** argv);

// Whether argv asks for JSON, read before parsing so that a usage error is
// a JSON object too: the last `--json` or `--json=VALUE` (true/false, on/off,
// yes/no, 1/0) before a `--`, after which every argument is a file name.
bool json_requested(int argc, char** argv);

// `rackopt --help`: the commands, one line each.
std::string program_help();

// The candidate nearest to `given` ("--thread" -> "--threads"), or "" when
// none is near enough to be a likely typo.
std::string nearest_name(const std::string& given, const std::vector<std::string>& candidates);

// render_plot lives in the library (rackopt/output/plot.hpp): studies plot too.
using rackopt::render_plot;

double ms_since(std::chrono::steady_clock::time_point t0);

// Tells stderr which stale temporary files taking the folder lock removed.
void report_stale_temporaries(const rackopt::FolderLock& lock);

int cmd_check(const Args& a);
int cmd_stiffness(const Args& a);
int cmd_wear(const Args& a);
int cmd_dynamics(const Args& a);
int cmd_run(const Args& a);
// `run --ranks N` with N > 1: `mpirun -np N <this program> run ...` as a
// child (cmd_run_ranks.cpp; docs/studies.md, "Running on several cores and
// machines"); its exit status, 130 when a Ctrl-C or SIGTERM stopped it.
int cmd_run_ranks(const Args& a);
int cmd_fe(const Args& a);

}  // namespace rackopt::cli
