// The calls rackopt makes into pagmo 2.18, behind a small interface that a
// separate shared module (librackopt_pagmo.so, built from
// solvers/pagmo_module/) implements. libpagmo's static initialisers and the
// libraries it pulls in (Boost.Serialization, TBB) cost every process about a
// tenth of a second of CPU and 25 MiB before main() when linked, while only a
// study with a pagmo algorithm or a front hypervolume calls it; the module is
// opened with dlopen the first time one of those is asked for
// (pagmo_library.hpp). Nothing here includes a pagmo header.
//
// The module and the program are built together from one tree: the types
// below cross the boundary as C++ types, and the module refuses a program of
// another version (kAbi).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace rackopt::solvers::pagmo_module {

// Bumped with every change to the types below.
inline constexpr int kAbi = 1;
// The one symbol the module exports: `const Api* rackopt_pagmo_module_api()`.
inline constexpr const char* kEntrySymbol = "rackopt_pagmo_module_api";

enum class Method { kNsga2, kMoead, kCmaes, kSade, kGaco };

// One algorithm's settings (pagmo's constructor arguments rackopt varies).
struct AlgorithmSettings {
  Method method = Method::kNsga2;
  unsigned seed = 0;
  double crossover_probability = 0.95;  // NSGA-II
  double mutation_probability = 0.1;    // NSGA-II, per variable
  unsigned neighbours = 20;             // MOEA/D
  double sigma0 = 0.3;                  // CMA-ES
  unsigned kernel = 63;                 // GACO's solution archive
};

// Fitness vectors (pagmo's layout: the objectives) of decision vectors.
using Fitness = std::function<std::vector<double>(const std::vector<double>& x)>;
// Many at once, in the order of `xs`: the batch evaluator of NSGA-II and GACO.
using BatchFitness = std::function<std::vector<std::vector<double>>(const std::vector<std::vector<double>>& xs)>;

// The unconstrained box problem pagmo evolves (rackopt penalizes constraints
// before pagmo sees them: pagmo_backend.cpp).
struct ProblemSettings {
  std::size_t objectives = 1;
  std::size_t integers = 0;  // the last `integers` variables are whole-valued
  std::vector<double> lower, upper;
  Fitness fitness;
  BatchFitness batch_fitness;
};

// One population and its algorithm. Exceptions thrown by the fitness
// functions pass through unchanged.
class Evolution {
 public:
  virtual ~Evolution() = default;
  // Adds an individual whose fitness is already known.
  virtual void add(const std::vector<double>& x, const std::vector<double>& f) = 0;
  // One generation of the algorithm over the population.
  virtual void evolve_generation() = 0;
  // The best objective 0 of the population (one objective).
  virtual double champion_objective() const = 0;
};

struct Api {
  int abi = kAbi;
  // An empty population of `problem` (seeded by population_seed) and the algorithm.
  std::unique_ptr<Evolution> (*start)(const ProblemSettings& problem, const AlgorithmSettings& algorithm,
                                      unsigned population_seed) = nullptr;
  // The exact hypervolume (pagmo's WFG / HV2D / HV3D) dominated by `points`
  // (2 or more objectives, each point better than `reference` in every one).
  double (*hypervolume)(const std::vector<std::vector<double>>& points, const std::vector<double>& reference) = nullptr;
};

}  // namespace rackopt::solvers::pagmo_module
