// The drive train's reduction and natural frequencies against closed forms
// derived from the full 3-degree-of-freedom system (docs/models/dynamics.md).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dynamics/dynamics_test_support.hpp"

namespace rackopt {
namespace {

TEST(DriveTrain, RigidNaturalFrequencyClosedForm) {
  const DriveTrain t = dyntest::rigid_train();
  const double k = 8e8, c = std::cos(t.pressure_angle), J = 2.0;
  const double w2 = k * (t.base_radius * t.base_radius / J + c * c / t.moving_mass);
  const auto f = natural_frequencies_hz(t, k);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(std::pow(2 * M_PI * f[0], 2) / w2, 1.0, 1e-6);
  EXPECT_NEAR(reduce(t).mesh_mass, 1 / (t.base_radius * t.base_radius / J + c * c / t.moving_mass), 1e-9);
}

// det(K - lambda M) of the full system (theta_m, theta_p, x) with
// V = k_d (theta_m - theta_p)^2 / 2 + k (r_b theta_p - cos(alpha) x)^2 / 2,
// M = diag(J_m, J_p, M), expanded by hand: -lambda (A lambda^2 - B lambda + C) with
//   A = J_m J_p M
//   B = k_d M (J_m + J_p) + k J_m (r_b^2 M + c^2 J_p)
//   C = k k_d (r_b^2 M + c^2 (J_m + J_p))
// (the zero root is the rigid-body motion). The test checks the expansion
// against the determinant itself before using its roots.
TEST(DriveTrain, DriveSpringNaturalFrequenciesFromCharacteristicPolynomial) {
  DriveTrain t = dyntest::rigid_train();
  t.drive_stiffness = 3e5;
  const double k = 8e8, kd = t.drive_stiffness, Jm = t.drive_inertia, Jp = t.pinion_inertia, M = t.moving_mass;
  const double rb = t.base_radius, c = std::cos(t.pressure_angle);
  const double A = Jm * Jp * M;
  const double B = kd * M * (Jm + Jp) + k * Jm * (rb * rb * M + c * c * Jp);
  const double C = k * kd * (rb * rb * M + c * c * (Jm + Jp));
  // The expansion against a direct 3x3 determinant at two lambdas.
  for (double lam : {1e4, 7e5}) {
    Eigen::Matrix3d Kf, Mf;
    Kf << kd, -kd, 0, -kd, kd + k * rb * rb, -k * rb * c, 0, -k * rb * c, k * c * c;
    Mf = Eigen::Vector3d(Jm, Jp, M).asDiagonal();
    const double det = (Kf - lam * Mf).determinant();
    const double poly = -lam * (A * lam * lam - B * lam + C);
    EXPECT_NEAR(det / poly, 1.0, 1e-9);
  }
  const double disc = std::sqrt(B * B - 4 * A * C);
  const double l1 = (B - disc) / (2 * A), l2 = (B + disc) / (2 * A);
  const auto f = natural_frequencies_hz(t, k);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_NEAR(std::pow(2 * M_PI * f[0], 2) / l1, 1.0, 1e-6);
  EXPECT_NEAR(std::pow(2 * M_PI * f[1], 2) / l2, 1.0, 1e-6);
  EXPECT_NEAR(reduce(t).mesh_mass, 1 / (rb * rb / Jp + c * c / M), 1e-9);
}

TEST(DriveTrain, BadArgumentsNameTheQuantity) {
  DriveTrain t = dyntest::rigid_train();
  t.moving_mass = 0;
  try {
    reduce(t);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("moving_mass"), std::string::npos);
  }
  t = dyntest::rigid_train();
  t.drive_inertia = t.pinion_inertia = 0;
  EXPECT_THROW(reduce(t), std::invalid_argument);
  t = dyntest::rigid_train();
  t.drive_stiffness = 1e5;
  t.drive_inertia = 0;
  try {
    reduce(t);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("drive_inertia"), std::string::npos);
  }
  t = dyntest::rigid_train();
  t.base_radius = std::nan("");
  EXPECT_THROW(reduce(t), std::invalid_argument);
  EXPECT_THROW(natural_frequencies_hz(dyntest::rigid_train(), -1), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt
