// The dynamic analysis of a shipped drive (docs/models/dynamics.md,
// "Analysis"): natural frequencies against the closed form on the law's own
// tangent stiffness, the Campbell crossings and the resonance margin from
// their definitions, the default speed range, the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "rackopt/core/error.hpp"
#include "rackopt/dynamics/drive_dynamics.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt {
namespace {

using test_support::load_shipped_problem;

DriveDynamics gantry(const std::vector<std::string>& overrides, const DynamicsRequest& request) {
  const Drive drive = load_shipped_problem("gantry_axis.yaml", overrides);
  const MeshStiffnessModel model(drive);
  return analyse_drive_dynamics(drive, model, request);
}

DynamicsRequest frequencies_only() {
  DynamicsRequest r;
  r.response_at_speed = false;
  r.sweep = false;
  return r;
}

// A rigid drive train: one mode, omega^2 = k (r_b^2/J + cos^2 a / M) at every
// travel sample's tangent stiffness, the mean at the mean tangent.
TEST(DriveDynamics, NaturalFrequencyIsTheClosedFormOnTheLawsTangent) {
  const DriveDynamics d = gantry({"dynamics.drive_stiffness=0"}, frequencies_only());
  ASSERT_EQ(d.natural_frequencies_hz.size(), 1u);
  const DriveTrain& t = d.train;
  const double J = t.drive_inertia + t.pinion_inertia;
  const double flex = t.base_radius * t.base_radius / J + std::pow(std::cos(t.pressure_angle), 2) / t.moving_mass;
  auto f = [&](double k) { return std::sqrt(k * flex) / (2 * std::numbers::pi); };
  EXPECT_NEAR(d.natural_frequencies_hz[0], f(d.mean_stiffness), 1e-9 * d.natural_frequencies_hz[0]);
  ASSERT_EQ(d.natural_frequency_along_travel[0].size(), d.law.travel.size());
  for (std::size_t j = 0; j < d.law.travel.size(); j += 97) {
    const double x = d.law.travel[j];
    const double k = d.law.tangent(x, d.law.approach_at(x, d.static_force));
    EXPECT_NEAR(d.natural_frequency_along_travel[0][j], f(k), 1e-9 * f(k)) << "sample " << j;
  }
  // The tangent under load is the static model's stiffness where no corner
  // contact acts: its mean lies within a few percent of the curve's.
  const Drive drive = load_shipped_problem("gantry_axis.yaml");
  const StiffnessCurve curve = MeshStiffnessModel(drive).curve(CurveDetail::kSummary);
  EXPECT_NEAR(d.mean_stiffness, curve.k_mean, 0.05 * curve.k_mean);
}

// A drive spring adds the drive's twist mode above the mesh mode.
TEST(DriveDynamics, ADriveSpringAddsASecondMode) {
  const DriveDynamics rigid = gantry({"dynamics.drive_stiffness=0"}, frequencies_only());
  const DriveDynamics sprung = gantry({}, frequencies_only());
  ASSERT_EQ(sprung.natural_frequencies_hz.size(), 2u);
  EXPECT_LT(sprung.natural_frequencies_hz[0], sprung.natural_frequencies_hz[1]);
  // A spring in series can only lower the mesh mode.
  EXPECT_LT(sprung.natural_frequencies_hz[0], rigid.natural_frequencies_hz[0]);
}

// Each order meets each mode at v = f lambda; the margin is the relative
// distance of the operating speed from the nearest mesh or span crossing of
// mode 1.
TEST(DriveDynamics, CampbellCrossingsAndResonanceMarginFollowTheirDefinitions) {
  const DriveDynamics d = gantry({}, frequencies_only());
  const double p = d.law.mesh_pitch, l = d.law.period;
  EXPECT_NEAR(p, std::numbers::pi * load_shipped_problem("gantry_axis.yaml").pinion.module, 1e-15);
  ASSERT_EQ(d.resonances.size(), d.orders.size() * d.natural_frequencies_hz.size());
  double margin = std::numeric_limits<double>::infinity();
  for (const Resonance& r : d.resonances) {
    const double lambda = r.order == "mesh" ? p : r.order == "2 x mesh" ? p / 2 : r.order == "3 x mesh" ? p / 3 : l;
    EXPECT_NEAR(r.speed_at_mean, d.natural_frequencies_hz[r.mode] * lambda, 1e-12 * r.speed_at_mean) << r.order;
    EXPECT_LE(r.speed_low, r.speed_at_mean);
    EXPECT_GE(r.speed_high, r.speed_at_mean);
    if (r.mode == 0 && (r.order == "mesh" || r.order == "span"))
      margin = std::min(margin, std::abs(d.operating_speed - r.speed_at_mean) / r.speed_at_mean);
  }
  EXPECT_DOUBLE_EQ(d.resonance_margin, margin);
  // Running exactly at the mesh resonance leaves no margin.
  DynamicsRequest at = frequencies_only();
  at.speed = d.natural_frequencies_hz[0] * p;
  EXPECT_NEAR(gantry({}, at).resonance_margin, 0.0, 1e-12);
}

TEST(DriveDynamics, DefaultSpeedRangeSurroundsTheOperatingSpeed) {
  const Drive drive = load_shipped_problem("gantry_axis.yaml");
  const std::vector<double> v = dynamics_speeds(drive, 2.0);
  ASSERT_EQ(v.size(), 40u);
  EXPECT_DOUBLE_EQ(v.front(), 0.1);
  EXPECT_DOUBLE_EQ(v.back(), 2.5);
  Drive none = drive;
  none.load.speed = 0;
  EXPECT_THROW(dynamics_speeds(none, 0.0), InputError);
  const Drive given = load_shipped_problem(
      "gantry_axis.yaml", {"dynamics.speed_range.from=1 m/s", "dynamics.speed_range.to=3 m/s",
                           "dynamics.speed_range.points=5"});
  EXPECT_EQ(dynamics_speeds(given, 2.0), (std::vector<double>{1, 1.5, 2, 2.5, 3}));
}

// The response at the operating speed: K_V is its largest force over the
// static force, and the falling sweep equals the rising one where the flanks
// never separate.
TEST(DriveDynamics, ResponseAndSweepAgreeWithTheirDefinitions) {
  DynamicsRequest r;
  r.sweep = true;
  const DriveDynamics d = gantry({"dynamics.speed_range.from=1.9 m/s", "dynamics.speed_range.to=2.1 m/s",
                                  "dynamics.speed_range.points=3"},
                                 r);
  ASSERT_TRUE(d.at_speed.has_value());
  const SteadyResponse& s = *d.at_speed;
  EXPECT_NEAR(s.dynamic_factor, s.mesh_force_max / d.static_force, 1e-12);
  EXPECT_GE(s.dynamic_factor, 1.0);
  ASSERT_EQ(d.sweep.size(), 3u);
  // The middle speed is the operating speed: the same periodic state,
  // reached from another start, so equal to the periodic tolerance (1e-6 of
  // the state) times the force's sensitivity to it.
  EXPECT_NEAR(d.sweep[1].kv_up, s.dynamic_factor, 1e-5 * s.dynamic_factor);
  double kv_max = 0;
  for (const SweepPoint& p : d.sweep) {
    kv_max = std::max({kv_max, p.kv_up, p.kv_down});
    if (p.contact_loss_up == 0) {
      EXPECT_EQ(p.kv_down, p.kv_up);
    }
  }
  EXPECT_EQ(d.kv_max, kv_max);
}

TEST(DriveDynamics, RefusesWithoutAMovingMass) {
  Drive drive = load_shipped_problem("gantry_axis.yaml");
  drive.dynamics.moving_mass = 0;
  const MeshStiffnessModel model(drive);
  EXPECT_THROW(analyse_drive_dynamics(drive, model, frequencies_only()), InputError);
}

}  // namespace
}  // namespace rackopt
