// ISO 6336-1 single stiffness beside the model: the standard's formula by
// hand, and the model's single pair near it on the shipped drives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/iso_single_stiffness.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt {
namespace {

Drive iso_drive(int z, double x, double force) {
  Drive d;
  d.pinion.teeth = z;
  d.pinion.module = 0.01;
  d.pinion.pressure_angle = 20.0 * std::numbers::pi / 180.0;
  d.pinion.face_width = 0.05;
  d.pinion.profile_shift = x;
  d.pinion.dedendum_coef = 1.25;
  d.pinion.material.youngs_modulus = 206e9;
  d.rack.material.youngs_modulus = 206e9;
  d.load.force = force;
  return d;
}

TEST(IsoSingleStiffness, StandardFormulaByHand) {
  // z1 = 20, x1 = 0, 20 deg, h_fP = 1.25 m, steel at E_st: q' = 0.04723 + 0.15551/20,
  // C_B = 1 + 0.5 (1.2 - 1.25) = 0.975, c' = 0.8 C_B / q'. F_t/b = 200 N/mm: no load factor.
  const double ft = 200.0 * 50.0;  // N on 50 mm
  const IsoSingleStiffness iso = iso_single_stiffness(iso_drive(20, 0.0, ft / std::cos(20.0 * std::numbers::pi / 180)));
  const double q = 0.04723 + 0.15551 / 20;
  EXPECT_NEAR(iso.q_prime, q, 1e-12);
  EXPECT_NEAR(iso.basic_rack_factor, 0.975, 1e-12);
  EXPECT_DOUBLE_EQ(iso.load_factor, 1.0);
  EXPECT_NEAR(iso.c_prime, 0.8 * 0.975 / q, 1e-9);
  EXPECT_NEAR(iso.stiffness, iso.c_prime * 50.0 * 1e6, 1e-3);  // N/(mm um) x 50 mm -> N/m
  // Light load: 50 N/mm gives (50/100)^(1/4).
  const IsoSingleStiffness light =
      iso_single_stiffness(iso_drive(20, 0.0, 50.0 * 50.0 / std::cos(20.0 * std::numbers::pi / 180)));
  EXPECT_NEAR(light.load_factor, std::pow(0.5, 0.25), 1e-12);
  // A positive shift thickens the root: a stiffer pair (smaller q').
  EXPECT_LT(iso_single_stiffness(iso_drive(20, 0.5, ft)).q_prime, iso.q_prime);
  // More teeth: stiffer.
  EXPECT_LT(iso_single_stiffness(iso_drive(40, 0.0, ft)).q_prime, iso.q_prime);
}

TEST(IsoSingleStiffness, ShippedDrivesSitNearTheStandard) {
  // ISO's c' is an empirical value for solid gear pairs, independent of this
  // model: the FE-grade single pair lands within 1.5 % of it on the shipped
  // drives (the papers' tooth model: 42-46 % above); the band is 10 %.
  for (const char* name : {"gantry_axis", "large_module", "rack_railway", "ship_lift"}) {
    const Drive d = test_support::load_shipped_problem(std::string(name) + ".yaml");
    const MeshGeometry g = build_mesh_geometry(d);
    const double ratio = single_pair_stiffness_at_pitch_point(d, g) / iso_single_stiffness(d).stiffness;
    std::printf("[ info ] %s: model single pair at the pitch point / ISO c' b = %.3f\n", name, ratio);
    EXPECT_NEAR(ratio, 1.0, 0.1) << name;
  }
}

}  // namespace
}  // namespace rackopt
