// Test drives for the wear tests: problems/ship_lift.yaml (the wear paper's drive) with the
// wear and duty filled in C++ (the problem loader does not read them yet).
#pragma once

#include <string>

#include "rackopt/core/drive.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::test {

inline Drive ship_lift() { return test_support::load_shipped_problem("ship_lift.yaml"); }

// The wear paper's polynomial H = -0.25h^3 - 1.6786h^2 + 2h + 596 (HB, h in mm),
// converted to SI (Pa, h in m): c_i [HB/mm^i] * kPaPerHB * 1e3^i.
inline HardnessProfile wear_paper_polynomial(double valid_depth = 6.5e-3, double core = 0) {
  HardnessProfile p;
  p.kind = HardnessProfile::Kind::kPolynomial;
  p.coefficients = {596 * kPaPerHB, 2 * kPaPerHB * 1e3, -1.6786 * kPaPerHB * 1e6, -0.25 * kPaPerHB * 1e9};
  p.valid_depth = valid_depth;
  p.core = core;
  return p;
}

inline HardnessProfile constant_hardness(double hb) {
  HardnessProfile p;
  p.kind = HardnessProfile::Kind::kConstant;
  p.surface = hb * kPaPerHB;
  return p;
}

// The wear paper's wear set-up: K = 3e-6 (docs/models/wear.md), h_max = 1.5 mm, the
// polynomial hardness on both members, 4000 rack passes a year (an assumption:
// only the order of magnitude matters for these tests).
inline Drive ship_lift_wear() {
  Drive d = ship_lift();
  d.wear.coefficient = 3e-6;
  d.wear.max_depth = 1.5e-3;
  d.wear.pinion_hardness = wear_paper_polynomial();
  d.wear.rack_hardness = wear_paper_polynomial();
  d.wear.min_contact_ratio = 1.0;
  d.duty.rack_meshes_per_year = 4000;
  d.duty.pinion_meshes_per_year = 4000;
  // The model's defaults, not the shipped calibration's (which freezes the
  // profile and uses 240 points: problems/ship_lift.yaml).
  d.wear.update_profile = true;
  d.wear.profile_points = 60;
  return d;
}

}  // namespace rackopt::test
