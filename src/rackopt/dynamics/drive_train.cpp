// Reduction of the drive train to its vibration coordinates (docs/models/dynamics.md).
#include "rackopt/dynamics/drive_train.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

namespace rackopt {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("drive train: " + what);
}

}  // namespace

ReducedSystem reduce(const DriveTrain& t) {
  require(std::isfinite(t.drive_inertia) && t.drive_inertia >= 0, "drive_inertia must be finite and >= 0");
  require(std::isfinite(t.pinion_inertia) && t.pinion_inertia >= 0, "pinion_inertia must be finite and >= 0");
  require(std::isfinite(t.drive_stiffness), "drive_stiffness must be finite");
  require(std::isfinite(t.moving_mass) && t.moving_mass > 0, "moving_mass must be finite and > 0");
  require(std::isfinite(t.base_radius) && t.base_radius > 0, "base_radius must be finite and > 0");
  require(std::isfinite(t.pressure_angle) && std::cos(t.pressure_angle) > 0 && t.pressure_angle >= 0,
          "pressure_angle must be in [0, pi/2)");
  const double c = std::cos(t.pressure_angle), rb = t.base_radius, M = t.moving_mass;
  ReducedSystem r;
  // The inverse of the generalized mass restricted to the vibration
  // coordinates: with the coordinate map A (delta, phi, x) = A (theta_m,
  // theta_p, x), M_g^-1 = A diag(J_m, J_p, M)^-1 A^T. The cyclic coordinate x
  // receives no generalized force (the mesh, the motor torque and the
  // resistance cancel on it), so y'' = [M_g^-1]_yy Q_y and M_r = [M_g^-1]_yy^-1
  // exactly: the rigid-body motion is eliminated, not neglected.
  if (t.rigid()) {
    const double J = t.drive_inertia + t.pinion_inertia;
    require(J > 0, "drive_inertia + pinion_inertia must be > 0");
    const double g00 = rb * rb / J + c * c / M;
    r.mass = Eigen::MatrixXd::Constant(1, 1, 1.0 / g00);
    r.drive_stiffness = Eigen::MatrixXd::Zero(1, 1);
    r.mesh_mass = 1.0 / g00;
    return r;
  }
  require(t.drive_inertia > 0, "drive_inertia must be > 0 with a drive spring (drive_stiffness > 0)");
  require(t.pinion_inertia > 0, "pinion_inertia must be > 0 with a drive spring (drive_stiffness > 0)");
  Eigen::Matrix2d g;
  g(0, 0) = rb * rb / t.pinion_inertia + c * c / M;
  g(0, 1) = g(1, 0) = -rb / t.pinion_inertia;
  g(1, 1) = 1.0 / t.drive_inertia + 1.0 / t.pinion_inertia;
  r.mass = g.inverse();
  r.drive_stiffness = Eigen::MatrixXd::Zero(2, 2);
  r.drive_stiffness(1, 1) = t.drive_stiffness;
  r.mesh_mass = 1.0 / g(0, 0);
  return r;
}

std::vector<double> natural_frequencies_hz(const DriveTrain& train, double mesh_stiffness) {
  if (!(std::isfinite(mesh_stiffness) && mesh_stiffness >= 0))
    throw std::invalid_argument("natural_frequencies_hz: mesh_stiffness must be finite and >= 0");
  const ReducedSystem r = reduce(train);
  Eigen::MatrixXd K = r.drive_stiffness;
  K(0, 0) += mesh_stiffness;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, r.mass, Eigen::EigenvaluesOnly);
  std::vector<double> f;
  for (int i = 0; i < es.eigenvalues().size(); ++i)
    f.push_back(std::sqrt(std::max(0.0, es.eigenvalues()[i])) / (2 * M_PI));
  return f;  // ascending: Eigen sorts the eigenvalues
}

}  // namespace rackopt
