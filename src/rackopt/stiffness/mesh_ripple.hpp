// The mesh ripple: the fluctuation of the mesh stiffness within each mesh
// period, (k_max - k_min)/k_mean of that period, its worst and its mean over
// one rack span. Unlike StiffnessCurve::k_fluctuation it leaves out the slow
// change of stiffness along the span (the rack body on its hinges)
// (docs/models/transmission_error.md, docs/metrics.md).
//
// Example:
//   MeshRipple r = mesh_ripple(period_stats(model, curve, CurveQuantity::kStiffness));
//   std::cout << r.max << " " << r.mean << "\n";
#pragma once

#include <vector>

#include "rackopt/stiffness/period_stats.hpp"

namespace rackopt {

struct MeshRipple {
  std::vector<double> ripple;  // per period: (k_max - k_min)/k_mean [-]
  double max = 0;              // worst period [-]
  double mean = 0;             // mean over the periods [-]
};

// From the stiffness statistics of the periods (CurveQuantity::kStiffness).
// A period with k_mean <= 0 has ripple 0.
MeshRipple mesh_ripple(const std::vector<PeriodStats>& stiffness_periods);

}  // namespace rackopt
