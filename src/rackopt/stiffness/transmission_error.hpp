// Static transmission error under load: the mesh deflection delta(X) along
// the line of action at which the pairs in contact carry load.force
// (MeshState::approach; with profile relief from the loaded contact solve),
// its peak-to-peak over one rack span and within each mesh period
// (docs/models/transmission_error.md).
//
// Example:
//   MeshStiffnessModel model(drive);
//   StiffnessCurve curve = model.curve();
//   TransmissionError te = transmission_error(period_stats(model, curve, CurveQuantity::kApproach));
//   std::cout << te.peak_to_peak * 1e6 << " um over the span\n";
#pragma once

#include <vector>

#include "rackopt/stiffness/period_stats.hpp"

namespace rackopt {

struct TransmissionError {
  double min = 0, max = 0;               // delta extremes over the span [m]
  double travel_at_min = 0, travel_at_max = 0;
  double peak_to_peak = 0;               // max - min over the span [m]
  std::vector<double> period_peak_to_peak;  // per mesh period [m]
  double period_max = 0;                 // worst period [m]
  double period_mean = 0;                // mean over the periods [m]
};

// From the approach statistics of the periods (CurveQuantity::kApproach);
// the periods cover the span, so their extremes are the span's.
TransmissionError transmission_error(const std::vector<PeriodStats>& approach_periods);

}  // namespace rackopt
