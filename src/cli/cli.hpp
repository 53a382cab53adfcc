// Shared pieces of the rackopt command line: arguments and the commands.
#pragma once

#include <chrono>
#include <stdexcept>
#include <optional>
#include <string>
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
  int positions = -1;      // --positions N (fe): 1..64; -1 = 4
  int level = -1;          // --level L (fe): 0..6; -1 = 0
  bool extended_contact = false;  // --extended-contact (fe)
  bool pictures = false;          // --pictures (fe): mesh and deformed shape of the first position
  bool rack_supports = false;     // --rack-supports (fe)
  std::vector<std::string> given;  // every --option given, in order, without "=value"
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses argv; throws UsageError for unknown options or missing values.
Args parse_args(int argc, char** argv);

// The options each command accepts, in one table (options.cpp). Throws
// UsageError naming the option and the command when an option that does not
// apply to a.command was given (options are never silently ignored).
void check_options_apply(const Args& a);

// "--set, --out, --json": the options `command` accepts ("" for an unknown command).
std::string accepted_options(const std::string& command);

// render_plot lives in the library (rackopt/output/plot.hpp): studies plot too.
using rackopt::render_plot;

double ms_since(std::chrono::steady_clock::time_point t0);

// Tells stderr which stale temporary files taking the folder lock removed.
void report_stale_temporaries(const rackopt::FolderLock& lock);

int cmd_check(const Args& a);
int cmd_stiffness(const Args& a);
int cmd_wear(const Args& a);
int cmd_run(const Args& a);
int cmd_fe(const Args& a);

}  // namespace rackopt::cli
