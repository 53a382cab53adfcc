// The drive train of the dynamic model from a shipped problem: the pinion's
// inertia against a hand computation, the values passed through, and the
// refusal of a drive without a moving mass (docs/models/dynamics.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rackopt/core/error.hpp"
#include "rackopt/dynamics/drive_train_builder.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt {
namespace {

TEST(DriveTrainBuilder, PinionInertiaIsTheDiscToThePitchCircle) {
  // Gantry axis: z = 20, m = 4 mm: r = 40 mm; face 40 mm; the loader's bore is
  // half the root radius, r_f = 40 - 1.25 x 4 = 35 mm: r_i = 17.5 mm;
  // rho = 7850 kg/m^3. J = rho pi b (r^4 - r_i^4) / 2
  //   = 7850 pi 0.04 (2.56e-6 - 9.37890625e-8) / 2 = 1.216409e-3 kg m^2.
  Drive d = test_support::load_shipped_problem("gantry_axis.yaml");
  d.dynamics.moving_mass = 1500;
  const MeshGeometry g = build_mesh_geometry(d);
  ASSERT_DOUBLE_EQ(d.pinion.bore_radius, 0.0175);
  const double hand = 7850 * std::numbers::pi * 0.04 * (2.56e-6 - 9.37890625e-8) / 2;
  EXPECT_NEAR(hand, 1.216409e-3, 1e-9);
  const DriveTrain t = drive_train(d, g);
  EXPECT_NEAR(t.pinion_inertia, hand, 1e-12 * hand);
  // Without a bore: the full disc, rho pi b r^4 / 2 = 1.2629e-3 kg m^2.
  d.pinion.bore_radius = 0;
  EXPECT_NEAR(pinion_inertia(d.pinion, g.pinion), 7850 * std::numbers::pi * 0.04 * 2.56e-6 / 2, 1e-15);
}

TEST(DriveTrainBuilder, PassesTheDynamicsSectionAndTheGeometryThrough) {
  Drive d = test_support::load_shipped_problem("gantry_axis.yaml");
  d.dynamics.moving_mass = 1500;
  d.dynamics.drive_inertia = 2e-3;
  d.dynamics.drive_stiffness = 4e4;
  const MeshGeometry g = build_mesh_geometry(d);
  const DriveTrain t = drive_train(d, g);
  EXPECT_EQ(t.moving_mass, 1500);
  EXPECT_EQ(t.drive_inertia, 2e-3);
  EXPECT_EQ(t.drive_stiffness, 4e4);
  EXPECT_FALSE(t.rigid());
  EXPECT_NEAR(t.base_radius, 0.04 * std::cos(20 * std::numbers::pi / 180), 1e-15);
  EXPECT_NEAR(t.pressure_angle, 20 * std::numbers::pi / 180, 1e-15);
}

TEST(DriveTrainBuilder, RefusesADriveWithoutMovingMass) {
  Drive d = test_support::load_shipped_problem("gantry_axis.yaml");
  d.dynamics.moving_mass = 0;  // the shipped problem gives one
  const MeshGeometry g = build_mesh_geometry(d);
  try {
    (void)drive_train(d, g);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "dynamics.moving_mass");
    EXPECT_NE(std::string(e.what()).find("dynamics.moving_mass"), std::string::npos) << e.what();
  }
  d.dynamics.moving_mass = 1500;
  d.dynamics.drive_inertia = -1;
  try {
    (void)drive_train(d, g);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "dynamics.drive_inertia");
  }
}

}  // namespace
}  // namespace rackopt
