// Extremes and mean of a quantity of the mesh state (stiffness, approach)
// over each mesh period of a stiffness curve: the pieces the mesh ripple and
// the transmission error are made of (docs/models/transmission_error.md).
//
// Example:
//   MeshStiffnessModel model(drive);
//   StiffnessCurve curve = model.curve();
//   auto periods = period_stats(model, curve, CurveQuantity::kStiffness);
//   for (const PeriodStats& w : periods) use(w.start, w.min, w.max, w.mean);
#pragma once

#include <vector>

#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt {

enum class CurveQuantity {
  kStiffness,  // MeshState::stiffness [N/m]
  kApproach,   // MeshState::approach [m] (static transmission error)
};

// One mesh period: a window of travel one circular pitch p = pi m long (the
// pairs' pattern repeats when the rack moves by p; along the line of action
// that is one base pitch).
struct PeriodStats {
  double start = 0, end = 0;  // travel window [m]
  double min = 0, max = 0;    // extremes over the window
  double travel_at_min = 0, travel_at_max = 0;
  double mean = 0;            // (1/p) * integral over the window
};

// Mesh periods covering [0, span]: [k p, (k+1) p] for each whole period from
// the left support, and, when the span is not a whole number of periods, one
// more period ending at the span end, [span - p, span] (it overlaps the one
// before: every window is one full period). A span shorter than p gives the
// one window [0, span].
std::vector<PeriodStats> period_stats(const MeshStiffnessModel& model, const StiffnessCurve& curve,
                                      CurveQuantity quantity);

// Value of `quantity` in `state`.
double curve_quantity(const MeshState& state, CurveQuantity quantity);

}  // namespace rackopt
