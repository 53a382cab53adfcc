// The dynamic analysis of one drive as `rackopt dynamics`, its metrics and a
// study's report ask for it (docs/models/dynamics.md): the drive train and
// the mesh force law built once from the static model, the natural
// frequencies along the travel and where the excitation orders cross them
// (Campbell), the steady response at the operating speed, K_V over the speed
// range (up and down), and the parametric stability over speed.
//
// Example:
//   Drive drive = load_problem("problems/gantry_axis.yaml");
//   MeshStiffnessModel model(drive);
//   DriveDynamics d = analyse_drive_dynamics(drive, model, DynamicsRequest{});
//   std::cout << "K_V max " << d.kv_max << "\n";
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/dynamics/drive_response.hpp"
#include "rackopt/dynamics/drive_train.hpp"
#include "rackopt/dynamics/mesh_force_law.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt {

// What to compute beyond the drive train, the law and the natural frequencies
// (which cost microseconds). Each part off costs nothing.
struct DynamicsRequest {
  bool response_at_speed = true;   // steady response at the operating speed
  std::optional<double> speed;     // operating speed [m/s]; absent = load.speed
  bool sweep = true;               // K_V over the speed range, up and down
  bool stability = false;          // Floquet spectral radius over the speed range
  int positions_per_period = 0;    // law samples per mesh period; 0 = the drive's numerics
  DynamicsOptions options;         // fidelity; damping_ratio is taken from drive.dynamics
};

// An excitation order: a frequency proportional to the speed, f = v / wavelength.
struct ExcitationOrder {
  std::string name;        // "mesh", "2 x mesh", "3 x mesh", "span"
  double wavelength = 0;   // [m]: p, p/2, p/3, l
};

// Where an order meets a natural frequency: the speed band over which the
// natural frequency (which changes along the travel with the mesh stiffness)
// equals the order's frequency.
struct Resonance {
  std::string order;
  int mode = 0;             // 0 = lowest natural frequency
  double speed_at_mean = 0; // with the mean stiffness's natural frequency [m/s]
  double speed_low = 0, speed_high = 0;  // band over the travel [m/s]
};

struct StabilityPoint {
  double speed = 0;
  double spectral_radius = 0;  // < 1 stable
};

struct DriveDynamics {
  DriveTrain train;
  MeshForceLaw law;
  double static_force = 0;          // F_s = load.force [N]
  double mean_stiffness = 0;        // the law's mean full stiffness [N/m]
  double damping_ratio = 0;
  double operating_speed = 0;       // [m/s] (0: none given)
  std::vector<double> speeds;       // the speed range swept [m/s]
  // Natural frequencies at the mean stiffness, lowest first [Hz].
  std::vector<double> natural_frequencies_hz;
  // Along the travel (the law's samples): per mode, the natural frequency [Hz].
  std::vector<double> travel;
  std::vector<std::vector<double>> natural_frequency_along_travel;  // [mode][sample]
  std::vector<ExcitationOrder> orders;
  std::vector<Resonance> resonances;  // every order x mode crossing, by speed_at_mean
  // Relative distance of the operating speed from the nearest main resonance
  // (mesh order and span order against the lowest mode, at the mean
  // stiffness): min |v - v_res| / v_res. Infinity when none.
  double resonance_margin = 0;
  std::optional<SteadyResponse> at_speed;
  std::vector<SweepPoint> sweep;
  double kv_max = 0;                 // max K_V over the sweep (both branches); at_speed's without a sweep
  double speed_at_kv_max = 0;
  std::vector<StabilityPoint> stability;
  double stability_margin = 0;       // 1 - max spectral radius over the range (> 0 stable)
  std::vector<std::string> warnings;
};

// The speeds of drive.dynamics.speed_range, or the default range around the
// operating speed (docs/yaml.md, dynamics): 40 speeds from v/20 to 1.25 v.
// Throws InputError (key dynamics.speed_range) when neither is given.
std::vector<double> dynamics_speeds(const Drive& drive, double operating_speed);

// Throws InputError for missing dynamics inputs (dynamics.moving_mass; a
// speed to run at), DesignError when the design cannot run (the static
// model's codes).
DriveDynamics analyse_drive_dynamics(const Drive& drive, const MeshStiffnessModel& model,
                                     const DynamicsRequest& request);

}  // namespace rackopt
