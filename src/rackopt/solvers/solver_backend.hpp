// One optimization library behind the solvers' common settings. A backend
// owns its algorithm names, its own settings (SolverSettings::options, keys
// it declares with defaults and ranges), the checks of what it can run, and
// the run itself. `minimize` and `pareto_front` find the backend by
// SolverSettings::library and never name a library themselves; the study
// loader reads the options a backend declares. Adding a library is one file
// with a class like the ones in *_backend.cpp and one entry in
// solver_backends.cpp (docs/extending.md, "A new solver backend").
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "rackopt/solvers/pareto.hpp"
#include "rackopt/solvers/problem.hpp"
#include "rackopt/solvers/solver.hpp"

namespace rackopt::solvers {

// A setting of one library, read from the study file's `solver:` section
// under `key` and kept in SolverSettings::options. A key the file leaves out
// takes `default_value` (so spelling a default out changes nothing).
struct BackendOption {
  std::string key;            // e.g. "ipopt_tol", "population"
  double default_value = 0;
  double lo = 0, hi = 0;      // allowed range [lo, hi], or (lo, hi] when lo_open
  bool whole = false;         // whole numbers only
  bool lo_open = false;
  std::string meaning;        // one line for docs and messages
  bool output_only = false;   // changes what is printed, never a result (left out of study fingerprints)
};

// One algorithm a library offers.
struct BackendAlgorithm {
  std::string name;           // as written in `solver.algorithm` (compared without case)
  bool fronts = false;        // finds a whole Pareto front itself (population multi-objective search)
  std::string note;           // one line for docs and messages
  bool integers = false;      // searches whole-valued variables (Problem::num_integer) as such
};

class SolverBackend {
 public:
  virtual ~SolverBackend() = default;

  // The `solver.library` name, lower case.
  virtual std::string_view library() const = 0;
  // The algorithms; empty when the library has one method (Ipopt).
  virtual std::vector<BackendAlgorithm> algorithms() const = 0;
  // What `solver.algorithm` means when the study file leaves it out.
  virtual std::string default_algorithm() const = 0;
  // The library's own settings (keys of SolverSettings::options).
  virtual const std::vector<BackendOption>& options() const = 0;

  // Whether `settings` can run a problem of `shape` on this library (the
  // algorithm, its constraint support, its own settings); the common numbers
  // and SolverSettings::options' keys and ranges are checked before this.
  virtual std::optional<SolverSettingsRefusal> check(const SolverSettings& settings,
                                                     const ProblemShape& shape) const = 0;

  // Minimizes objective 0 under the constraints (the contract of
  // solvers::minimize, which calls this after its checks).
  virtual SolverResult minimize(const Problem& problem, std::span<const double> x0, const SolverSettings& settings,
                                const SolverCallbacks& callbacks) const = 0;

  // Whether `settings.algorithm` finds a whole front itself (then
  // pareto_front calls front() instead of scalarizing).
  bool finds_fronts(const SolverSettings& settings) const;
  // Objectives a front search of this library handles (when finds_fronts).
  virtual std::size_t max_front_objectives() const { return 0; }
  // A whole front in one run (the contract of pareto_front). The default
  // throws std::logic_error: only libraries with front algorithms override it.
  virtual ParetoResult front(const Problem& problem, std::span<const double> x0, const ParetoSettings& settings,
                             const ParetoCallbacks& callbacks) const;

  // SolverSettings::options[key] when given, else the option's default.
  // Throws std::logic_error for a key the library does not declare.
  double option(const SolverSettings& settings, std::string_view key) const;
  // The algorithm entry for `name` (any case), or nullptr.
  std::optional<BackendAlgorithm> find_algorithm(std::string_view name) const;
};

// The backend of `library` (any case), or nullptr.
const SolverBackend* find_solver_backend(std::string_view library);
// Every backend, in the order documented (nlopt, ipopt, pagmo).
const std::vector<const SolverBackend*>& solver_backends();
// "nlopt", "ipopt", ... in that order.
std::vector<std::string> solver_library_names();

}  // namespace rackopt::solvers
