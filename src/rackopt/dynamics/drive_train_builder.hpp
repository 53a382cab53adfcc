// The drive train of the dynamic model (drive_train.hpp) from a drive's
// `dynamics:` section and its mesh geometry (docs/models/dynamics.md,
// "Drive train inputs").
//
// Example:
//   MeshGeometry g = build_mesh_geometry(drive);
//   DriveTrain train = drive_train(drive, g);
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/dynamics/drive_train.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {

// moving_mass, drive_inertia and drive_stiffness from drive.dynamics; the
// pinion's inertia as a solid disc of the pinion material between the bore
// and the pitch radius over the face width (pinion_inertia below); base radius
// and pressure angle from `geometry` (build_mesh_geometry(drive)).
// Throws InputError with key `dynamics.moving_mass` when no moving mass is
// given, and with the key of any other dynamics value that is negative or not
// finite.
DriveTrain drive_train(const Drive& drive, const MeshGeometry& geometry);

// J_p = rho pi b (r^4 - r_i^4) / 2 [kg m^2]: a solid disc from the bore r_i to
// the pitch radius r. The teeth fill about half of the annulus between the
// root and the tip circle; the disc to the pitch radius counts the annulus
// between root and pitch circle full instead, nearly the same mass at nearly
// the same radius (a disc to the root circle would leave the teeth out).
double pinion_inertia(const PinionSpec& pinion, const PinionGeometry& geometry);

}  // namespace rackopt
