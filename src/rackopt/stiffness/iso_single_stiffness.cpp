#include "rackopt/stiffness/iso_single_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rackopt/core/error.hpp"

namespace rackopt {

IsoSingleStiffness iso_single_stiffness(const Drive& drive) {
  const PinionSpec& p = drive.pinion;
  const double b_rack = drive.rack.face_width > 0 ? drive.rack.face_width : p.face_width;
  const double b = std::min(p.face_width, b_rack);
  const double E1 = p.material.youngs_modulus, E2 = drive.rack.material.youngs_modulus;
  if (!(b > 0) || !(E1 > 0) || !(E2 > 0) || p.teeth < 1) {
    throw InputError({}, "pinion", "ISO single stiffness needs positive width, moduli and teeth");
  }
  IsoSingleStiffness out;
  const double z1 = p.teeth, x1 = p.profile_shift;
  out.q_prime = 0.04723 + 0.15551 / z1 - 0.00635 * x1 - 0.11654 * x1 / z1 + 0.00529 * x1 * x1;
  out.c_theoretical = 1.0 / out.q_prime;
  const double alpha_deg = p.pressure_angle * 180.0 / std::numbers::pi;
  // h_fP: the dedendum of the basic rack that cut the pinion.
  out.basic_rack_factor = (1 + 0.5 * (1.2 - p.dedendum_coef)) * (1 - 0.02 * (20.0 - alpha_deg));
  const double e_ratio = (2 * E1 * E2 / (E1 + E2)) / 206e9;
  // Nominal tangential force on the pitch circle per unit width, N/mm.
  const double ft_per_mm = drive.load.force * std::cos(p.pressure_angle) / (b * 1e3);
  out.load_factor = ft_per_mm < 100 ? std::pow(std::max(ft_per_mm, 0.0) / 100, 0.25) : 1.0;
  out.c_prime = out.c_theoretical * 0.8 * out.basic_rack_factor * e_ratio * out.load_factor;
  out.stiffness = out.c_prime * (b * 1e3) * 1e6;  // N/um -> N/m
  return out;
}

}  // namespace rackopt
