#include "rackopt/wear/contact.hpp"

#include <algorithm>
#include <cmath>

#include "rackopt/core/error.hpp"

namespace rackopt {

HertzLineContact hertz_line_contact(double w, double r_eff, double e_star) {
  if (!(w >= 0) || !std::isfinite(w)) throw InputError({}, "", "Hertz contact: load per width must be >= 0 and finite");
  if (!(r_eff > 0) || !std::isfinite(r_eff))
    throw InputError({}, "", "Hertz contact: effective radius must be positive and finite");
  if (!(e_star > 0) || !std::isfinite(e_star))
    throw InputError({}, "", "Hertz contact: effective modulus must be positive and finite");
  HertzLineContact c;
  if (w == 0) return c;
  c.half_width = std::sqrt(4.0 * w * r_eff / (M_PI * e_star));
  c.peak_pressure = 2.0 * w / (M_PI * c.half_width);
  c.mean_pressure = 0.25 * M_PI * c.peak_pressure;
  return c;
}

RackPinionSliding::RackPinionSliding(double s_pitch, double min_pinion_rolling)
    : s_pitch_(s_pitch), floor_(min_pinion_rolling) {
  if (!(s_pitch > 0) || !std::isfinite(s_pitch)) throw InputError({}, "", "sliding: pitch point s_P must be positive");
  if (!(min_pinion_rolling > 0)) throw InputError({}, "", "sliding: the pinion rolling floor must be positive");
}

double RackPinionSliding::pinion_rolling(double s) const { return std::max(s, floor_); }

double RackPinionSliding::sliding(double s) const { return std::abs(s - s_pitch_); }

}  // namespace rackopt
