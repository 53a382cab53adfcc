// The rack drive as a vibrating system (docs/models/dynamics.md): the drive
// (motor and gearbox reduced to the pinion shaft), an optional torsional
// spring from it to the pinion, the pinion, and the moving mass the pinion
// drives along the fixed rack. The mesh acts along the line of action:
//   delta = r_b theta_p - x cos(alpha)        (approach of the flanks [m])
// which is the pinion's roll minus the mass's travel, both seen along the
// line of action (r_b = r cos alpha, so rolling without load keeps delta 0).
//
// The rigid-body motion (everything moving at the travel speed) carries no
// spring: the vibration coordinates are y = (delta) for a rigid drive train,
// y = (delta, phi = theta_m - theta_p) with a drive spring. ReducedSystem is
// the drive train in those coordinates: M_r y'' + C y' + K(X) y = f, the
// rigid-body coordinate eliminated exactly (its equation of motion solved
// for its acceleration), not neglected.
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace rackopt {

struct DriveTrain {
  double drive_inertia = 0;    // J_m: motor + gearbox reduced to the pinion shaft [kg m^2] (>= 0)
  double pinion_inertia = 0;   // J_p [kg m^2] (> 0 when the drive train is rigid and J_m = 0)
  double drive_stiffness = 0;  // k_d torsional, drive to pinion [N m/rad]; 0 = rigid drive train
  double moving_mass = 0;      // M: what this pinion drives along the rack [kg] (> 0)
  double base_radius = 0;      // r_b [m]
  double pressure_angle = 0;   // alpha: line of action to the rack axis [rad]
  bool rigid() const { return drive_stiffness <= 0; }
  int degrees_of_freedom() const { return rigid() ? 1 : 2; }  // vibration coordinates
};

// The drive train in vibration coordinates. Index 0 is delta (along the line
// of action, m); index 1, with a drive spring, the drive twist phi (rad).
struct ReducedSystem {
  Eigen::MatrixXd mass;            // M_r (symmetric positive definite)
  Eigen::MatrixXd drive_stiffness; // K without the mesh: k_d on phi (zero for a rigid drive train)
  // The mesh's stiffness enters only K(0, 0); a mesh stiffness k gives K = drive_stiffness + k e0 e0^T.
  // Effective mass of the mesh alone, 1 / (r_b^2/J + cos^2 alpha / M) with J = J_m + J_p
  // (rigid drive train), or 1 / (r_b^2/J_p + cos^2 alpha / M) with a drive spring [kg].
  double mesh_mass = 0;
};

// Throws std::invalid_argument for a drive train that cannot move (M <= 0,
// J <= 0, non-finite values) with the quantity's name.
ReducedSystem reduce(const DriveTrain& train);

// Undamped natural frequencies [Hz] of the linearised drive at mesh stiffness
// k [N/m], lowest first (the rigid-body mode excluded): one with a rigid drive
// train, sqrt(k (r_b^2/J + cos^2 alpha / M)) / 2 pi; two with a drive spring.
std::vector<double> natural_frequencies_hz(const DriveTrain& train, double mesh_stiffness);

}  // namespace rackopt
