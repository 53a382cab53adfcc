// The steady response of linear drives against closed forms: harmonic
// forcing through a kinematic error, energy conservation, the quasi-static
// limit (docs/models/dynamics.md).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "dynamics/dynamics_test_support.hpp"
#include "rackopt/dynamics/drive_transient.hpp"

namespace rackopt {
namespace {

// First Fourier coefficients (cos, sin) of samples over one period.
void first_harmonic(const std::vector<double>& y, double& a1, double& b1) {
  a1 = b1 = 0;
  const size_t n = y.size();
  for (size_t i = 0; i < n; ++i) {
    a1 += 2.0 / n * y[i] * std::cos(2 * M_PI * i / n);
    b1 += 2.0 / n * y[i] * std::sin(2 * M_PI * i / n);
  }
}

// m d'' + c d' + k (d - a (1 + sin W t)) = F_s: the particular solution's
// harmonic is A sin(W t - psi) with A = k a / |k - m W^2 + i c W|.
TEST(LinearResponse, HarmonicKinematicErrorAmplitudeAndPhase) {
  const DriveTrain t = dyntest::rigid_train();
  const double k = 8e8, a = 1e-6, period = 0.02, fs = 16e3;
  const MeshForceLaw law = dyntest::harmonic_gap_law(k, a, period, 2000);
  const double m = dyntest::mesh_mass(t), wn = std::sqrt(k / m);
  DynamicsOptions o;
  o.damping_ratio = 0.05;
  o.steps_per_mesh_period = 512;
  o.history_points = 4000;
  for (double ratio : {0.5, 0.9, 1.0, 1.6}) {
    const double W = ratio * wn, v = W * period / (2 * M_PI);
    const double c = 2 * o.damping_ratio * std::sqrt(k * m);
    const double re = k - m * W * W, im = c * W;
    const double A = k * a / std::hypot(re, im), psi = std::atan2(im, re);
    const SteadyResponse r = steady_response(t, law, v, fs, o);
    ASSERT_EQ(r.status, ResponseStatus::kConverged) << r.message;
    double a1, b1;
    first_harmonic(r.dte, a1, b1);
    // A sin(W t - psi) = A cos(psi) sin - A sin(psi) cos.
    EXPECT_NEAR(b1 / A, std::cos(psi), 1e-4) << "ratio " << ratio;
    EXPECT_NEAR(-a1 / A, std::sin(psi), 1e-4) << "ratio " << ratio;
    double mean = 0;
    for (double d : r.dte) mean += d / r.dte.size();
    EXPECT_NEAR(mean, fs / k + a, 1e-4 * A);
    EXPECT_NEAR(r.dte_peak_to_peak / (2 * A), 1.0, 1e-3);
    EXPECT_EQ(r.contact_loss_fraction, 0.0);
  }
}

// With a drive spring: M_r y'' + C y' + K y = f + e0 k g(t), C = diag(c_mesh,
// c_drive) with c_drive = 2 zeta sqrt(k_d J_m J_p / (J_m + J_p)) (the twist's
// own critical damping, the mesh free). The delta harmonic is the first
// component of (K - W^2 M_r + i W C)^-1 e0 k a, from the 3-DOF masses.
TEST(LinearResponse, DriveSpringHarmonicResponse) {
  DriveTrain t = dyntest::rigid_train();
  t.drive_stiffness = 2e5;
  const double k = 8e8, a = 1e-6, period = 0.02, fs = 16e3, zeta = 0.05;
  const double Jm = t.drive_inertia, Jp = t.pinion_inertia, rb = t.base_radius, c = std::cos(t.pressure_angle);
  // [M_g^-1]_yy from the coordinate map (delta, phi) = (r_b th_p - c x, th_m - th_p).
  Eigen::Matrix2d Ginv;
  Ginv << rb * rb / Jp + c * c / t.moving_mass, -rb / Jp, -rb / Jp, 1 / Jm + 1 / Jp;
  const Eigen::Matrix2d Mr = Ginv.inverse();
  const double m_mesh = 1 / Ginv(0, 0);
  const double cm = 2 * zeta * std::sqrt(k * m_mesh), cd = 2 * zeta * std::sqrt(t.drive_stiffness * Jm * Jp / (Jm + Jp));
  const MeshForceLaw law = dyntest::harmonic_gap_law(k, a, period, 2000);
  DynamicsOptions o;
  o.damping_ratio = zeta;
  o.steps_per_mesh_period = 512;
  o.steps_per_natural_period = 256;
  o.history_points = 4000;
  const auto f = natural_frequencies_hz(t, k);
  for (double W : {0.8 * 2 * M_PI * f[1], 1.1 * 2 * M_PI * f[1], 3 * 2 * M_PI * f[0]}) {
    const double v = W * period / (2 * M_PI);
    Eigen::Matrix2cd D;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) D(i, j) = std::complex<double>(-W * W * Mr(i, j), 0);
    D(0, 0) += std::complex<double>(k, W * cm);
    D(1, 1) += std::complex<double>(t.drive_stiffness, W * cd);
    // Forcing k a sin(W t) = Im(k a e^{iWt}): delta's harmonic Im(Y0 e^{iWt}).
    const Eigen::Vector2cd Y = D.fullPivLu().solve(Eigen::Vector2cd(k * a, 0));
    const SteadyResponse r = steady_response(t, law, v, fs, o);
    ASSERT_EQ(r.status, ResponseStatus::kConverged) << r.message;
    double a1, b1;
    first_harmonic(r.dte, a1, b1);
    // Im(Y e^{i th}) = Im(Y) cos th + Re(Y) sin th.
    const double A = std::abs(Y(0));
    EXPECT_NEAR(b1 / A, Y(0).real() / A, 1e-4) << "W " << W;
    EXPECT_NEAR(a1 / A, Y(0).imag() / A, 1e-4) << "W " << W;
  }
}

// Total energy of the undamped drive (kinetic in the reduced mass, the
// mesh and drive springs, minus the constant forcing's work) is conserved.
double energy(const DriveTrain& t, double k, double fs, const DriveState& s) {
  const ReducedSystem r = reduce(t);
  Eigen::VectorXd v(r.mass.rows());
  v(0) = s.delta_rate;
  if (v.size() == 2) v(1) = s.twist_rate;
  double e = 0.5 * v.dot(r.mass * v) + 0.5 * k * s.delta * s.delta - fs * s.delta;
  if (!t.rigid()) e += 0.5 * t.drive_stiffness * s.twist * s.twist - t.base_radius * fs * s.twist;
  return e;
}

TEST(LinearResponse, EnergyConservedWithoutDampingOver1000Periods) {
  for (bool spring : {false, true}) {
    DriveTrain t = dyntest::rigid_train();
    if (spring) t.drive_stiffness = 3e5;
    const double k = 8e8, fs = 16e3, period = 0.02;
    const MeshForceLaw law = dyntest::constant_law(k, period, period);
    DynamicsOptions o;
    o.damping_ratio = 0;
    o.steps_per_natural_period = 128;
    // One excitation period = one period of the lowest mode: 1000 of them.
    const double f0 = natural_frequencies_hz(t, k).front();
    const double v = period * f0;
    DriveState s;
    s.delta = 1.5 * fs / k;  // never leaves contact: delta stays in (0.5, 1.5) static approaches
    s.twist = spring ? 1.2 * t.base_radius * fs / t.drive_stiffness : 0;
    const double e0 = energy(t, k, fs, s);
    const double e_ref = 0.5 * k * (0.5 * fs / k) * (0.5 * fs / k);  // vibration energy scale
    const TransientResult r = drive_transient(t, law, v, fs, o, s, 1000);
    ASSERT_EQ(r.status, ResponseStatus::kConverged);
    ASSERT_EQ(r.period_end.size(), 1000u);
    EXPECT_NEAR((energy(t, k, fs, r.period_end.back()) - e0) / e_ref, 0.0, 1e-4) << "drive spring " << spring;
  }
}

// Speed -> 0 over a smoothly varying stiffness: the response is the static one.
TEST(LinearResponse, StaticLimitOfSmoothLaw) {
  const DriveTrain t = dyntest::rigid_train();
  const double k0 = 8e8, pitch = 0.02, period = 4 * pitch, fs = 16e3;
  const MeshForceLaw law = dyntest::one_slot_law(
      period, pitch, 1600, [&](double X) { return k0 * (1 + 0.3 * std::sin(2 * M_PI * X / pitch)); },
      [](double) { return 0.0; });
  const double fn = natural_frequencies_hz(t, k0).front();
  DynamicsOptions o;
  const double v = pitch * fn / 300;  // mesh frequency 1/300 of the natural frequency
  const SteadyResponse r = steady_response(t, law, v, fs, o);
  ASSERT_EQ(r.status, ResponseStatus::kConverged) << r.message;
  EXPECT_NEAR(r.dynamic_factor, 1.0, 1e-3);
  double worst = 0;
  for (size_t i = 0; i < r.travel.size(); ++i) {
    const double qs = law.approach_at(r.travel[i], fs);
    worst = std::max(worst, std::abs(r.dte[i] - qs) / qs);
  }
  EXPECT_LT(worst, 1e-3);
  // And it is dynamic at speed: the same law near resonance is not static.
  const SteadyResponse fast = steady_response(t, law, pitch * fn, fs, o);
  EXPECT_GT(fast.dynamic_factor, 1.05);
}

}  // namespace
}  // namespace rackopt
