// The file set of a dynamic analysis (`rackopt dynamics`, docs/output.md):
//   dynamics.json           every figure of DriveDynamics (the --json object's `dynamics` part)
//   dynamics_sweep.csv      K_V, DTE and contact loss over speed, up and down
//   dynamics_response.csv   mesh force and DTE over one span at the operating speed
//   dynamics_spectrum.csv   their amplitude spectra
//   dynamics_campbell.csv   natural frequencies along the travel
//   dynamics.gp / .png      K_V over speed, force and DTE over the travel, the
//                           force spectrum, the Campbell diagram (and the
//                           Floquet spectral radius when computed)
#pragma once

#include <string>

#include "rackopt/dynamics/drive_dynamics.hpp"
#include "rackopt/output/plot.hpp"
#include "rackopt/output/written_files.hpp"

namespace rackopt {

// The JSON object of a dynamic analysis (docs/output.md, "rackopt dynamics").
std::string dynamics_json(const DriveDynamics& d);

// The text `rackopt dynamics` prints.
std::string dynamics_summary(const DriveDynamics& d);

// Writes the files above into `out_dir` (it must exist), each atomically; a
// plot gnuplot cannot draw is a warning in the result.
WrittenFiles write_dynamics_files(const DriveDynamics& d, const std::string& out_dir, const std::string& title,
                                  PlotImages plots = PlotImages::kPng);

}  // namespace rackopt
