#include "rackopt/fe/plane_stress_model.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rackopt::fe {

void fix_node_set(PlaneStressModel& model, const std::string& set, int dof, double value) {
  for (int node : model.mesh.node_set(set)) model.supports.push_back({node, dof, value});
}

void check_equations(const std::vector<NodeEquation>& equations, int nodes, const std::string& where) {
  const auto fail = [&](const std::string& what) { throw std::invalid_argument(where + ": " + what); };
  for (const NodeEquation& eq : equations) {
    if (eq.terms.size() < 2) fail("an equation needs at least two terms");
    if (!(eq.terms.front().coefficient != 0)) fail("an equation's first (dependent) coefficient must not be 0");
    for (const EquationTerm& t : eq.terms) {
      if (t.node < 0 || t.node >= nodes) fail("equation on node " + std::to_string(t.node) + ", not in the mesh");
      if (t.dof != 1 && t.dof != 2) fail("equation dof " + std::to_string(t.dof) + " (allowed: 1 = x, 2 = y)");
      if (!std::isfinite(t.coefficient)) fail("equation coefficient is not finite");
    }
  }
}

void check_model(const PlaneStressModel& model) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("plane-stress model: " + what); };
  const int n = static_cast<int>(model.mesh.nodes.size());
  if (model.mesh.triangles.empty()) fail("the mesh has no triangles");
  if (!(model.youngs_modulus > 0) || !std::isfinite(model.youngs_modulus)) fail("Young's modulus must be positive");
  if (!(model.poisson_ratio > -1 && model.poisson_ratio < 0.5)) fail("Poisson's ratio must lie in (-1, 0.5)");
  if (model.supports.empty()) fail("no support: the body would float");
  for (const PrescribedDisplacement& s : model.supports) {
    if (s.node < 0 || s.node >= n) fail("support on node " + std::to_string(s.node) + ", not in the mesh");
    if (s.dof != 1 && s.dof != 2) fail("support dof " + std::to_string(s.dof) + " (allowed: 1 = x, 2 = y)");
    if (!std::isfinite(s.value)) fail("support value is not finite");
  }
  for (const NodeLoad& l : model.loads) {
    if (l.node < 0 || l.node >= n) fail("load on node " + std::to_string(l.node) + ", not in the mesh");
    if (!std::isfinite(l.fx) || !std::isfinite(l.fy)) fail("load is not finite");
  }
  check_equations(model.equations, n, "plane-stress model");
  for (const auto& [name, set] : model.mesh.node_sets) {
    check_set_name(name);
    for (int i : set) {
      if (i < 0 || i >= n) fail("node set " + name + " holds node " + std::to_string(i) + ", not in the mesh");
    }
  }
}

}  // namespace rackopt::fe
