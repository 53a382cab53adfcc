#include "rackopt/stiffness/transmission_error.hpp"

#include <algorithm>

namespace rackopt {

TransmissionError transmission_error(const std::vector<PeriodStats>& periods) {
  TransmissionError out;
  if (periods.empty()) return out;
  out.min = periods.front().min;
  out.max = periods.front().max;
  out.travel_at_min = periods.front().travel_at_min;
  out.travel_at_max = periods.front().travel_at_max;
  double sum = 0;
  for (const PeriodStats& w : periods) {
    if (w.min < out.min) {
      out.min = w.min;
      out.travel_at_min = w.travel_at_min;
    }
    if (w.max > out.max) {
      out.max = w.max;
      out.travel_at_max = w.travel_at_max;
    }
    const double pp = w.max - w.min;
    out.period_peak_to_peak.push_back(pp);
    out.period_max = std::max(out.period_max, pp);
    sum += pp;
  }
  out.peak_to_peak = out.max - out.min;
  out.period_mean = sum / static_cast<double>(periods.size());
  return out;
}

}  // namespace rackopt
