// rackopt run --ranks N STUDY ...: `mpirun -np N <this program> run STUDY
// ...` as a child, so that a Ctrl-C in the terminal stops the study cleanly
// (the stopped report, exit 130) as it does without MPI. A Ctrl-C that
// reached mpirun itself would abort the job with OpenMPI's status 1; the
// child is therefore put in a process group of its own and our SIGINT and
// SIGTERM go to it as SIGUSR1, which mpirun forwards to every rank and rank
// 0 takes as its stop (forwarding_child.hpp; docs/output.md, "Ctrl-C and
// SIGTERM"). mpirun's output is passed through; we print only errors.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <signal.h>
#include <unistd.h>

#include "cli.hpp"
#include "forwarding_child.hpp"
#include "rackopt/core/child_process.hpp"
#include "rackopt/core/interrupt.hpp"
#ifdef RACKOPT_WITH_MPI
#include "rackopt/mpi/mpi_job.hpp"
#endif

namespace rackopt::cli {
#ifdef RACKOPT_WITH_MPI
namespace {

// mpirun: RACKOPT_MPIRUN when set (a site's other MPI), else the one the
// build found (it matches the MPI library linked in), else the first on PATH.
std::string find_mpirun() {
  const char* chosen = std::getenv("RACKOPT_MPIRUN");
  if (chosen != nullptr && *chosen != '\0') {
    const std::string found = find_program(chosen);
    if (found.empty()) {
      throw MpiUnavailable(std::string("--ranks: RACKOPT_MPIRUN names '") + chosen +
                           "', which is no executable program (found neither as a path nor on PATH)");
    }
    return found;
  }
  std::string built;
#ifdef RACKOPT_MPIRUN_PROGRAM
  built = RACKOPT_MPIRUN_PROGRAM;
  if (::access(built.c_str(), X_OK) == 0) return built;
#endif
  const std::string on_path = find_program("mpirun");
  if (!on_path.empty()) return on_path;
  throw MpiUnavailable("--ranks needs mpirun (Debian openmpi-bin), found " +
                       (built.empty() ? std::string() : "neither at " + built + " nor ") +
                       "on PATH; or run it yourself: mpirun -np N rackopt run ...");
}

// This program, as an absolute path every rank can start (the ranks of
// other machines need it at the same path, as they need the study file).
std::string this_program() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || self.empty()) throw MpiUnavailable("--ranks: cannot tell where this program is (/proc/self/exe)");
  return self.string();
}

// `arguments` (argv[1..]) without its --ranks options: what every rank is
// given after the program. Everything after "--" is kept (file names).
std::vector<std::string> arguments_for_ranks(const std::vector<std::string>& arguments) {
  std::vector<std::string> kept;
  bool files_only = false;  // after "--" every argument is a file name
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& a = arguments[i];
    if (!files_only && a == "--") files_only = true;
    if (!files_only && a == "--ranks") {
      ++i;  // and its value
      continue;
    }
    if (!files_only && a.rfind("--ranks=", 0) == 0) continue;
    kept.push_back(a);
  }
  return kept;
}

}  // namespace
#endif

int cmd_run_ranks(const Args& a) {
#ifdef RACKOPT_WITH_MPI
  if (mpi::MpiJob::launched()) {
    throw MpiUnavailable("--ranks starts mpirun itself; under mpirun leave it out (mpirun -np N sets the ranks)");
  }
#endif
  if (a.ranks == 1) {  // one rank: this process, as without --ranks
    Args here = a;
    here.ranks = 0;
    return cmd_run(here);
  }
#ifndef RACKOPT_WITH_MPI
  throw MpiUnavailable(
      "--ranks needs a rackopt built with MPI (Debian libopenmpi-dev, then rebuild: ./dev.sh build); this one "
      "has none");
#else
  const std::string mpirun = find_mpirun();
  std::vector<std::string> args = {"-np", std::to_string(a.ranks), this_program()};
  const std::vector<std::string> rest = arguments_for_ranks(a.arguments);
  args.insert(args.end(), rest.begin(), rest.end());
  const ForwardedChildOutcome child = run_forwarding_stops(mpirun, args, SIGUSR1, a.json);
  if (!child.started) throw MpiUnavailable("--ranks: " + child.error);
  const std::string stop =
      child.stop_signal == 0 ? std::string() : child.stop_signal == SIGINT ? "SIGINT (Ctrl-C)" : "SIGTERM";
  if (a.json && !child.printed && child.exit_code != 0) {
    // mpirun ended before rank 0 printed (it could not start the ranks, or a
    // stop came first): the one JSON object of --json is ours to print.
    const std::string what = "mpirun ended with status " + std::to_string(child.exit_code) +
                             " before rank 0 printed its result (mpirun's messages are on stderr)";
    if (!stop.empty()) throw Interrupted(what + "; stopped by " + stop);
    throw std::runtime_error(what);
  }
  // As for a run in one process: a stop that came at all ends the run as
  // interrupted, also one that reached mpirun before it could forward it
  // (it then ends with its own status, and nothing was recorded).
  if (child.stop_signal != 0 && child.exit_code != kInterruptedExit) {
    std::cerr << "rackopt: stopped by " << stop << "; mpirun ended with status " << child.exit_code << "\n";
    return kInterruptedExit;
  }
  return child.exit_code;
#endif
}

}  // namespace rackopt::cli
