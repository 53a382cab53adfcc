// Load sharing of tooth pairs pressed together by one rigid approach, with
// unilateral contact and initial gaps (profile relief)
// (docs/models/transmission_error.md).
//
// The pairs share the approach delta along the line of action. Pair i has an
// initial gap g_i >= 0 and the pairs' compliances (local and body, coupled)
// form the symmetric positive definite matrix C [m/N]. The forces f solve
//   C f = delta 1 - g  on the pairs that carry load (f_i >= 0),
//   (C f)_i >= delta - g_i on the others (they stay open), sum f = F,
// which is the minimum of f^T C f / 2 + g^T f over f >= 0, sum f = F: a
// strictly convex problem with one solution; delta is the multiplier of the
// load balance.
//
// Example:
//   std::vector<double> C{c11, c12, c12, c22}, gap{0.0, 20e-6};
//   LoadedContact lc = solve_loaded_contact(C, gap, 50e3);
//   // lc.approach [m], lc.force[i] [N], lc.tangent_stiffness [N/m]
#pragma once

#include <span>
#include <vector>

namespace rackopt {

struct LoadedContact {
  std::vector<double> force;     // f_i [N], >= 0, sum = F
  std::vector<bool> loaded;      // pair i in the active set (carries load)
  double approach = 0;           // delta [m]
  // dF/d delta at this load = 1^T C_A^-1 1 over the loaded pairs [N/m]: the
  // stiffness a small load change sees (the active set does not change).
  double tangent_stiffness = 0;
};

// `C` is n x n row major (n = gap.size(), 1 <= n <= 8), symmetric positive
// definite; gaps finite; F >= 0. Throws std::invalid_argument for bad sizes
// and std::runtime_error when C is not positive definite on a subset.
LoadedContact solve_loaded_contact(std::span<const double> C, std::span<const double> gap, double F);

}  // namespace rackopt
