// The table of solver libraries, and what every backend shares.
#include <algorithm>
#include <stdexcept>

#include "rackopt/core/text.hpp"
#include "rackopt/solvers/adapters.hpp"
#include "rackopt/solvers/solver_backend.hpp"

namespace rackopt::solvers {

const std::vector<const SolverBackend*>& solver_backends() {
  static const std::vector<const SolverBackend*> table = {
      &detail::nlopt_backend(),
      &detail::ipopt_backend(),
      &detail::pagmo_backend(),
  };
  return table;
}

const SolverBackend* find_solver_backend(std::string_view library) {
  const std::string wanted = lower(std::string(library));
  for (const SolverBackend* b : solver_backends())
    if (b->library() == wanted) return b;
  return nullptr;
}

std::vector<std::string> solver_library_names() {
  std::vector<std::string> names;
  for (const SolverBackend* b : solver_backends()) names.emplace_back(b->library());
  return names;
}

std::optional<BackendAlgorithm> SolverBackend::find_algorithm(std::string_view name) const {
  const std::string wanted = lower(std::string(name));
  for (const BackendAlgorithm& a : algorithms())
    if (lower(a.name) == wanted) return a;
  return std::nullopt;
}

bool SolverBackend::finds_fronts(const SolverSettings& settings) const {
  const auto a = find_algorithm(settings.algorithm);
  return a && a->fronts;
}

ParetoResult SolverBackend::front(const Problem&, std::span<const double>, const ParetoSettings&,
                                  const ParetoCallbacks&) const {
  throw std::logic_error(std::string(library()) + " has no front algorithm");
}

double SolverBackend::option(const SolverSettings& settings, std::string_view key) const {
  const auto& declared = options();
  const auto it = std::find_if(declared.begin(), declared.end(), [&](const BackendOption& o) { return o.key == key; });
  if (it == declared.end())
    throw std::logic_error(std::string(library()) + " declares no option '" + std::string(key) + "'");
  const auto given = settings.options.find(std::string(key));
  return given == settings.options.end() ? it->default_value : given->second;
}

}  // namespace rackopt::solvers
