// The NLopt 2.7.1 backend. Pitfalls handled here (docs/dependencies.md, "NLopt 2.7" and our
// own probes of Debian 12's NLopt):
//  * exceptions out of callbacks: nlopt.hpp would turn them into
//    std::runtime_error("nlopt failure"); every callback catches everything
//    itself (EvaluationTracker::guard), stores the exception_ptr, calls
//    force_stop, and we rethrow after optimize() returns;
//  * optimize() throws roundoff_limited / forced_stop with a usable x: both
//    are caught, the best point comes from the tracker anyway;
//  * COBYLA returns its last, not best, point and SLSQP may report success
//    while infeasible: we never read the solver's x or f;
//  * NaN makes COBYLA "succeed" with f = nan: solvers only get finite values
//    (failed evaluations become penalty values);
//  * AUGLAG without a local optimizer throws, and LN_/LD_AUGLAG(_EQ) and all
//    MLSL variants without one SEGFAULT in 2.7.1 (nlopt_set_xtol_abs on the
//    default sub-optimizer): we always set the local optimizer ourselves
//    (local_algorithm, else LD_MMA for LD_/GD_ variants, LN_COBYLA for the
//    rest, the generic AUGLAG/AUGLAG_EQ/G_MLSL/G_MLSL_LDS included);
//  * nlopt::srand is thread-local: seeded right here, in the solver thread,
//    before every start.
#include <nlopt.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "rackopt/core/text.hpp"
#include "rackopt/solvers/adapters.hpp"

namespace rackopt::solvers::detail {

namespace {

using LS = LocalSolver;

struct NloptRun {
  EvaluationTracker* tracker;
  nlopt::opt* opt;
};

void stop_solver(NloptRun& run) noexcept {
  // Every later callback returns at once without evaluating, so even a
  // sub-optimizer that does not see the flag ends quickly.
  try {
    run.opt->force_stop();
  } catch (...) {
    // force_stop only throws for an uninitialized opt, which cannot happen here.
  }
}

double objective_callback(unsigned n, const double* x, double* grad, void* data) {
  NloptRun& run = *static_cast<NloptRun*>(data);
  EvaluationTracker& t = *run.tracker;
  double value = 0.0;
  const bool ok = t.guard([&] {
    const Evaluation e = t.at(x);
    value = e.ok() ? e.objectives[0] : t.penalty_objective();
    if (grad) {
      const Jacobian& j = t.jacobian(x);
      std::copy(j.values.begin(), j.values.begin() + n, grad);
    }
  });
  if (!ok) {
    stop_solver(run);
    if (grad) std::fill(grad, grad + n, 0.0);
    value = t.penalty_objective();
  }
  return value;
}

// Vector constraint: rows [first_row, first_row + m) of the stacked vector.
template <bool kEquality>
void constraint_callback(unsigned m, double* result, unsigned n, const double* x, double* grad, void* data) {
  NloptRun& run = *static_cast<NloptRun*>(data);
  EvaluationTracker& t = *run.tracker;
  const std::size_t first_row = kEquality ? 1 + t.num_inequality() : 1;
  const bool ok = t.guard([&] {
    const Evaluation e = t.at(x);
    if (e.ok()) {
      const std::vector<double>& v = kEquality ? e.equality : e.inequality;
      std::copy(v.begin(), v.end(), result);
    } else {
      std::fill(result, result + m, t.penalty_constraint());
    }
    if (grad) {
      const Jacobian& j = t.jacobian(x);
      std::copy(j.values.begin() + first_row * n, j.values.begin() + (first_row + m) * n, grad);
    }
  });
  if (!ok) {
    stop_solver(run);
    std::fill(result, result + m, t.penalty_constraint());
    if (grad) std::fill(grad, grad + std::size_t(m) * n, 0.0);
  }
}

const char* result_name(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS: return "NLOPT_SUCCESS";
    case nlopt::STOPVAL_REACHED: return "NLOPT_STOPVAL_REACHED";
    case nlopt::FTOL_REACHED: return "NLOPT_FTOL_REACHED";
    case nlopt::XTOL_REACHED: return "NLOPT_XTOL_REACHED";
    case nlopt::MAXEVAL_REACHED: return "NLOPT_MAXEVAL_REACHED";
    case nlopt::MAXTIME_REACHED: return "NLOPT_MAXTIME_REACHED";
    default: return "NLOPT_UNKNOWN_RESULT";
  }
}

void set_tolerances(nlopt::opt& opt, const SolverSettings& s) {
  opt.set_xtol_rel(s.xtol_rel);
  opt.set_ftol_rel(s.ftol_rel);
  opt.set_ftol_abs(s.ftol_abs);
  if (s.xtol_abs > 0) opt.set_xtol_abs(s.xtol_abs);
}

}  // namespace

const std::vector<NloptAlgorithmInfo>& nlopt_algorithm_table() {
  // LD_LBFGS_NOCEDAL is left out: not compiled into Debian's NLopt
  // (optimize() answers "invalid argument").
  static const std::vector<NloptAlgorithmInfo> table = {
      {"LN_COBYLA", nlopt::LN_COBYLA, true, true, LS::kNone, false, false, "linear approximations; returns its last point (we keep the best)"},
      {"LN_BOBYQA", nlopt::LN_BOBYQA, false, false, LS::kNone, false, false, "quadratic models, bounds only"},
      {"LN_NEWUOA", nlopt::LN_NEWUOA, false, false, LS::kNone, false, false, "quadratic models, ignores bounds (we clamp)"},
      {"LN_NEWUOA_BOUND", nlopt::LN_NEWUOA_BOUND, false, false, LS::kNone, false, false, "NEWUOA with bounds"},
      {"LN_PRAXIS", nlopt::LN_PRAXIS, false, false, LS::kNone, false, false, "principal axis"},
      {"LN_NELDERMEAD", nlopt::LN_NELDERMEAD, false, false, LS::kNone, false, false, "simplex"},
      {"LN_SBPLX", nlopt::LN_SBPLX, false, false, LS::kNone, false, false, "subspace simplex"},
      {"LD_SLSQP", nlopt::LD_SLSQP, true, true, LS::kNone, true, false, "SQP; may claim success while infeasible (we re-check)"},
      {"LD_MMA", nlopt::LD_MMA, true, false, LS::kNone, true, false, "moving asymptotes"},
      {"LD_CCSAQ", nlopt::LD_CCSAQ, true, false, LS::kNone, true, false, "conservative convex separable approximation"},
      {"LD_LBFGS", nlopt::LD_LBFGS, false, false, LS::kNone, true, false, "limited-memory BFGS"},
      {"LD_VAR1", nlopt::LD_VAR1, false, false, LS::kNone, true, false, "variable metric rank 1"},
      {"LD_VAR2", nlopt::LD_VAR2, false, false, LS::kNone, true, false, "variable metric rank 2"},
      {"LD_TNEWTON", nlopt::LD_TNEWTON, false, false, LS::kNone, true, false, "truncated Newton"},
      {"LD_TNEWTON_RESTART", nlopt::LD_TNEWTON_RESTART, false, false, LS::kNone, true, false, "truncated Newton"},
      {"LD_TNEWTON_PRECOND", nlopt::LD_TNEWTON_PRECOND, false, false, LS::kNone, true, false, "truncated Newton"},
      {"LD_TNEWTON_PRECOND_RESTART", nlopt::LD_TNEWTON_PRECOND_RESTART, false, false, LS::kNone, true, false, "truncated Newton"},
      {"LN_AUGLAG", nlopt::LN_AUGLAG, true, true, LS::kOptional, false, false, "augmented Lagrangian, local LN_COBYLA unless given"},
      {"LD_AUGLAG", nlopt::LD_AUGLAG, true, true, LS::kOptional, true, false, "augmented Lagrangian, local LD_MMA unless given"},
      {"LN_AUGLAG_EQ", nlopt::LN_AUGLAG_EQ, true, true, LS::kOptional, false, false, "penalizes equalities only, local LN_COBYLA unless given"},
      {"LD_AUGLAG_EQ", nlopt::LD_AUGLAG_EQ, true, true, LS::kOptional, true, false, "penalizes equalities only, local LD_MMA unless given"},
      {"AUGLAG", nlopt::AUGLAG, true, true, LS::kOptional, false, false, "augmented Lagrangian around local_algorithm, LN_COBYLA unless given"},
      {"AUGLAG_EQ", nlopt::AUGLAG_EQ, true, true, LS::kOptional, false, false, "penalizes equalities only; local_algorithm (LN_COBYLA unless given) gets the inequalities"},
      {"GN_DIRECT", nlopt::GN_DIRECT, false, false, LS::kNone, false, true, "dividing rectangles"},
      {"GN_DIRECT_L", nlopt::GN_DIRECT_L, false, false, LS::kNone, false, true, "locally biased DIRECT"},
      {"GN_DIRECT_L_RAND", nlopt::GN_DIRECT_L_RAND, false, false, LS::kNone, false, true, "randomized DIRECT-L (seeded)"},
      {"GN_DIRECT_NOSCAL", nlopt::GN_DIRECT_NOSCAL, false, false, LS::kNone, false, true, "unscaled DIRECT"},
      {"GN_DIRECT_L_NOSCAL", nlopt::GN_DIRECT_L_NOSCAL, false, false, LS::kNone, false, true, "unscaled DIRECT-L"},
      {"GN_DIRECT_L_RAND_NOSCAL", nlopt::GN_DIRECT_L_RAND_NOSCAL, false, false, LS::kNone, false, true, "unscaled randomized DIRECT-L"},
      {"GN_ORIG_DIRECT", nlopt::GN_ORIG_DIRECT, true, false, LS::kNone, false, true, "original DIRECT; overshoots NLopt's maxeval (our budget holds)"},
      {"GN_ORIG_DIRECT_L", nlopt::GN_ORIG_DIRECT_L, true, false, LS::kNone, false, true, "original DIRECT-L"},
      {"GN_CRS2_LM", nlopt::GN_CRS2_LM, false, false, LS::kNone, false, true, "controlled random search (seeded)"},
      {"GN_ISRES", nlopt::GN_ISRES, true, true, LS::kNone, false, true, "evolution strategy with stochastic ranking (seeded)"},
      {"GN_ESCH", nlopt::GN_ESCH, false, false, LS::kNone, false, true, "evolution strategy (seeded)"},
      {"GN_AGS", nlopt::GN_AGS, true, false, LS::kNone, false, true, "Strongin's global search, Hilbert curve (libnlopt_cxx only)"},
      {"GD_STOGO", nlopt::GD_STOGO, false, false, LS::kNone, true, true, "branch and bound with BFGS (libnlopt_cxx only)"},
      {"GD_STOGO_RAND", nlopt::GD_STOGO_RAND, false, false, LS::kNone, true, true, "randomized StoGO (seeded)"},
      {"GN_MLSL", nlopt::GN_MLSL, false, false, LS::kOptional, false, true, "multi-level single linkage, local LN_COBYLA unless given"},
      {"GD_MLSL", nlopt::GD_MLSL, false, false, LS::kOptional, true, true, "multi-level single linkage, local LD_MMA unless given"},
      {"GN_MLSL_LDS", nlopt::GN_MLSL_LDS, false, false, LS::kOptional, false, true, "MLSL on a Sobol sequence, local LN_COBYLA unless given"},
      {"GD_MLSL_LDS", nlopt::GD_MLSL_LDS, false, false, LS::kOptional, true, true, "MLSL on a Sobol sequence, local LD_MMA unless given"},
      {"G_MLSL", nlopt::G_MLSL, false, false, LS::kOptional, false, true, "MLSL around local_algorithm, LN_COBYLA unless given"},
      {"G_MLSL_LDS", nlopt::G_MLSL_LDS, false, false, LS::kOptional, false, true, "MLSL (Sobol) around local_algorithm, LN_COBYLA unless given"},
  };
  return table;
}

const NloptAlgorithmInfo* find_nlopt_algorithm(const std::string& name) {
  std::string key;
  for (char c : name) key.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  if (key.rfind("NLOPT_", 0) == 0) key.erase(0, 6);
  for (const NloptAlgorithmInfo& info : nlopt_algorithm_table())
    if (key == info.name) return &info;
  return nullptr;
}

StartOutcome run_nlopt_start(EvaluationTracker& tracker, const SolverSettings& settings,
                             const NloptAlgorithmInfo& algorithm, const NloptAlgorithmInfo* local,
                             std::vector<double> x_start, int start) {
  const unsigned n = static_cast<unsigned>(tracker.dimension());
  tracker.begin_start(start);
  // Thread-local in NLopt: must be called here, in the thread that runs
  // optimize(). Each start gets its own stream derived from the seed only.
  nlopt::srand(static_cast<unsigned long>(settings.seed + 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(start)));

  nlopt::opt opt(static_cast<nlopt::algorithm>(algorithm.id), n);
  NloptRun run{&tracker, &opt};
  opt.set_lower_bounds(tracker.lower());
  opt.set_upper_bounds(tracker.upper());
  opt.set_min_objective(objective_callback, &run);
  // The solver's own feasibility tolerance is tighter than our re-check, so
  // what it calls feasible we call feasible too.
  const double solver_tol = 0.5 * settings.constraint_tolerance;
  if (tracker.num_inequality() > 0)
    opt.add_inequality_mconstraint(constraint_callback<false>, &run,
                                   std::vector<double>(tracker.num_inequality(), solver_tol));
  if (tracker.num_equality() > 0)
    opt.add_equality_mconstraint(constraint_callback<true>, &run,
                                 std::vector<double>(tracker.num_equality(), solver_tol));
  set_tolerances(opt, settings);
  if (algorithm.local != LocalSolver::kNone) {
    nlopt::algorithm local_id;
    if (local) {
      local_id = static_cast<nlopt::algorithm>(local->id);
    } else {
      // NLopt's own defaults, set explicitly: leaving them to NLopt 2.7.1
      // crashes (LN_/LD_ AUGLAG, MLSL) or throws (generic AUGLAG). LN_COBYLA
      // for the generic ones: it accepts the inequalities AUGLAG_EQ hands on.
      local_id = algorithm.derivative ? nlopt::LD_MMA : nlopt::LN_COBYLA;
    }
    nlopt::opt sub(local_id, n);
    set_tolerances(sub, settings);
    opt.set_local_optimizer(sub);
  }

  StartOutcome outcome;
  double f = 0;
  try {
    const nlopt::result r = opt.optimize(x_start, f);
    outcome.message = result_name(r);
    if (r == nlopt::MAXEVAL_REACHED) outcome.status = SolverStatus::kMaxEvaluations;
    else if (r == nlopt::MAXTIME_REACHED) outcome.status = SolverStatus::kMaxTime;
    else outcome.status = SolverStatus::kConverged;
  } catch (const nlopt::roundoff_limited&) {
    // x is still good (docs/dependencies.md, "NLopt 2.7"); our best point is independent of it.
    outcome.status = SolverStatus::kConverged;
    outcome.message = "NLOPT_ROUNDOFF_LIMITED";
  } catch (const nlopt::forced_stop&) {
    outcome.message = "NLOPT_FORCED_STOP";
    if (tracker.halt() == Halt::kNone) outcome.status = SolverStatus::kSolverFailed;
  } catch (const std::invalid_argument& e) {
    tracker.rethrow_if_error();
    throw std::invalid_argument(std::string("NLopt rejected the settings for ") + algorithm.name + ": " + e.what());
  } catch (const std::bad_alloc&) {
    tracker.rethrow_if_error();
    throw;
  } catch (const std::runtime_error& e) {
    outcome.status = SolverStatus::kSolverFailed;
    outcome.message = std::string("NLOPT_FAILURE: ") + e.what();
  }
  tracker.rethrow_if_error();
  if (tracker.halt() != Halt::kNone) outcome.status.reset();
  return outcome;
}

}  // namespace rackopt::solvers::detail

namespace rackopt::solvers::detail {

namespace {

// Algorithms that accept the constraint kinds the problem has, local ones
// first (they are the usual fix), then global ones.
std::vector<std::string> capable_algorithms(std::size_t ni, std::size_t ne) {
  std::vector<std::string> local, global;
  for (const NloptAlgorithmInfo& a : nlopt_algorithm_table()) {
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
  for (const NloptAlgorithmInfo& a : nlopt_algorithm_table())
    if (is_local_algorithm(a) && (!need_inequality || a.inequality)) names.push_back(a.name);
  return names;
}

class NloptBackend final : public SolverBackend {
 public:
  std::string_view library() const override { return "nlopt"; }
  std::vector<BackendAlgorithm> algorithms() const override {
    std::vector<BackendAlgorithm> out;
    for (const NloptAlgorithmInfo& a : nlopt_algorithm_table()) out.push_back({a.name, false, a.note});
    return out;
  }
  std::string default_algorithm() const override { return "LN_COBYLA"; }
  const std::vector<BackendOption>& options() const override {
    static const std::vector<BackendOption> none;
    return none;
  }

  std::optional<SolverSettingsRefusal> check(const SolverSettings& s, const ProblemShape& shape) const override {
    const std::size_t n = shape.dimension, ni = shape.inequality, ne = shape.equality;
    auto algorithm = [](std::string m) { return SolverSettingsRefusal{SolverSetting::kAlgorithm, std::move(m), ""}; };
    auto local_algorithm = [](std::string m) {
      return SolverSettingsRefusal{SolverSetting::kLocalAlgorithm, std::move(m), ""};
    };
    const NloptAlgorithmInfo* a = find_nlopt_algorithm(s.algorithm);
    if (!a)
      return algorithm("unknown NLopt algorithm '" + s.algorithm + "'; valid names: " + join(nlopt_algorithm_names()));

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
        return local_algorithm("local_algorithm '" + s.local_algorithm +
                               "' is only used by AUGLAG and MLSL variants; " + a->name +
                               " does not take one (leave local_algorithm empty)");
      return std::nullopt;
    }
    const bool eq_only_penalized = std::string(a->name).find("AUGLAG_EQ") != std::string::npos;
    const bool local_needs_inequality = eq_only_penalized && ni > 0;
    if (s.local_algorithm.empty()) {
      if (a->local == LocalSolver::kRequired)
        return algorithm(std::string(a->name) + " needs local_algorithm (the sub-solver it drives); use one of " +
                         join(local_algorithm_names(local_needs_inequality)));
    } else {
      const NloptAlgorithmInfo* l = find_nlopt_algorithm(s.local_algorithm);
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

  SolverResult minimize(const Problem& problem, std::span<const double> x0, const SolverSettings& settings,
                        const SolverCallbacks& callbacks) const override {
    const NloptAlgorithmInfo* algorithm = find_nlopt_algorithm(settings.algorithm);
    const NloptAlgorithmInfo* local =
        settings.local_algorithm.empty() ? nullptr : find_nlopt_algorithm(settings.local_algorithm);
    return run_multistart(problem, x0, settings, callbacks,
                          [&](EvaluationTracker& tracker, std::vector<double> x_start, int start) {
                            return run_nlopt_start(tracker, settings, *algorithm, local, std::move(x_start), start);
                          });
  }
};

}  // namespace

const SolverBackend& nlopt_backend() {
  static const NloptBackend backend;
  return backend;
}

}  // namespace rackopt::solvers::detail
