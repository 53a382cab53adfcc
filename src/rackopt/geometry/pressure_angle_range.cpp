#include "rackopt/geometry/pressure_angle_range.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "rackopt/core/error.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kLow = 5 * kDeg, kHigh = 45 * kDeg, kStep = 0.25 * kDeg, kTol = 0.001 * kDeg;

// nullopt when feasible, else the DesignError code.
std::optional<std::string> failure_at(Drive d, double angle) {
  d.pinion.pressure_angle = angle;
  try {
    build_mesh_geometry(d);
    return std::nullopt;
  } catch (const DesignError& e) {
    return e.code();
  }
}

// From a feasible angle, walk towards `end` in steps, then bisect the first
// change to kTol. Returns the last feasible angle and the code beyond it.
std::pair<double, std::string> edge(const Drive& d, double from, double end) {
  const double dir = end > from ? 1 : -1;
  double ok = from;
  for (;;) {
    const double next = std::abs(end - ok) <= kStep ? end : ok + dir * kStep;
    const auto f = failure_at(d, next);
    if (!f) {
      if (next == end) return {end, ""};
      ok = next;
      continue;
    }
    double bad = next;
    std::string code = *f;
    while (std::abs(bad - ok) > kTol) {
      const double mid = 0.5 * (ok + bad);
      if (const auto g = failure_at(d, mid)) {
        bad = mid;
        code = *g;
      } else {
        ok = mid;
      }
    }
    return {ok, code};
  }
}

}  // namespace

PressureAngleRange feasible_pressure_angles(const Drive& drive) {
  PressureAngleRange r;
  const double a = drive.pinion.pressure_angle;
  if (failure_at(drive, a)) return r;
  r.found = true;
  std::tie(r.lower, r.lower_limit) = edge(drive, a, kLow);
  std::tie(r.upper, r.upper_limit) = edge(drive, a, kHigh);
  return r;
}

}  // namespace rackopt
