#include "rackopt/stiffness/mesh_ripple.hpp"

#include <algorithm>

namespace rackopt {

MeshRipple mesh_ripple(const std::vector<PeriodStats>& periods) {
  MeshRipple out;
  out.ripple.reserve(periods.size());
  double sum = 0;
  for (const PeriodStats& w : periods) {
    const double r = w.mean > 0 ? (w.max - w.min) / w.mean : 0.0;
    out.ripple.push_back(r);
    out.max = std::max(out.max, r);
    sum += r;
  }
  out.mean = periods.empty() ? 0.0 : sum / static_cast<double>(periods.size());
  return out;
}

}  // namespace rackopt
