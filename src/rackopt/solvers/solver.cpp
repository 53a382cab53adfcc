#include "rackopt/solvers/solver.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>

#include "rackopt/doe/samplers.hpp"
#include "rackopt/solvers/adapters.hpp"
#include "rackopt/solvers/evaluation_tracker.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt::solvers {

namespace {

using detail::LocalSolver;
using detail::NloptAlgorithmInfo;


// Algorithms that accept the constraint kinds the problem has, local ones
// first (they are the usual fix), then global ones.
std::vector<std::string> capable_algorithms(std::size_t ni, std::size_t ne) {
  std::vector<std::string> local, global;
  for (const NloptAlgorithmInfo& a : detail::nlopt_algorithm_table()) {
    if ((ni > 0 && !a.inequality) || (ne > 0 && !a.equality)) continue;
    if (a.local == LocalSolver::kRequired) continue;  // named separately with their local algorithm
    (a.global ? global : local).push_back(a.name);
  }
  local.insert(local.end(), global.begin(), global.end());
  return local;
}

std::string constraint_phrase(std::size_t ni, std::size_t ne) {
  std::ostringstream out;
  if (ni > 0) out << ni << " inequality";
  if (ni > 0 && ne > 0) out << " and ";
  if (ne > 0) out << ne << " equality";
  out << " constraint" << (ni + ne > 1 ? "s" : "");
  return out.str();
}

bool is_local_algorithm(const NloptAlgorithmInfo& a) { return !a.global && a.local == LocalSolver::kNone; }

std::vector<std::string> local_algorithm_names(bool need_inequality) {
  std::vector<std::string> names;
  for (const NloptAlgorithmInfo& a : detail::nlopt_algorithm_table())
    if (is_local_algorithm(a) && (!need_inequality || a.inequality)) names.push_back(a.name);
  return names;
}

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
  if (!(s.ipopt_tol > 0 && std::isfinite(s.ipopt_tol))) return "ipopt_tol must be > 0, e.g. 1e-8";
  if (s.ipopt_max_iterations < 1) return "ipopt_max_iterations must be >= 1, e.g. 3000";
  return "";
}

std::optional<SolverSettingsRefusal> check_library(const SolverSettings& settings) {
  const std::string library = lower(settings.library);
  if (library == "nlopt" || library == "ipopt") return std::nullopt;
  return SolverSettingsRefusal{SolverSetting::kLibrary,
                               "unknown solver library '" + settings.library + "'; use \"nlopt\" or \"ipopt\""};
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

std::optional<SolverSettingsRefusal> check_nlopt(const SolverSettings& s, const ProblemShape& shape) {
  const std::size_t n = shape.dimension, ni = shape.inequality, ne = shape.equality;
  auto algorithm = [](std::string m) { return SolverSettingsRefusal{SolverSetting::kAlgorithm, std::move(m)}; };
  auto local_algorithm = [](std::string m) {
    return SolverSettingsRefusal{SolverSetting::kLocalAlgorithm, std::move(m)};
  };
  const NloptAlgorithmInfo* a = detail::find_nlopt_algorithm(s.algorithm);
  if (!a) return algorithm("unknown NLopt algorithm '" + s.algorithm + "'; valid names: " + join(nlopt_algorithm_names()));

  if ((ni > 0 && !a->inequality) || (ne > 0 && !a->equality)) {
    std::string msg = std::string(a->name) + " cannot handle the " + constraint_phrase(ni, ne) +
                      " of this problem; use " + join(capable_algorithms(ni, ne));
    if (is_local_algorithm(*a)) msg += ", or AUGLAG with local_algorithm " + std::string(a->name);
    return algorithm(msg);
  }
  if (ne > n)
    return algorithm("NLopt 2.7.1 refuses more equality constraints (" + std::to_string(ne) + ") than variables (" +
                     std::to_string(n) + "); remove redundant equalities or turn some into pairs of inequalities");

  if (a->local == LocalSolver::kNone) {
    if (!s.local_algorithm.empty())
      return local_algorithm("local_algorithm '" + s.local_algorithm + "' is only used by AUGLAG and MLSL variants; " +
                             a->name + " does not take one (leave local_algorithm empty)");
    return std::nullopt;
  }
  const bool eq_only_penalized = std::string(a->name).find("AUGLAG_EQ") != std::string::npos;
  const bool local_needs_inequality = eq_only_penalized && ni > 0;
  if (s.local_algorithm.empty()) {
    if (a->local == LocalSolver::kRequired)
      return algorithm(std::string(a->name) + " needs local_algorithm (the sub-solver it drives); use one of " +
                       join(local_algorithm_names(local_needs_inequality)));
  } else {
    const NloptAlgorithmInfo* l = detail::find_nlopt_algorithm(s.local_algorithm);
    if (!l || !is_local_algorithm(*l))
      return local_algorithm("local_algorithm '" + s.local_algorithm + "' is not a local NLopt algorithm; use one of " +
                             join(local_algorithm_names(local_needs_inequality)));
    if (local_needs_inequality && !l->inequality)
      return local_algorithm(std::string(a->name) + " passes the " + constraint_phrase(ni, 0) +
                             " to its local_algorithm, and " + l->name + " cannot handle them; use one of " +
                             join(local_algorithm_names(true)) +
                             " as local_algorithm, or AUGLAG (which penalizes all constraints)");
  }
  return std::nullopt;
}

}  // namespace

ProblemShape shape_of(const Problem& problem) {
  return ProblemShape{problem.dimension(), problem.num_objectives(), problem.num_inequality(),
                      problem.num_equality()};
}

std::vector<std::string> nlopt_algorithm_names() {
  std::vector<std::string> names;
  for (const NloptAlgorithmInfo& a : detail::nlopt_algorithm_table()) names.push_back(a.name);
  return names;
}

std::optional<SolverSettingsRefusal> check_solver_settings(const SolverSettings& settings, const ProblemShape& shape) {
  if (auto r = check_library(settings)) return r;
  const std::string library = lower(settings.library);
  if (std::string msg = check_shape(shape); !msg.empty()) return SolverSettingsRefusal{SolverSetting::kProblem, msg};
  if (std::string msg = check_numbers(settings); !msg.empty())
    return SolverSettingsRefusal{SolverSetting::kNumbers, msg};
  if (library == "ipopt") {
    if (shape.equality > shape.dimension)
      return SolverSettingsRefusal{
          SolverSetting::kLibrary,
          "Ipopt needs at least as many variables as equality constraints; the problem has " +
              std::to_string(shape.equality) + " equalities for " + std::to_string(shape.dimension) +
              " variables (too few degrees of freedom)"};
    return std::nullopt;
  }
  return check_nlopt(settings, shape);
}

std::string check_solver_settings(const SolverSettings& settings, const Problem& problem) {
  const ProblemShape shape = shape_of(problem);
  // The library first, then the problem's own bounds, then what the settings
  // make of its shape: the first thing to fix is named first.
  if (auto r = check_library(settings)) return r->message;
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

  const std::vector<double> lo = problem.lower_bounds(), up = problem.upper_bounds();
  std::vector<double> x0c(x0.begin(), x0.end());
  for (std::size_t i = 0; i < x0c.size(); ++i) x0c[i] = std::clamp(x0c[i], lo[i], up[i]);

  std::vector<std::vector<double>> start_points{x0c};
  if (settings.starts > 1) {
    auto design = doe::latin_hypercube(lo, up, static_cast<std::size_t>(settings.starts - 1), settings.seed);
    start_points.insert(start_points.end(), design.begin(), design.end());
  }

  const bool use_ipopt = lower(settings.library) == "ipopt";
  const NloptAlgorithmInfo* algorithm = use_ipopt ? nullptr : detail::find_nlopt_algorithm(settings.algorithm);
  const NloptAlgorithmInfo* local =
      settings.local_algorithm.empty() ? nullptr : detail::find_nlopt_algorithm(settings.local_algorithm);

  detail::EvaluationTracker tracker(problem, settings, callbacks, x0c);
  std::vector<detail::StartOutcome> outcomes;
  for (std::size_t s = 0; s < start_points.size(); ++s) {
    const int start = static_cast<int>(s);
    outcomes.push_back(use_ipopt ? detail::run_ipopt_start(tracker, settings, start_points[s], start)
                                 : detail::run_nlopt_start(tracker, settings, *algorithm, local, start_points[s], start));
    if (tracker.halt() != detail::Halt::kNone) break;
  }

  SolverResult result;
  tracker.fill_result(result);
  for (std::size_t s = 0; s < outcomes.size(); ++s) {
    if (outcomes.size() > 1) result.solver_message += (s ? "; start " : "start ") + std::to_string(s) + ": ";
    result.solver_message += outcomes[s].message;
  }
  if (tracker.halt() == detail::Halt::kRequests)
    result.solver_message += "; ended by the adapter: the solver asked for " +
                             std::to_string(tracker.point_requests()) + " points (cap 10 * max_evaluations + 1000) but " +
                             std::to_string(result.evaluations) +
                             " were new; it kept revisiting evaluated points (cycling)";

  if (result.evaluations > 0 && !tracker.any_ok()) {
    result.status = SolverStatus::kAllFailed;
  } else if (result.evaluations > 0 && !tracker.any_feasible()) {
    result.status = SolverStatus::kNoFeasiblePoint;
  } else if (tracker.halt() != detail::Halt::kNone) {
    // A halt by an error was rethrown above; every other halt has a status.
    result.status = detail::halt_status(tracker.halt()).value_or(SolverStatus::kSolverFailed);
  } else {
    const bool any_converged = std::any_of(outcomes.begin(), outcomes.end(), [](const detail::StartOutcome& o) {
      return o.status == SolverStatus::kConverged;
    });
    result.status = any_converged ? SolverStatus::kConverged
                                  : outcomes.back().status.value_or(SolverStatus::kSolverFailed);
  }
  return result;
}

}  // namespace rackopt::solvers
