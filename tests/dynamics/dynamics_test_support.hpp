// Laws and drive trains shared by the dynamics tests: hand-built laws whose
// exact responses have closed forms (docs/models/dynamics.md).
#pragma once

#include <cmath>
#include <functional>
#include <limits>

#include "rackopt/dynamics/drive_response.hpp"
#include "rackopt/dynamics/drive_train.hpp"
#include "rackopt/dynamics/mesh_force_law.hpp"

namespace rackopt::dyntest {

// A rigid drive: J = 2 kg m^2 at r_b = 0.1 m, 20 degrees, 5000 kg.
inline DriveTrain rigid_train() {
  DriveTrain t;
  t.drive_inertia = 1.5;
  t.pinion_inertia = 0.5;
  t.moving_mass = 5000;
  t.base_radius = 0.1;
  t.pressure_angle = 20 * M_PI / 180;
  return t;
}

// One slot, sampled at n+1 travels over the period: stiffness k(X), gap g(X).
inline MeshForceLaw one_slot_law(double period, double pitch, int n, const std::function<double(double)>& k,
                                 const std::function<double(double)>& g,
                                 double backlash = std::numeric_limits<double>::infinity()) {
  MeshForceLaw law;
  law.period = period;
  law.mesh_pitch = pitch;
  law.slots = 1;
  law.backlash = backlash;
  for (int i = 0; i <= n; ++i) {
    const double X = i == n ? period : period * i / n;
    law.travel.push_back(X);
    law.stiffness.push_back(k(X));
    law.gap.push_back(g(X));
  }
  return law;
}

inline MeshForceLaw constant_law(double k, double period = 0.02, double pitch = 0.02) {
  return one_slot_law(period, pitch, 1, [k](double) { return k; }, [](double) { return 0.0; });
}

// Constant stiffness, gap a (1 + sin(2 pi X / period)) >= 0: a kinematic error.
inline MeshForceLaw harmonic_gap_law(double k, double a, double period, int n,
                                     double backlash = std::numeric_limits<double>::infinity()) {
  return one_slot_law(period, period, n, [k](double) { return k; },
                      [a, period](double X) { return a * (1 + std::sin(2 * M_PI * X / period)); }, backlash);
}

// Square wave k0 (1 + eps) on the first half period, k0 (1 - eps) on the second.
inline MeshForceLaw square_wave_law(double k0, double eps, double period) {
  MeshForceLaw law;
  law.period = law.mesh_pitch = period;
  law.slots = 1;
  law.travel = {0, period / 2, period / 2, period};
  law.stiffness = {k0 * (1 + eps), k0 * (1 + eps), k0 * (1 - eps), k0 * (1 - eps)};
  law.gap = {0, 0, 0, 0};
  return law;
}

inline double mesh_mass(const DriveTrain& t) {
  const double J = t.drive_inertia + t.pinion_inertia, c = std::cos(t.pressure_angle);
  return 1 / (t.base_radius * t.base_radius / J + c * c / t.moving_mass);
}

}  // namespace rackopt::dyntest
