#include "rackopt/solvers/solver.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "rackopt/core/text.hpp"
#include "rackopt/doe/samplers.hpp"
#include "rackopt/solvers/adapters.hpp"
#include "rackopt/solvers/evaluation_tracker.hpp"
#include "rackopt/solvers/solver_backend.hpp"

namespace rackopt::solvers {

namespace {

std::string check_numbers(const SolverSettings& s) {
  auto nonneg = [](double v) { return std::isfinite(v) && v >= 0; };
  if (s.max_evaluations == 0) return "max_evaluations must be > 0 (it is the budget of model evaluations, e.g. 1000)";
  if (s.starts < 1) return "starts must be >= 1 (1 = only x0), got " + std::to_string(s.starts);
  if (!nonneg(s.xtol_rel) || !nonneg(s.xtol_abs) || !nonneg(s.ftol_rel) || !nonneg(s.ftol_abs))
    return "xtol_rel, xtol_abs, ftol_rel and ftol_abs must be finite and >= 0 (0 disables a test)";
  if (!nonneg(s.max_seconds)) return "max_seconds must be finite and >= 0 (0 = no time limit)";
  if (!nonneg(s.constraint_tolerance)) return "constraint_tolerance must be finite and >= 0, e.g. 1e-6";
  if (!(s.gradient_step > 0 && s.gradient_step <= 0.25))
    return "gradient_step must be in (0, 0.25] (a fraction of upper-lower), e.g. 1e-6";
  return "";
}

// The library's own settings: known keys, in range, whole where they must be.
std::optional<SolverSettingsRefusal> check_options(const SolverSettings& s, const SolverBackend& backend) {
  for (const auto& entry : s.options) {
    // Named copies, not a structured binding: the lambda below captures the key.
    const std::string& key = entry.first;
    const double value = entry.second;
    const auto& declared = backend.options();
    const auto it = std::find_if(declared.begin(), declared.end(), [&](const BackendOption& o) { return o.key == key; });
    if (it == declared.end()) {
      std::vector<std::string> keys;
      for (const BackendOption& o : declared) keys.push_back(o.key);
      return SolverSettingsRefusal{SolverSetting::kOption,
                                   "'" + key + "' is not a setting of " + std::string(backend.library()) + "; " +
                                       (keys.empty() ? std::string("it has no settings of its own")
                                                     : "its own settings are " + join(keys)),
                                   key};
    }
    const bool in_range =
        std::isfinite(value) && (it->lo_open ? value > it->lo : value >= it->lo) && value <= it->hi;
    if (!in_range || (it->whole && value != std::floor(value))) {
      std::ostringstream out;
      out << key << " = " << value << " is out of range; allowed: " << (it->whole ? "whole numbers " : "")
          << (it->lo_open ? "> " : ">= ") << it->lo << " and <= " << it->hi << " (" << it->meaning << ")";
      return SolverSettingsRefusal{SolverSetting::kOption, out.str(), key};
    }
  }
  return std::nullopt;
}

std::optional<SolverSettingsRefusal> check_library(const SolverSettings& settings) {
  if (find_solver_backend(settings.library)) return std::nullopt;
  std::vector<std::string> quoted;
  for (const std::string& name : solver_library_names()) quoted.push_back("\"" + name + "\"");
  return SolverSettingsRefusal{SolverSetting::kLibrary,
                               "unknown solver library '" + settings.library + "'; use " + join(quoted)};
}

std::string check_shape(const ProblemShape& shape) {
  if (shape.objectives != 1)
    return "the solvers minimize one objective but the problem has " + std::to_string(shape.objectives) +
           "; combine them into one (weighted sum, or the others as constraints) or use a multi-objective method";
  if (shape.dimension == 0) return "the problem has no variables";
  return "";
}

std::string check_bounds(const Problem& problem) {
  const std::size_t n = problem.dimension();
  const std::vector<double> lo = problem.lower_bounds(), up = problem.upper_bounds();
  if (lo.size() != n || up.size() != n)
    return "the problem declares " + std::to_string(n) + " variables but gives " + std::to_string(lo.size()) +
           " lower and " + std::to_string(up.size()) + " upper bounds";
  const std::vector<std::string> names = problem.variable_names();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(lo[i]) || !std::isfinite(up[i]) || !(lo[i] < up[i])) {
      std::ostringstream out;
      out << "variable " << (i < names.size() ? names[i] : "x" + std::to_string(i)) << " has bounds [" << lo[i] << ", "
          << up[i] << "]; every variable needs finite bounds with lower < upper";
      return out.str();
    }
  }
  return "";
}

// Whole-valued variables need an algorithm that keeps them whole; the others
// would evaluate between two list entries.
std::optional<SolverSettingsRefusal> check_integers(const SolverSettings& s, const SolverBackend& backend,
                                                    const ProblemShape& shape) {
  if (shape.integer == 0) return std::nullopt;
  if (shape.integer > shape.dimension)
    return SolverSettingsRefusal{SolverSetting::kProblem,
                                 "the problem declares " + std::to_string(shape.integer) + " integer variables of " +
                                     std::to_string(shape.dimension)};
  const auto algorithm = backend.find_algorithm(s.algorithm);
  if (algorithm && algorithm->integers) return std::nullopt;
  std::vector<std::string> able;
  for (const SolverBackend* b : solver_backends())
    for (const BackendAlgorithm& a : b->algorithms())
      if (a.integers) able.push_back(std::string(b->library()) + " " + a.name);
  return SolverSettingsRefusal{SolverSetting::kAlgorithm,
                               std::string(backend.library()) + (algorithm ? " " + algorithm->name : std::string()) +
                                   " moves continuous variables only and the problem has " +
                                   std::to_string(shape.integer) + " whole-valued ones; algorithms that search them: " +
                                   join(able),
                               ""};
}

}  // namespace

ProblemShape shape_of(const Problem& problem) {
  return ProblemShape{problem.dimension(), problem.num_objectives(), problem.num_inequality(),
                      problem.num_equality(), problem.num_integer()};
}

std::vector<std::string> nlopt_algorithm_names() {
  std::vector<std::string> names;
  for (const detail::NloptAlgorithmInfo& a : detail::nlopt_algorithm_table()) names.push_back(a.name);
  return names;
}

bool algorithm_finds_fronts(const SolverSettings& settings) {
  const SolverBackend* backend = find_solver_backend(settings.library);
  return backend && backend->finds_fronts(settings);
}

// The settings a front algorithm runs on are checked by its shape with one
// objective per front search: check_shape's single objective rule is for
// the scalar solvers only.
std::optional<SolverSettingsRefusal> check_solver_settings(const SolverSettings& settings, const ProblemShape& shape) {
  if (auto r = check_library(settings)) return r;
  const SolverBackend& backend = *find_solver_backend(settings.library);
  const bool front = backend.finds_fronts(settings);
  if (!front) {
    if (std::string msg = check_shape(shape); !msg.empty()) return SolverSettingsRefusal{SolverSetting::kProblem, msg};
  } else if (shape.dimension == 0) {
    return SolverSettingsRefusal{SolverSetting::kProblem, "the problem has no variables"};
  }
  if (std::string msg = check_numbers(settings); !msg.empty())
    return SolverSettingsRefusal{SolverSetting::kNumbers, msg};
  if (auto r = check_options(settings, backend)) return r;
  if (auto r = check_integers(settings, backend, shape)) return r;
  return backend.check(settings, shape);
}

std::string check_solver_settings(const SolverSettings& settings, const Problem& problem) {
  const ProblemShape shape = shape_of(problem);
  // The library first, then the problem's own bounds, then what the settings
  // make of its shape: the first thing to fix is named first.
  if (auto r = check_library(settings)) return r->message;
  if (!algorithm_finds_fronts(settings))
    if (std::string msg = check_shape(shape); !msg.empty()) return msg;
  if (std::string msg = check_bounds(problem); !msg.empty()) return msg;
  const auto r = check_solver_settings(settings, shape);
  return r ? r->message : "";
}

std::string check_solver_settings(const SolverSettings& settings, const Problem& problem, std::span<const double> x0) {
  if (std::string msg = check_solver_settings(settings, problem); !msg.empty()) return msg;
  if (x0.size() != problem.dimension())
    return "x0 has " + std::to_string(x0.size()) + " values, the problem has " + std::to_string(problem.dimension()) +
           " variables";
  for (std::size_t i = 0; i < x0.size(); ++i)
    if (!std::isfinite(x0[i])) return "x0[" + std::to_string(i) + "] is not finite";
  return "";
}

SolverResult minimize(const Problem& problem, std::span<const double> x0, const SolverSettings& settings,
                      const SolverCallbacks& callbacks) {
  if (std::string msg = check_solver_settings(settings, problem, x0); !msg.empty()) throw std::invalid_argument(msg);
  const SolverBackend& backend = *find_solver_backend(settings.library);
  if (backend.finds_fronts(settings))
    throw std::invalid_argument(settings.algorithm + " finds Pareto fronts (pareto_front); minimize needs a "
                                "single-objective algorithm");
  return backend.minimize(problem, x0, settings, callbacks);
}

namespace detail {

SolverResult run_multistart(const Problem& problem, std::span<const double> x0, const SolverSettings& settings,
                            const SolverCallbacks& callbacks, const StartRunner& run_start) {
  const std::vector<double> lo = problem.lower_bounds(), up = problem.upper_bounds();
  std::vector<double> x0c(x0.begin(), x0.end());
  for (std::size_t i = 0; i < x0c.size(); ++i) x0c[i] = std::clamp(x0c[i], lo[i], up[i]);

  std::vector<std::vector<double>> start_points{x0c};
  if (settings.starts > 1) {
    auto design = doe::latin_hypercube(lo, up, static_cast<std::size_t>(settings.starts - 1), settings.seed);
    start_points.insert(start_points.end(), design.begin(), design.end());
  }

  EvaluationTracker tracker(problem, settings, callbacks, x0c);
  std::vector<StartOutcome> outcomes;
  for (std::size_t s = 0; s < start_points.size(); ++s) {
    outcomes.push_back(run_start(tracker, start_points[s], static_cast<int>(s)));
    if (tracker.halt() != Halt::kNone) break;
  }

  SolverResult result;
  tracker.fill_result(result);
  for (std::size_t s = 0; s < outcomes.size(); ++s) {
    if (outcomes.size() > 1) result.solver_message += (s ? "; start " : "start ") + std::to_string(s) + ": ";
    result.solver_message += outcomes[s].message;
  }
  if (tracker.halt() == Halt::kRequests)
    result.solver_message += "; ended by the adapter: the solver asked for " +
                             std::to_string(tracker.point_requests()) + " points (cap 10 * max_evaluations + 1000) but " +
                             std::to_string(result.evaluations) +
                             " were new; it kept revisiting evaluated points (cycling)";

  if (const auto ended = tracker.ending_status()) {
    result.status = *ended;
  } else {
    const bool any_converged = std::any_of(outcomes.begin(), outcomes.end(), [](const StartOutcome& o) {
      return o.status == SolverStatus::kConverged;
    });
    result.status = any_converged ? SolverStatus::kConverged
                                  : outcomes.back().status.value_or(SolverStatus::kSolverFailed);
  }
  return result;
}

}  // namespace detail

}  // namespace rackopt::solvers
