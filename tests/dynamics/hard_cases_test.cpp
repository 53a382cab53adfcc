// Edge cases of the drive dynamics: undamped resonance, extreme mass ratio,
// very slow mesh, one-speed sweep, and bad arguments (docs/models/dynamics.md).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "dynamics/dynamics_test_support.hpp"
#include "rackopt/dynamics/drive_transient.hpp"

namespace rackopt {
namespace {

void expect_finite(const SteadyResponse& r) {
  for (double v : {r.mesh_force_max, r.mesh_force_min, r.dte_max, r.dte_min, r.dte_peak_to_peak,
                   r.contact_loss_fraction})
    EXPECT_TRUE(std::isfinite(v));
  EXPECT_FALSE(std::isnan(r.dynamic_factor));
}

TEST(DynamicsHardCases, UndampedResonanceIsFiniteWithStatus) {
  const DriveTrain t = dyntest::rigid_train();
  const double k = 8e8, period = 0.02;
  const MeshForceLaw law = dyntest::harmonic_gap_law(k, 1e-6, period, 400);
  const double v = natural_frequencies_hz(t, k).front() * period;  // excitation at the natural frequency
  DynamicsOptions o;
  o.damping_ratio = 0;
  o.max_periods = 50;
  const SteadyResponse r = steady_response(t, law, v, 16e3, o);
  EXPECT_FALSE(std::isnan(r.dynamic_factor));
  if (r.status != ResponseStatus::kUnbounded) {
    expect_finite(r);
    // Undamped at resonance the amplitude grows by about pi a per period until the contact nonlinearity bounds it.
    EXPECT_GT(r.dynamic_factor, 1.2);
  }
  if (r.status != ResponseStatus::kConverged) {
    EXPECT_FALSE(r.message.empty());
  }
}

// A 15,000 t ship chamber against a pinion: mass ratio 1e6 (J / r_b^2 = 15 kg).
TEST(DynamicsHardCases, MassRatioOneMillion) {
  DriveTrain t = dyntest::rigid_train();
  t.drive_inertia = 0.1;
  t.pinion_inertia = 0.05;
  t.moving_mass = 1.5e7;
  const double k = 8e8, c = std::cos(t.pressure_angle);
  const double w2 = k * (t.base_radius * t.base_radius / 0.15 + c * c / t.moving_mass);
  EXPECT_NEAR(std::pow(2 * M_PI * natural_frequencies_hz(t, k)[0], 2) / w2, 1.0, 1e-9);
  const MeshForceLaw law = dyntest::harmonic_gap_law(k, 1e-6, 0.02, 400);
  DynamicsOptions o;
  const SteadyResponse r = steady_response(t, law, 0.3, 5e4, o);
  ASSERT_EQ(r.status, ResponseStatus::kConverged) << r.message;
  expect_finite(r);
  EXPECT_GT(r.dynamic_factor, 1.0);
  EXPECT_TRUE(floquet(t, law, 0.3, 5e4, o).stable);
}

// Mesh frequency 0.25 Hz: quasi-static, still resolved by the natural-frequency steps.
TEST(DynamicsHardCases, MeshFrequencyBelowOneHertz) {
  const DriveTrain t = dyntest::rigid_train();
  const double k = 8e8, pitch = 0.02, fs = 16e3, a = 1e-6;
  const MeshForceLaw law = dyntest::harmonic_gap_law(k, a, pitch, 400);
  DynamicsOptions o;
  const SteadyResponse r = steady_response(t, law, 0.25 * pitch, fs, o);
  ASSERT_EQ(r.status, ResponseStatus::kConverged) << r.message;
  EXPECT_NEAR(r.excitation_period_s, 4.0, 1e-12);
  // Quasi-static: the approach follows the kinematic error, the force stays F_s.
  EXPECT_NEAR(r.dte_peak_to_peak / (2 * a), 1.0, 1e-3);
  EXPECT_NEAR(r.dynamic_factor, 1.0, 1e-3);
}

TEST(DynamicsHardCases, SweepWithOneSpeed) {
  const DriveTrain t = dyntest::rigid_train();
  const MeshForceLaw law = dyntest::harmonic_gap_law(8e8, 1e-6, 0.02, 400);
  DynamicsOptions o;
  const auto s = speed_sweep(t, law, {2.0}, 16e3, o);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].speed, 2.0);
  EXPECT_EQ(s[0].kv_up, s[0].kv_down);
  EXPECT_EQ(s[0].kv_up, steady_response(t, law, 2.0, 16e3, o).dynamic_factor);
  EXPECT_GT(s[0].kv_up, 1.0);
}

void expect_throw_naming(const std::function<void()>& f, const std::string& name) {
  try {
    f();
    ADD_FAILURE() << "no exception for " << name;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
}

TEST(DynamicsHardCases, BadArgumentsThrowNamingTheQuantity) {
  const DriveTrain t = dyntest::rigid_train();
  const MeshForceLaw law = dyntest::constant_law(8e8);
  DynamicsOptions o;
  expect_throw_naming([&] { steady_response(t, law, 0, 1e4, o); }, "speed");
  expect_throw_naming([&] { steady_response(t, law, std::nan(""), 1e4, o); }, "speed");
  expect_throw_naming([&] { steady_response(t, law, 1, -1, o); }, "static_force");
  expect_throw_naming([&] { floquet(t, law, 1, std::nan(""), o); }, "static_force");
  expect_throw_naming([&] { speed_sweep(t, law, {}, 1e4, o); }, "speeds");
  expect_throw_naming([&] { speed_sweep(t, law, {1, -2}, 1e4, o); }, "speed");
  DynamicsOptions bad = o;
  bad.damping_ratio = -0.1;
  expect_throw_naming([&] { steady_response(t, law, 1, 1e4, bad); }, "damping_ratio");
  bad = o;
  bad.steps_per_mesh_period = 0;
  expect_throw_naming([&] { steady_response(t, law, 1, 1e4, bad); }, "steps_per_mesh_period");
  bad = o;
  bad.periodic_tolerance = 0;
  expect_throw_naming([&] { steady_response(t, law, 1, 1e4, bad); }, "periodic_tolerance");
  bad = o;
  bad.max_periods = 0;
  expect_throw_naming([&] { steady_response(t, law, 1, 1e4, bad); }, "max_periods");
  MeshForceLaw l2 = law;
  l2.period = -1;
  expect_throw_naming([&] { steady_response(t, l2, 1, 1e4, o); }, "period");
  l2 = law;
  l2.gap[0] = -1e-6;
  expect_throw_naming([&] { l2.validate(); }, "gap");
  l2 = law;
  l2.stiffness.pop_back();
  expect_throw_naming([&] { l2.validate(); }, "stiffness");
  l2 = law;
  l2.travel = {0.0, 0.5 * law.period};
  expect_throw_naming([&] { l2.validate(); }, "travel");
  DriveTrain t2 = t;
  t2.moving_mass = -5;
  expect_throw_naming([&] { steady_response(t2, law, 1, 1e4, o); }, "moving_mass");
  // A speed so low that the natural period needs more than the step limit.
  expect_throw_naming([&] { steady_response(t, law, 1e-9, 1e4, o); }, "speed");
  expect_throw_naming([&] { drive_transient(t, law, 1, 1e4, o, DriveState{}, 0); }, "periods");
  expect_throw_naming([&] { law.force(std::nan(""), 0); }, "travel");
}

// The law's own evaluation against its definition.
TEST(MeshForceLaw, ForceTangentApproachOfTwoSlots) {
  MeshForceLaw law;
  law.period = 1;
  law.mesh_pitch = 1;
  law.slots = 2;
  law.travel = {0, 1};
  law.stiffness = {1e8, 2e8, 1e8, 2e8};
  law.gap = {0, 5e-6, 0, 5e-6};
  law.backlash = 1e-4;
  law.validate();
  EXPECT_DOUBLE_EQ(law.force(0.3, 2e-6), 1e8 * 2e-6);
  EXPECT_DOUBLE_EQ(law.force(0.3, 8e-6), 1e8 * 8e-6 + 2e8 * 3e-6);
  EXPECT_DOUBLE_EQ(law.force(0.3, -5e-5), 0);
  EXPECT_NEAR(law.force(0.3, -1.03e-4), -1e8 * 3e-6, 1e-9);
  EXPECT_DOUBLE_EQ(law.tangent(0.3, 8e-6), 3e8);
  EXPECT_DOUBLE_EQ(law.tangent(0.3, -5e-5), 0);
  EXPECT_DOUBLE_EQ(law.full_stiffness(1.7), 3e8);
  const double f = 1e8 * 8e-6 + 2e8 * 3e-6;
  EXPECT_NEAR(law.approach_at(0.3, f), 8e-6, 1e-18);
  EXPECT_NEAR(law.approach_at(0.3, 100), 1e-6, 1e-18);
  EXPECT_DOUBLE_EQ(law.mean_stiffness(), 3e8);
}

}  // namespace
}  // namespace rackopt
