// Time integration of the rack drive from a given state (docs/models/dynamics.md):
// the stepper behind steady_response, exposed for transients (run-up from
// rest, free vibration) and for the tests' energy and growth checks.
#pragma once

#include <vector>

#include "rackopt/dynamics/drive_response.hpp"

namespace rackopt {

// The vibration state: approach delta [m], drive twist phi [rad] (0 with a
// rigid drive train) and their rates.
struct DriveState {
  double delta = 0, twist = 0, delta_rate = 0, twist_rate = 0;
};

struct TransientResult {
  ResponseStatus status = ResponseStatus::kConverged;  // kUnbounded when the approach ran away
  std::vector<DriveState> period_end;  // state at the end of each excitation period integrated
  int steps_per_period = 0;            // time steps of one excitation period (events excluded)
};

// Integrates `periods` excitation periods at speed v from `start` at travel 0
// (options as in steady_response; their periodic fields are not used).
// Throws std::invalid_argument for bad arguments.
TransientResult drive_transient(const DriveTrain& train, const MeshForceLaw& law, double speed,
                                double static_force, const DynamicsOptions& options, const DriveState& start,
                                int periods);

}  // namespace rackopt
