// Parametric stability (Meissner's equation) against the exact one-period
// transfer matrix of a square-wave stiffness (docs/models/dynamics.md).
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/dynamics_test_support.hpp"
#include "rackopt/dynamics/drive_transient.hpp"

namespace rackopt {
namespace {

// Spectral radius of the exact transfer matrix over one period T of
// m d'' + k0 (1 +/- eps) d = 0 (halves of T): product of the harmonic
// oscillator's transfer matrices [[cos, sin/w], [-w sin, cos]].
double exact_spectral_radius(double m, double k0, double eps, double T) {
  auto tm = [&](double k) {
    const double w = std::sqrt(k / m), p = w * T / 2;
    Eigen::Matrix2d M;
    M << std::cos(p), std::sin(p) / w, -w * std::sin(p), std::cos(p);
    return M;
  };
  const Eigen::Matrix2d phi = tm(k0 * (1 - eps)) * tm(k0 * (1 + eps));
  const double half = phi.trace() / 2;  // det = 1
  return std::abs(half) <= 1 ? 1.0 : std::abs(half) + std::sqrt(half * half - 1);
}

struct Meissner {
  DriveTrain t = dyntest::rigid_train();
  double k0 = 8e8, eps = 0.3, period = 0.02, fs = 16e3;
  MeshForceLaw law = dyntest::square_wave_law(k0, eps, period);
  double m = dyntest::mesh_mass(t);
  double w0 = std::sqrt(k0 / m);
  double speed(double T) const { return period / T; }
};

TEST(Floquet, SquareWaveSpectralRadiusMatchesExactTransferMatrix) {
  Meissner s;
  DynamicsOptions o;
  o.damping_ratio = 0;
  o.steps_per_mesh_period = 4000;
  int inside = 0, outside = 0;
  // Excitation periods across the principal tongue (T near pi / w0) and the next.
  for (double f : {0.6, 0.9, 0.97, 1.0, 1.05, 1.2, 1.6, 1.9, 2.0, 2.1}) {
    const double T = f * M_PI / s.w0;
    const double exact = exact_spectral_radius(s.m, s.k0, s.eps, T);
    const FloquetResult fl = floquet(s.t, s.law, s.speed(T), s.fs, o);
    EXPECT_NEAR(fl.spectral_radius, exact, 1e-6) << "T = " << f << " pi / w0";
    ASSERT_EQ(fl.multiplier_magnitudes.size(), 2u);
    (exact > 1 + 1e-3 ? inside : outside) += 1;
    if (exact > 1 + 1e-3) {
      EXPECT_FALSE(fl.stable);
    }
  }
  EXPECT_GE(inside, 3);  // the sweep crosses tongues and the stable bands between
  EXPECT_GE(outside, 3);
}

// Two transients differing by a tiny perturbation differ by a solution of the
// homogeneous linear system: it grows by the spectral radius per period
// inside a tongue, and decays with damping outside.
TEST(Floquet, TimeIntegrationGrowsInsideTongueDecaysOutside) {
  Meissner s;
  DynamicsOptions o;
  o.damping_ratio = 0;
  o.steps_per_mesh_period = 2000;
  const double T_in = M_PI / s.w0;
  const double rho = exact_spectral_radius(s.m, s.k0, s.eps, T_in);
  ASSERT_GT(rho, 1.1);
  // Start on the exact periodic solution: each half is the affine map
  // z -> H (z - s) + s about its static approach s = F_s / k.
  auto half = [&](double k) {
    const double w = std::sqrt(k / s.m), p = w * T_in / 2;
    Eigen::Matrix2d H;
    H << std::cos(p), std::sin(p) / w, -w * std::sin(p), std::cos(p);
    return H;
  };
  const Eigen::Matrix2d H1 = half(s.k0 * (1 + s.eps)), H2 = half(s.k0 * (1 - s.eps));
  const Eigen::Vector2d s1(s.fs / (s.k0 * (1 + s.eps)), 0), s2(s.fs / (s.k0 * (1 - s.eps)), 0);
  // z_T = H2 (H1 (z - s1) + s1 - s2) + s2 = Phi z + p.
  const Eigen::Matrix2d Phi = H2 * H1;
  const Eigen::Vector2d zp = H2 * (s1 - H1 * s1 - s2) + s2;
  const Eigen::Vector2d z0 = (Eigen::Matrix2d::Identity() - Phi).inverse() * zp;
  DriveState a;
  a.delta = z0(0);
  a.delta_rate = z0(1);
  DriveState b = a;
  b.delta *= 1 + 1e-7;
  const int n = 30;  // the other multiplier, 1 / rho, has died out by then
  const auto ra = drive_transient(s.t, s.law, s.speed(T_in), s.fs, o, a, n);
  const auto rb = drive_transient(s.t, s.law, s.speed(T_in), s.fs, o, b, n);
  auto diff = [&](int p) {
    const double dd = ra.period_end[p].delta - rb.period_end[p].delta;
    const double dr = (ra.period_end[p].delta_rate - rb.period_end[p].delta_rate) / s.w0;
    return std::hypot(dd, dr);
  };
  EXPECT_NEAR(diff(n - 1) / diff(n - 2), rho, 1e-3 * rho);
  EXPECT_GT(diff(n - 1), 100 * 1e-7 * a.delta);
  // The steady response does not settle there without damping.
  o.max_periods = 60;
  const SteadyResponse r = steady_response(s.t, s.law, s.speed(T_in), s.fs, o);
  EXPECT_NE(r.status, ResponseStatus::kConverged);
  EXPECT_FALSE(std::isnan(r.dynamic_factor));

  // Outside the tongues with damping: the difference decays, the response converges.
  o.damping_ratio = 0.05;
  const double T_out = 0.6 * M_PI / s.w0;
  ASSERT_EQ(exact_spectral_radius(s.m, s.k0, s.eps, T_out), 1.0);
  const auto oa = drive_transient(s.t, s.law, s.speed(T_out), s.fs, o, a, 100);
  const auto ob = drive_transient(s.t, s.law, s.speed(T_out), s.fs, o, b, 100);
  const double d0 = 1e-7 * a.delta;
  EXPECT_LT(std::abs(oa.period_end.back().delta - ob.period_end.back().delta), 1e-2 * d0);
  const SteadyResponse ro = steady_response(s.t, s.law, s.speed(T_out), s.fs, o);
  EXPECT_EQ(ro.status, ResponseStatus::kConverged) << ro.message;
  EXPECT_TRUE(floquet(s.t, s.law, s.speed(T_out), s.fs, o).stable);
}

}  // namespace
}  // namespace rackopt
