// A 2-D plane-stress problem as the FE reference solves it: a mesh, one
// linear-elastic isotropic material, prescribed nodal displacements and
// nodal forces. Everything is per unit thickness (forces in N per metre of
// thickness), so results compare directly with 2-D elasticity and with the
// per-face-width stiffness of the analytic models.
#pragma once

#include <string>
#include <vector>

#include "rackopt/fe/mesh2d.hpp"

namespace rackopt::fe {

// Displacement component `dof` (1 = x, 2 = y) of node `node` held at `value` (m).
struct PrescribedDisplacement {
  int node = 0;
  int dof = 1;
  double value = 0;
};

// Force on node `node` (N per metre of thickness).
struct NodeLoad {
  int node = 0;
  double fx = 0;
  double fy = 0;
};

// One term c * u_dof(node) of a linear constraint.
struct EquationTerm {
  int node = 0;
  int dof = 1;  // 1 = x, 2 = y
  double coefficient = 0;
};

// A homogeneous linear constraint between nodal displacements,
// sum of the terms = 0 (CalculiX *EQUATION). The first term's component is
// the dependent one that ccx eliminates: it must not be held by a support
// nor be the first term of another equation, and its coefficient must not
// be 0. Keep the coefficients summing to 0 per direction where the
// constraint is meant to transmit no net force (a rigid tie).
struct NodeEquation {
  std::vector<EquationTerm> terms;
};

struct PlaneStressModel {
  Mesh2D mesh;
  double youngs_modulus = 0;  // Pa
  double poisson_ratio = 0;
  std::vector<PrescribedDisplacement> supports;
  std::vector<NodeLoad> loads;
  std::vector<NodeEquation> equations;
};

// Appends supports holding component `dof` of every node of set `set` at `value`.
void fix_node_set(PlaneStressModel& model, const std::string& set, int dof, double value = 0);

// Throws std::invalid_argument naming what is wrong: no triangles, E <= 0,
// nu outside (-1, 0.5), a node index out of range, a dof other than 1 or 2,
// a non-finite number, no support at all, an equation with fewer than two
// terms or a zero first coefficient.
void check_model(const PlaneStressModel& model);

// The equation checks of check_model for a mesh of `nodes` nodes; the
// message starts with `where`.
void check_equations(const std::vector<NodeEquation>& equations, int nodes, const std::string& where);

}  // namespace rackopt::fe
