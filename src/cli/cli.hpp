// Shared pieces of the rackopt command line: arguments and the commands.
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

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
  long samples = -1;       // --samples N (wear): overrides reliability.samples
  long seed = -1;          // --seed S (wear): overrides reliability.seed
  int threads = 0;         // --threads N (wear): 0 = all cores
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses argv; throws UsageError for unknown options or missing values.
Args parse_args(int argc, char** argv);

// Runs gnuplot on DIR/script (which writes `png`.tmp); renames it to DIR/png so
// a failed plot never leaves a half-written image. Returns the PNG path, or ""
// with a warning appended when gnuplot is missing or fails.
std::string render_plot(const std::string& dir, const std::string& script, const std::string& png,
                        std::vector<std::string>& warnings);

double ms_since(std::chrono::steady_clock::time_point t0);

int cmd_check(const Args& a);
int cmd_stiffness(const Args& a);
int cmd_wear(const Args& a);

}  // namespace rackopt::cli
