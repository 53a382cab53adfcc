// Response of the rack drive running at a constant travel speed over the
// mesh force law (docs/models/dynamics.md): the periodic steady state over one
// excitation period (one support span), the dynamic factor, the parametric
// stability of the linearised drive (Floquet), and speed sweeps.
//
// The excitation is the travel X = v t: the law repeats with its period
// (time T = period / v) and holds the mesh order (v / p) and the support
// order (v / l). The static mesh force F_s is what the drive transmits at
// constant speed (thrust and gravity on the moving mass, motor torque
// balancing them); the response is the deviation from rigid-body motion.
//
// Example:
//   DriveTrain train = drive_train(drive);                    // drive_train_builder.hpp
//   MeshForceLaw law = build_mesh_force_law(drive, model);    // mesh_force_law_builder.hpp
//   DynamicsOptions o;  o.damping_ratio = 0.05;
//   SteadyResponse r = steady_response(train, law, 0.4, 50e3, o);
//   std::cout << "K_V = " << r.dynamic_factor << "\n";
#pragma once

#include <string>
#include <vector>

#include "rackopt/dynamics/drive_train.hpp"
#include "rackopt/dynamics/mesh_force_law.hpp"

namespace rackopt {

// Fidelity knobs (docs/accuracy.md, dynamics) and the damping.
struct DynamicsOptions {
  // Mesh damping: c = 2 zeta sqrt(k_mean m_mesh), k_mean the law's mean
  // stiffness; it acts only while the flanks touch. The drive spring gets the
  // same ratio of its own critical damping.
  double damping_ratio = 0.05;
  // Time steps per mesh period (p / v), and at least this many per period of
  // the highest natural frequency at the mean stiffness.
  int steps_per_mesh_period = 64;
  int steps_per_natural_period = 32;
  // Steady state: the state at the end of an excitation period repeats the
  // state at its start to this relative tolerance (of the static approach
  // F_s / k_mean and its rate); at most max_periods periods are integrated.
  double periodic_tolerance = 1e-6;
  int max_periods = 200;
  // Samples of the reported history per excitation period (force, DTE).
  int history_points = 2000;
};

enum class ResponseStatus {
  kConverged,     // periodic to the tolerance
  kNotPeriodic,   // max_periods reached (e.g. parametrically unstable, or chaotic with contact loss)
  kUnbounded,     // the approach grew beyond 1e3 static approaches: unstable
};

struct SteadyResponse {
  ResponseStatus status = ResponseStatus::kConverged;
  double speed = 0;              // v [m/s]
  double static_force = 0;       // F_s [N]
  double excitation_period_s = 0;  // period / v [s]
  // Over the steady period:
  double dynamic_factor = 0;     // K_V = max mesh force / F_s
  double mesh_force_max = 0, mesh_force_min = 0;  // [N] (min < 0: back-flank contact)
  double dte_max = 0, dte_min = 0;  // dynamic transmission error = approach delta [m]
  double dte_peak_to_peak = 0;      // [m]
  double contact_loss_fraction = 0; // time share with neither flank carrying load
  bool back_flank_contact = false;
  int periods = 0;                  // excitation periods integrated
  // History over one steady period, history_points samples: travel X in [0, period).
  std::vector<double> travel, mesh_force, dte;
  std::string message;              // why not converged, when not
};

// Periodic steady state at speed v > 0 under static mesh force F_s >= 0.
// Throws std::invalid_argument for bad arguments; never returns NaN: a
// response that grows without bound ends with kUnbounded.
SteadyResponse steady_response(const DriveTrain& train, const MeshForceLaw& law, double speed,
                               double static_force, const DynamicsOptions& options);

// Floquet multipliers of the drive linearised about its static state (each
// slot's tangent at the static approach, damping as in options) over one
// excitation period at speed v.
struct FloquetResult {
  std::vector<double> multiplier_magnitudes;  // |mu|, descending
  double spectral_radius = 0;                 // max |mu|: < 1 stable, > 1 parametrically unstable
  bool stable = true;
  // 1 - spectral_radius (> 0 stable): the parametric stability margin.
  double margin = 0;
};
FloquetResult floquet(const DriveTrain& train, const MeshForceLaw& law, double speed, double static_force,
                      const DynamicsOptions& options);

// K_V over speeds. With contact loss the response can have two branches; the
// sweep continues each speed from the previous speed's steady state, up
// (ascending) and down (descending), and reports both. When no speed of the
// rising sweep leaves front-flank contact (no separation, no back flank, every
// response periodic) the falling sweep is not run: its values are the rising
// ones (one periodic state), which halves the cost of a smooth drive.
struct SweepPoint {
  double speed = 0;
  double kv_up = 0, kv_down = 0;
  double dte_pp_up = 0, dte_pp_down = 0;
  double contact_loss_up = 0, contact_loss_down = 0;
  ResponseStatus status_up = ResponseStatus::kConverged, status_down = ResponseStatus::kConverged;
};
std::vector<SweepPoint> speed_sweep(const DriveTrain& train, const MeshForceLaw& law,
                                    const std::vector<double>& speeds, double static_force,
                                    const DynamicsOptions& options);

}  // namespace rackopt
