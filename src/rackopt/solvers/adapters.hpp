// Internal to the solver backends: the multistart loop NLopt and Ipopt share,
// one start of each on an EvaluationTracker, and the NLopt algorithm table.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rackopt/solvers/evaluation_tracker.hpp"
#include "rackopt/solvers/solver.hpp"
#include "rackopt/solvers/solver_backend.hpp"
#include "rackopt/solvers/solver_status.hpp"

namespace rackopt::solvers::detail {

enum class LocalSolver { kNone, kOptional, kRequired };

// What NLopt 2.7.1 (libnlopt_cxx, as packaged in Debian 12) accepts; each
// row was checked against Debian 12's NLopt by adding an inequality / equality
// mconstraint and running a small problem (docs/solvers.md).
struct NloptAlgorithmInfo {
  const char* name;        // without the NLOPT_ prefix
  int id;                  // nlopt::algorithm
  bool inequality;         // accepts nonlinear inequality constraints
  bool equality;           // accepts nonlinear equality constraints
  LocalSolver local;       // needs / accepts a local_algorithm
  bool derivative;         // asks for gradients (we give finite differences)
  bool global;             // searches the whole box
  const char* note;        // one line for the docs table and messages
};

const std::vector<NloptAlgorithmInfo>& nlopt_algorithm_table();
// nullptr when unknown. Accepts any case and an optional "NLOPT_" prefix.
const NloptAlgorithmInfo* find_nlopt_algorithm(const std::string& name);

// How one start ended, as seen by the solver ("" status when the adapter
// halted it: the tracker's halt() tells why).
struct StartOutcome {
  // kConverged, kMaxEvaluations, kMaxTime, kMaxIterations or kSolverFailed;
  // nullopt when the adapter halted the start (the tracker's halt() says why).
  std::optional<SolverStatus> status;
  std::string message;  // return code name (+ details)
};

// Runs one start. Rethrows whatever the model threw (after the solver has
// returned). Throws std::invalid_argument when the solver refuses settings
// the check did not catch.
StartOutcome run_nlopt_start(EvaluationTracker& tracker, const SolverSettings& settings,
                             const NloptAlgorithmInfo& algorithm, const NloptAlgorithmInfo* local,
                             std::vector<double> x_start, int start);
StartOutcome run_ipopt_start(EvaluationTracker& tracker, const SolverSettings& settings,
                             std::vector<double> x_start, int start);

// One start of a local solver from x_start (start 0 is x0).
using StartRunner = std::function<StartOutcome(EvaluationTracker& tracker, std::vector<double> x_start, int start)>;

// x0 (clamped into the box) and then settings.starts - 1 Latin hypercube
// points of the box, all on one tracker and budget; the result's status says
// how the whole run ended (the contract of solvers::minimize).
SolverResult run_multistart(const Problem& problem, std::span<const double> x0, const SolverSettings& settings,
                            const SolverCallbacks& callbacks, const StartRunner& run_start);

// The backends solver_backends() lists.
const SolverBackend& nlopt_backend();
const SolverBackend& ipopt_backend();
const SolverBackend& pagmo_backend();

}  // namespace rackopt::solvers::detail
