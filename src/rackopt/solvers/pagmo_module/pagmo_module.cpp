// librackopt_pagmo.so: the only code that includes pagmo's headers and links
// libpagmo (pagmo_module.hpp says why it is a module of its own). It wraps
// pagmo's population, algorithms and hypervolume; the penalty scheme, the
// budget, the labels and the front selection stay in pagmo_backend.cpp.
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/gaco.hpp>
#include <pagmo/algorithms/moead.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/bfe.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/utils/hypervolume.hpp>

#include <stdexcept>
#include <string>
#include <utility>

#include "rackopt/solvers/pagmo_module.hpp"

namespace rackopt::solvers::pagmo_module {
namespace {

// The problem as pagmo sees it. Copies share the callbacks: pagmo copies
// its problem into every population.
struct CallbackProblem {
  ProblemSettings settings;

  pagmo::vector_double fitness(const pagmo::vector_double& x) const { return settings.fitness(x); }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {settings.lower, settings.upper};
  }
  pagmo::vector_double::size_type get_nobj() const { return settings.objectives; }
  pagmo::vector_double::size_type get_nix() const { return settings.integers; }
  std::string get_name() const { return "rackopt penalized problem"; }
};

// pagmo's batch fitness evaluator: a generation's offspring go to the
// problem's batch fitness as one batch (flattened decision vectors in,
// flattened fitness vectors out, as pagmo's bfe contract says).
struct CallbackBatchEvaluator {
  pagmo::vector_double operator()(const pagmo::problem& p, const pagmo::vector_double& dvs) const {
    const CallbackProblem* udp = p.extract<CallbackProblem>();
    if (!udp) throw std::logic_error("the pagmo batch evaluator serves the rackopt problem only");
    const std::size_t n = p.get_nx();
    std::vector<std::vector<double>> xs;
    for (std::size_t k = 0; k + n <= dvs.size(); k += n)
      xs.emplace_back(dvs.begin() + static_cast<std::ptrdiff_t>(k), dvs.begin() + static_cast<std::ptrdiff_t>(k + n));
    pagmo::vector_double out;
    for (const auto& f : udp->settings.batch_fitness(xs)) out.insert(out.end(), f.begin(), f.end());
    return out;
  }
  std::string get_name() const { return "rackopt evaluation tracker"; }
};

pagmo::algorithm make_algorithm(const AlgorithmSettings& a) {
  switch (a.method) {
    case Method::kNsga2: {
      pagmo::nsga2 nsga2(1u, a.crossover_probability, 10.0, a.mutation_probability, 20.0, a.seed);
      nsga2.set_bfe(pagmo::bfe(CallbackBatchEvaluator{}));
      return pagmo::algorithm(nsga2);
    }
    case Method::kMoead:
      return pagmo::algorithm(
          pagmo::moead(1u, "low discrepancy", "tchebycheff", a.neighbours, 1.0, 0.5, 20.0, 0.9, 2u, true, a.seed));
    case Method::kCmaes:
      return pagmo::algorithm(pagmo::cmaes(1u, -1, -1, -1, -1, a.sigma0, 0, 0, true, true, a.seed));
    case Method::kSade: return pagmo::algorithm(pagmo::sade(1u, 2u, 1u, 0, 0, true, a.seed));
    case Method::kGaco: {
      // pagmo's threshold of 1: the greedy q = 0.01 from the first
      // generation (q = 1 until a threshold of half the budget's generations
      // ended on a worse optimum of the shipped gantry sizing study, and
      // made the search depend on the budget).
      pagmo::gaco gaco(1u, a.kernel, 1.0, 0.0, 0.01, 1u, 7u, 100000u, 100000u, 0.0, true, a.seed);
      gaco.set_bfe(pagmo::bfe(CallbackBatchEvaluator{}));
      return pagmo::algorithm(gaco);
    }
  }
  throw std::logic_error("unknown pagmo method");
}

class PagmoEvolution final : public Evolution {
 public:
  PagmoEvolution(const ProblemSettings& problem, const AlgorithmSettings& algorithm, unsigned population_seed)
      : pop_(pagmo::problem(CallbackProblem{problem}), 0u, population_seed), algo_(make_algorithm(algorithm)) {}
  void add(const std::vector<double>& x, const std::vector<double>& f) override { pop_.push_back(x, f); }
  void evolve_generation() override { pop_ = algo_.evolve(pop_); }
  double champion_objective() const override { return pop_.champion_f()[0]; }

 private:
  pagmo::population pop_;
  pagmo::algorithm algo_;
};

std::unique_ptr<Evolution> start(const ProblemSettings& problem, const AlgorithmSettings& algorithm,
                                 unsigned population_seed) {
  return std::make_unique<PagmoEvolution>(problem, algorithm, population_seed);
}

double hypervolume(const std::vector<std::vector<double>>& points, const std::vector<double>& reference) {
  const pagmo::hypervolume hv(points, true);
  return hv.compute(reference);
}

}  // namespace
}  // namespace rackopt::solvers::pagmo_module

extern "C" __attribute__((visibility("default"))) const rackopt::solvers::pagmo_module::Api*
rackopt_pagmo_module_api() {
  static const rackopt::solvers::pagmo_module::Api api{rackopt::solvers::pagmo_module::kAbi,
                                                       &rackopt::solvers::pagmo_module::start,
                                                       &rackopt::solvers::pagmo_module::hypervolume};
  return &api;
}
