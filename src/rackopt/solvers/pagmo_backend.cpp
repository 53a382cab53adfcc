// The pagmo 2.18 backend: population methods. NSGA-II and MOEA/D find a whole
// Pareto front in one run; CMA-ES, SADE and GACO minimize one objective over
// the whole box. NSGA-II and GACO also search whole-valued variables
// (Problem::num_integer: the index into a list of modules) as such, so a
// study's discrete variables take one run instead of one per combination.
// docs/solvers.md ("pagmo") has the table and the measured fronts.
//
// Constraints. pagmo's NSGA-II, MOEA/D, CMA-ES and SADE take unconstrained
// problems only, so the problem they see is penalized with a fixed scheme
// that reproduces Deb's constrained dominance (K. Deb, "An efficient
// constraint handling method for genetic algorithms", 2000):
//   feasible (max violation <= constraint_tolerance): the objectives as they are;
//   infeasible: every objective = kInfeasibleBase + violation;
//   failed evaluation: every objective = kFailedValue.
// A feasible point therefore dominates every infeasible one (as long as its
// objectives stay below kInfeasibleBase: the study's objectives are scaled
// to about 1), of two infeasible points the less violated one dominates, and
// among feasible points dominance is the true one. The front is then taken
// from the feasible evaluations only: no infeasible point can reach it.
//
// Pitfalls of Debian's pagmo 2.18 handled here:
//  * NSGA-II wants a population that is a multiple of 4 and at least 8, CMA-ES
//    at least 5, SADE at least 7, MOEA/D's "grid" weights a binomial count:
//    the automatic population respects them and the check says which;
//    MOEA/D uses the "low discrepancy" weights, which take any size;
//  * CMA-ES and SADE forget their adaptation between evolve() calls unless
//    `memory` is set: we evolve one generation at a time (for the stop
//    request, the budget and the labels), so memory is on;
//  * CMA-ES leaves the box unless force_bounds is set;
//  * CMA-ES, SADE and MOEA/D accept a problem with an integer part and then
//    hand it fractional values: they are refused for such problems;
//  * GACO keeps at most `ker` solutions and needs a population of at least
//    that many;
//  * pagmo reseeds nothing by itself: every seed comes from SolverSettings::seed.
//
// pagmo itself is called through librackopt_pagmo.so (pagmo_module.hpp),
// opened at the first run.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "rackopt/core/text.hpp"
#include "rackopt/doe/samplers.hpp"
#include "rackopt/solvers/adapters.hpp"
#include "rackopt/solvers/front_selection.hpp"
#include "rackopt/solvers/pagmo_library.hpp"

namespace rackopt::solvers::detail {

namespace {

constexpr double kInfeasibleBase = 1.0e6;
constexpr double kMaxViolationShown = 1.0e6;  // keeps base + violation exact enough to order
constexpr double kFailedValue = kInfeasibleBase * (2.0 + kMaxViolationShown);

// The objectives pagmo sees for an evaluation (see the file comment).
std::vector<double> penalized(const Evaluation& e, std::size_t objectives, double tolerance) {
  if (!e.ok()) return std::vector<double>(objectives, kFailedValue);
  const double v = max_violation(e);
  if (v > tolerance) return std::vector<double>(objectives, kInfeasibleBase + std::min(v, kMaxViolationShown));
  return std::vector<double>(e.objectives.begin(), e.objectives.end());
}

// The penalized problem on a tracker: one design, or many at once (the
// tracker hands them to Problem::evaluate_batch), fitness vectors in the
// order of `xs`.
pagmo_module::ProblemSettings penalized_problem(EvaluationTracker& tracker, std::size_t objectives,
                                                std::size_t integers, double tolerance) {
  pagmo_module::ProblemSettings p;
  p.objectives = objectives;
  p.integers = integers;
  p.lower = tracker.lower();
  p.upper = tracker.upper();
  p.fitness = [&tracker, objectives, tolerance](const std::vector<double>& x) {
    return penalized(tracker.at(x.data()), objectives, tolerance);
  };
  p.batch_fitness = [&tracker, objectives, tolerance](const std::vector<std::vector<double>>& xs) {
    std::vector<std::vector<double>> out;
    for (const Evaluation& e : tracker.at_batch(xs)) out.push_back(penalized(e, objectives, tolerance));
    return out;
  };
  return p;
}

using pagmo_module::Method;

struct MethodInfo {
  Method method;
  const char* name;
  bool fronts;
  std::size_t min_population;
  std::size_t population_multiple;
  const char* note;
  bool integers;  // keeps whole-valued variables whole
};

// GACO's solution archive: its default size, less when the population is
// smaller (it must hold at most a population).
constexpr std::size_t kGacoKernel = 63;

const std::vector<MethodInfo>& method_table() {
  static const std::vector<MethodInfo> table = {
      {Method::kNsga2, "nsga2", true, 8, 4,
       "NSGA-II: non-dominated sorting and crowding, SBX crossover and polynomial mutation; fronts of 2-4 "
       "objectives; discrete variables searched as integers",
       true},
      {Method::kMoead, "moead", true, 8, 1,
       "MOEA/D: decomposition into Tchebycheff sub-problems on low-discrepancy weights, differential evolution; "
       "fronts of 2-4 objectives",
       false},
      {Method::kCmaes, "cmaes", false, 5, 1, "CMA-ES: covariance matrix adaptation evolution strategy, one objective",
       false},
      {Method::kSade, "sade", false, 7, 1, "SADE: self-adaptive differential evolution (jDE), one objective", false},
      {Method::kGaco, "gaco", false, 8, 1,
       "GACO: extended ant colony optimization for mixed-integer problems, one objective; discrete variables "
       "searched as integers",
       true},
  };
  return table;
}

const MethodInfo* find_method(const std::string& name) {
  const std::string key = lower(name);
  for (const MethodInfo& m : method_table())
    if (key == m.name) return &m;
  return nullptr;
}

std::vector<std::string> method_names(bool fronts) {
  std::vector<std::string> names;
  for (const MethodInfo& m : method_table())
    if (m.fronts == fronts) names.push_back(m.name);
  return names;
}

// The population a run uses: the option when given, else a size that suits
// the method and the problem (rounded up to what the method accepts).
std::size_t population_size(const SolverBackend& backend, const SolverSettings& settings, const MethodInfo& m,
                            std::size_t dimension, std::size_t front_points) {
  std::size_t p = static_cast<std::size_t>(backend.option(settings, "population"));
  if (p == 0) {
    switch (m.method) {
      case Method::kNsga2:
      case Method::kMoead: p = std::max<std::size_t>(24, front_points); break;
      case Method::kCmaes:
        p = 4 + static_cast<std::size_t>(std::floor(3.0 * std::log(static_cast<double>(std::max<std::size_t>(1, dimension)))));
        p = std::max<std::size_t>(p, 8);
        break;
      case Method::kSade: p = std::max<std::size_t>(12, 5 * dimension); break;
      case Method::kGaco: p = std::max<std::size_t>(16, 5 * dimension); break;
    }
    p = std::max(p, m.min_population);
    p = (p + m.population_multiple - 1) / m.population_multiple * m.population_multiple;
  }
  return p;
}

pagmo_module::AlgorithmSettings algorithm_settings(const SolverBackend& backend, const SolverSettings& settings,
                                                   const MethodInfo& m, std::size_t dimension, std::size_t population) {
  pagmo_module::AlgorithmSettings a;
  a.method = m.method;
  a.seed = static_cast<unsigned>(settings.seed ^ (settings.seed >> 32));
  a.crossover_probability = backend.option(settings, "crossover_probability");
  const double mutation = backend.option(settings, "mutation_probability");
  a.mutation_probability = mutation > 0 ? mutation : 1.0 / static_cast<double>(std::max<std::size_t>(1, dimension));
  a.neighbours = static_cast<unsigned>(
      std::min<double>(backend.option(settings, "neighbours"), static_cast<double>(population - 1)));
  a.sigma0 = backend.option(settings, "sigma0");
  a.kernel = static_cast<unsigned>(std::min(kGacoKernel, population));
  return a;
}

// A point's whole-valued variables rounded to the nearest whole value (the
// bounds are whole, so it stays in the box).
void round_integer_part(std::vector<double>& x, std::size_t integers) {
  for (std::size_t i = x.size() - std::min(integers, x.size()); i < x.size(); ++i) x[i] = std::round(x[i]);
}

// One population run on a tracker: x0 and a Latin hypercube of the box as
// the first generation, then whole generations while the budget allows one.
// `on_generation(g)` is told before generation g is evaluated (0 = the first
// population). Ends by the budget, a halt (stop request, time) or, for one
// objective, `stall` generations without a better feasible point. Returns the
// generations completed after the first and whether the stall test ended it.
struct RunEnd {
  std::size_t generations = 0;
  bool stalled = false;
};
RunEnd evolve(EvaluationTracker& tracker, const SolverSettings& settings, const MethodInfo& m, std::size_t objectives,
              std::size_t integers, std::size_t population,
              const std::function<void(std::size_t)>& on_generation) {
  const SolverBackend& backend = pagmo_backend();
  const pagmo_module::ProblemSettings udp =
      penalized_problem(tracker, objectives, integers, settings.constraint_tolerance);
  const auto pop_seed = static_cast<unsigned>(settings.seed * 2654435761u + 17u);
  const std::unique_ptr<pagmo_module::Evolution> evolution =
      pagmo_api().start(udp, algorithm_settings(backend, settings, m, tracker.dimension(), population), pop_seed);
  RunEnd end;
  tracker.begin_start(0);
  on_generation(0);
  std::vector<std::vector<double>> first{tracker.x0()};
  if (population > 1) {
    auto lhs = doe::latin_hypercube(tracker.lower(), tracker.upper(), population - 1, settings.seed);
    // Whole-valued variables start whole: the hypercube's strata of an
    // index rounded to the nearest entry (x0 is rounded by minimize and front).
    for (auto& x : lhs) round_integer_part(x, integers);
    first.insert(first.end(), lhs.begin(), lhs.end());
  }
  // guard: a halt (budget, time, stop request) ends the run with every
  // evaluation kept by the tracker; anything else is rethrown by the caller.
  tracker.guard([&] {
    // The first population as one batch.
    const std::vector<std::vector<double>> first_f = udp.batch_fitness(first);
    for (std::size_t k = 0; k < first.size(); ++k) evolution->add(first[k], first_f[k]);
    const auto stall = static_cast<std::size_t>(backend.option(settings, "stall_generations"));
    double best = std::numeric_limits<double>::infinity();
    std::size_t since_better = 0;
    while (tracker.evaluations_so_far() + population <= settings.max_evaluations) {
      on_generation(end.generations + 1);
      evolution->evolve_generation();
      ++end.generations;
      if (objectives == 1 && stall > 0) {
        const double f = evolution->champion_objective();
        const double scale = settings.ftol_rel * std::abs(best) + settings.ftol_abs;
        if (f < best - scale || !std::isfinite(best)) {
          best = f;
          since_better = 0;
        } else if (++since_better >= stall) {
          end.stalled = true;
          break;
        }
      }
    }
  });
  return end;
}

class PagmoBackend final : public SolverBackend {
 public:
  std::string_view library() const override { return "pagmo"; }
  std::vector<BackendAlgorithm> algorithms() const override {
    std::vector<BackendAlgorithm> out;
    for (const MethodInfo& m : method_table()) out.push_back({m.name, m.fronts, m.note, m.integers});
    return out;
  }
  std::string default_algorithm() const override { return "nsga2"; }
  const std::vector<BackendOption>& options() const override {
    static const std::vector<BackendOption> table = {
        {"population", 0, 0, 100000, true, false,
         "individuals per generation; 0 = automatic (fronts: max(24, points) rounded up to a multiple of 4; "
         "CMA-ES 4 + 3 ln n, at least 8; SADE max(12, 5 n); GACO max(16, 5 n))"},
        {"crossover_probability", 0.95, 0, 1, false, false, "NSGA-II's SBX crossover probability"},
        {"mutation_probability", 0, 0, 1, false, false,
         "NSGA-II's polynomial mutation probability per variable; 0 = 1/n"},
        {"neighbours", 20, 2, 100000, true, false, "MOEA/D's neighbourhood size (capped at population - 1)"},
        {"sigma0", 0.3, 0, 1, false, true, "CMA-ES's initial step as a fraction of the box"},
        {"stall_generations", 30, 0, 100000, true, false,
         "one objective: end after this many generations without a better feasible point by ftol_rel/ftol_abs "
         "(0 = run the whole budget)"},
    };
    return table;
  }

  std::size_t max_front_objectives() const override { return 4; }

  std::optional<SolverSettingsRefusal> check(const SolverSettings& s, const ProblemShape& shape) const override {
    const MethodInfo* m = find_method(s.algorithm);
    if (!m)
      return SolverSettingsRefusal{SolverSetting::kAlgorithm,
                                   "unknown pagmo algorithm '" + s.algorithm + "'; valid names: " +
                                       join(method_names(true)) + " (Pareto fronts), " + join(method_names(false)) +
                                       " (one objective)",
                                   ""};
    if (!s.local_algorithm.empty())
      return SolverSettingsRefusal{SolverSetting::kLocalAlgorithm,
                                   "local_algorithm is only used by NLopt's AUGLAG and MLSL; pagmo's " +
                                       std::string(m->name) + " does not take one (leave it out)",
                                   ""};
    if (s.starts != 1)
      return SolverSettingsRefusal{SolverSetting::kNumbers,
                                   "starts must be 1 with pagmo: a population method starts from a whole "
                                   "population (x0 and a Latin hypercube of the box); raise population instead",
                                   ""};
    if (m->fronts && (shape.objectives < 2 || shape.objectives > max_front_objectives()))
      return SolverSettingsRefusal{SolverSetting::kAlgorithm,
                                   std::string(m->name) + " finds fronts of 2 to " +
                                       std::to_string(max_front_objectives()) + " objectives; the problem has " +
                                       std::to_string(shape.objectives) + "; for one objective use " +
                                       join(method_names(false)),
                                   ""};
    const std::size_t given = static_cast<std::size_t>(option(s, "population"));
    if (given != 0) {
      if (given < m->min_population || given % m->population_multiple != 0)
        return SolverSettingsRefusal{SolverSetting::kOption,
                                     std::string(m->name) + " needs a population of at least " +
                                         std::to_string(m->min_population) +
                                         (m->population_multiple > 1
                                              ? " and a multiple of " + std::to_string(m->population_multiple)
                                              : std::string()) +
                                         ", got " + std::to_string(given),
                                     "population"};
    }
    const std::size_t pop = population_size(*this, s, *m, shape.dimension, 0);
    if (s.max_evaluations < 2 * pop)
      return SolverSettingsRefusal{SolverSetting::kNumbers,
                                   "max_evaluations = " + std::to_string(s.max_evaluations) + " leaves " +
                                       std::string(m->name) + " no generation after the first population of " +
                                       std::to_string(pop) + "; give at least " + std::to_string(2 * pop) +
                                       " (about 50 generations, " + std::to_string(50 * pop) + ", is typical)",
                                   ""};
    return std::nullopt;
  }

  SolverResult minimize(const Problem& problem, std::span<const double> x0, const SolverSettings& settings,
                        const SolverCallbacks& callbacks) const override {
    const MethodInfo& m = *find_method(settings.algorithm);
    const std::vector<double> lo = problem.lower_bounds(), up = problem.upper_bounds();
    std::vector<double> x0c(x0.begin(), x0.end());
    for (std::size_t i = 0; i < x0c.size(); ++i) x0c[i] = std::clamp(x0c[i], lo[i], up[i]);
    round_integer_part(x0c, problem.num_integer());
    EvaluationTracker tracker(problem, settings, callbacks, x0c);
    const std::size_t pop = population_size(*this, settings, m, problem.dimension(), 0);
    const RunEnd end = evolve(tracker, settings, m, 1, problem.num_integer(), pop, [](std::size_t) {});
    tracker.rethrow_if_error();

    SolverResult result;
    tracker.fill_result(result);
    result.solver_message = std::string(m.name) + ": population " + std::to_string(pop) + ", " +
                            std::to_string(end.generations) + " generations";
    if (const auto ended = tracker.ending_status()) {
      result.status = *ended;
    } else if (end.stalled) {
      result.status = SolverStatus::kConverged;
      result.solver_message += " (no better feasible point in the last " +
                               std::to_string(static_cast<std::size_t>(option(settings, "stall_generations"))) +
                               " generations)";
    } else {
      result.status = SolverStatus::kMaxEvaluations;  // the budget had no room for another generation
    }
    return result;
  }

  ParetoResult front(const Problem& problem, std::span<const double> x0, const ParetoSettings& settings,
                     const ParetoCallbacks& callbacks) const override {
    const SolverSettings& s = settings.solver;
    const MethodInfo& m = *find_method(s.algorithm);
    const std::size_t n_obj = problem.num_objectives();
    const std::vector<double> lo = problem.lower_bounds(), up = problem.upper_bounds();
    std::vector<double> x0c(x0.begin(), x0.end());
    for (std::size_t i = 0; i < x0c.size(); ++i) x0c[i] = std::clamp(x0c[i], lo[i], up[i]);
    round_integer_part(x0c, problem.num_integer());

    std::string label;
    std::vector<ParetoPoint> archive;  // every feasible evaluation, in evaluation order
    bool stopped = false;
    SolverCallbacks cb;
    cb.observer = [&](const EvaluationRecord& rec) {
      if (is_feasible(rec.evaluation, s.constraint_tolerance))
        archive.push_back(ParetoPoint{rec.x, rec.evaluation, label, true});
      if (callbacks.observer) callbacks.observer(label, rec);
    };
    if (callbacks.stop)
      cb.stop = [&] {
        if (!callbacks.stop()) return false;
        stopped = true;
        return true;
      };
    EvaluationTracker tracker(problem, s, cb, x0c);
    const std::size_t pop = population_size(*this, s, m, problem.dimension(), settings.points);
    const RunEnd end = evolve(tracker, s, m, n_obj, problem.num_integer(), pop, [&](std::size_t g) {
      label = std::string(m.name) + " generation " + std::to_string(g);
    });
    tracker.rethrow_if_error();

    SolverResult counts;
    tracker.fill_result(counts);
    ParetoResult result = select_front(std::move(archive), settings.points, settings.duplicate_tolerance);
    result.evaluations = counts.evaluations;
    result.failed_evaluations = counts.failed_evaluations;
    result.subproblems = 1;
    result.generations = end.generations;
    result.population = pop;
    if (stopped || tracker.halt() == Halt::kStop)
      result.status = ParetoStatus::kStopped;
    else if (result.front.empty())
      result.status = ParetoStatus::kNoFeasiblePoint;
    else
      result.status = ParetoStatus::kOk;
    return result;
  }
};

}  // namespace

const SolverBackend& pagmo_backend() {
  static const PagmoBackend backend;
  return backend;
}

}  // namespace rackopt::solvers::detail
