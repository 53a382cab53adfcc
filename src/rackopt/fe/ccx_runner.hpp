// Running CalculiX ccx on a deck, each solve in a folder of its own (ccx
// writes jobname.* into its working directory).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace rackopt::fe {

// ccx is missing: the message names the program looked for and the Debian
// package (calculix-ccx).
class CcxNotFound : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A solve that failed: ccx exited non-zero, printed an *ERROR, did not
// finish its job, ran past the time limit, was stopped, or wrote output that
// does not read. The message carries the solver's own error lines and the
// kept folder; deck() is the path of the kept input deck, log() of ccx's
// stdout+stderr.
class CcxError : public std::runtime_error {
 public:
  CcxError(const std::string& message, std::string deck, std::string log)
      : std::runtime_error(message), deck_(std::move(deck)), log_(std::move(log)) {}
  const std::string& deck() const { return deck_; }
  const std::string& log() const { return log_; }

 private:
  std::string deck_;
  std::string log_;
};

struct CcxOptions {
  // The program: this when not empty, else the environment variable
  // RACKOPT_CCX when set, else "ccx" on PATH (Debian: /usr/bin/ccx).
  std::string program;
  // Seconds one solve may take before its process group is killed; <= 0: none.
  double time_limit_seconds = 600;
  // Where the solve folders are made ("" = the system temporary folder).
  std::string work_parent;
};

// The absolute path of the ccx that `options` selects; throws CcxNotFound.
std::string find_ccx(const CcxOptions& options = {});

// Writes `deck` to <folder>/job.inp in a new folder rackopt-ccx-XXXXXX under
// the work parent, runs `ccx -i job` there (single-threaded:
// OMP_NUM_THREADS=1; stdout and stderr to job.log), then calls `read` with
// the text of job.dat. On success the folder is removed; on failure (of ccx,
// or an exception thrown by `read`: output that does not read or fails a
// check) it is kept for inspection and CcxError is thrown, with `read`'s
// message (CcxNotFound before any folder is made). The stop request
// (Ctrl-C) ends the solve as a failure. The folder names its owner (this
// process) and a kept one says so (solve_folders.hpp); the first solve of a
// process under a work parent first removes the folders there whose owner
// was killed before it could clean up.
void run_ccx(const std::string& deck, const std::function<void(const std::string& dat_text)>& read,
             const CcxOptions& options = {});

}  // namespace rackopt::fe
