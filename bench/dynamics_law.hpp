// A representative mesh force law for the dynamics benchmarks and the
// accuracy table (docs/accuracy.md, "Dynamics"): module 8 mm (p = 25.1 mm),
// contact ratio 1.6 (one and two tooth pairs alternating, jumps at the
// changes), 20 um tip relief over the first fifth of the entering pair,
// and one rack support span of 100 mesh periods whose foundation softens
// the mesh by up to 20 % midway between supports.
#pragma once

#include <cmath>

#include "rackopt/dynamics/drive_response.hpp"

namespace rackopt::bench {

inline MeshForceLaw representative_law() {
  MeshForceLaw law;
  const double p = M_PI * 8e-3, k1 = 4e8, relief = 20e-6;
  const int periods = 100;
  law.mesh_pitch = p;
  law.period = periods * p;
  law.slots = 2;
  auto span = [&](double X) { return 1 - 0.2 * std::pow(std::sin(M_PI * X / law.period), 2); };
  auto add = [&](double X, double ka, double kb, double gb) {
    law.travel.push_back(X);
    law.stiffness.insert(law.stiffness.end(), {ka * span(X), kb * span(X)});
    law.gap.insert(law.gap.end(), {0.0, gb});
  };
  for (int i = 0; i < periods; ++i) {
    // Two pairs over [0, 0.6 p): the entering one (slot 1) behind its relief.
    for (int j = 0; j <= 6; ++j) {
      const double u = j / 10.0;  // fraction of p
      const double g = u < 0.2 ? relief * std::pow(1 - u / 0.2, 2) : 0.0;
      add((i + u) * p, k1, k1, g);
    }
    add((i + 0.6) * p, k1, 0, 0);  // the leaving pair drops out: jump to one pair
    add((i + 1.0) * p, k1, 0, 0);  // the next period's first sample makes the jump back to two pairs
  }
  law.period = law.travel.back();
  return law;
}

inline DriveTrain representative_train() {
  DriveTrain t;
  t.drive_inertia = 2.0;   // motor and gearbox at the pinion shaft [kg m^2]
  t.pinion_inertia = 0.3;
  t.moving_mass = 20e3;
  t.base_radius = 0.1;
  t.pressure_angle = 20 * M_PI / 180;
  return t;
}

}  // namespace rackopt::bench
