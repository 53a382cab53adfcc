#include "rackopt/dynamics/drive_train_builder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt {

namespace {

// The dynamics keys are the problem's: an error names the key as the file
// spells it (docs/yaml.md, dynamics), with the problem file as its source.
[[noreturn]] void refuse(const Drive& drive, const std::string& key, const std::string& message) {
  throw InputError(SourceMark{drive.source_file, 0, 0}, key, message);
}

void check_non_negative(const Drive& drive, const std::string& key, double value) {
  if (!std::isfinite(value) || value < 0) {
    refuse(drive, key, "must be a finite value >= 0, got " + std::to_string(value));
  }
}

}  // namespace

double pinion_inertia(const PinionSpec& pinion, const PinionGeometry& geometry) {
  const double r = geometry.pitch_radius;
  const double ri = std::min(pinion.bore_radius, r);
  const double r2 = r * r, ri2 = ri * ri;
  return pinion.material.density * std::numbers::pi * pinion.face_width * (r2 * r2 - ri2 * ri2) / 2.0;
}

DriveTrain drive_train(const Drive& drive, const MeshGeometry& geometry) {
  const DynamicsSpec& d = drive.dynamics;
  if (!std::isfinite(d.moving_mass) || d.moving_mass <= 0) {
    refuse(drive, "dynamics.moving_mass",
           "the dynamic model needs the mass this pinion drives along the rack (kg, > 0); not given");
  }
  check_non_negative(drive, "dynamics.drive_inertia", d.drive_inertia);
  check_non_negative(drive, "dynamics.drive_stiffness", d.drive_stiffness);
  DriveTrain t;
  t.moving_mass = d.moving_mass;
  t.drive_inertia = d.drive_inertia;
  t.drive_stiffness = d.drive_stiffness;
  t.pinion_inertia = pinion_inertia(drive.pinion, geometry.pinion);
  t.base_radius = geometry.pinion.base_radius;
  t.pressure_angle = geometry.pressure_angle;
  return t;
}

}  // namespace rackopt
