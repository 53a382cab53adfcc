// The dynamics metrics (docs/metrics.md, "Dynamics"): what each reads of the
// dynamic analysis, the stresses with effects.dynamics on, nothing of the
// dynamics run when no metric asks, the set-up errors.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/dynamics/drive_dynamics.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt {
namespace {

using test::eval;
using test::problem;

// A short speed range keeps the sweep cheap.
Drive gantry() {
  Drive d = problem("gantry_axis");
  d.dynamics.speed_from = 1.9;
  d.dynamics.speed_to = 2.1;
  d.dynamics.speed_points = 3;
  return d;
}

TEST(DriveDynamicsMetrics, ReadTheAnalysisOfTheDrive) {
  const Drive d = gantry();
  const metrics::MetricValues v =
      eval(d, {"dynamic_factor", "dynamic_mesh_force_max", "dynamic_transmission_error_pp", "contact_loss_fraction",
               "resonance_margin"});
  ASSERT_TRUE(v.all_ok()) << v.first_failure()->message;
  EXPECT_TRUE(v.models_run.contains(metrics::Model::kDynamics));
  DynamicsRequest r;
  r.sweep = true;
  const DriveDynamics a = analyse_drive_dynamics(d, MeshStiffnessModel(d), r);
  EXPECT_DOUBLE_EQ(v.at("dynamic_factor").value, a.kv_max);
  EXPECT_DOUBLE_EQ(v.at("dynamic_mesh_force_max").value, a.at_speed->mesh_force_max);
  EXPECT_DOUBLE_EQ(v.at("dynamic_transmission_error_pp").value, a.at_speed->dte_peak_to_peak);
  EXPECT_DOUBLE_EQ(v.at("contact_loss_fraction").value, a.at_speed->contact_loss_fraction);
  EXPECT_DOUBLE_EQ(v.at("resonance_margin").value, a.resonance_margin);
  EXPECT_GE(v.at("dynamic_factor").value, 1.0);
}

// With effects.dynamics the stresses carry the computed K_V: the root stress
// is linear in the load factors, the contact stress goes with their root.
TEST(DriveDynamicsMetrics, StressesUseTheComputedDynamicFactorWithTheEffectOn) {
  Drive d = gantry();
  const metrics::MetricValues off = eval(d, {"root_bending_stress", "contact_stress"});
  ASSERT_TRUE(off.all_ok());
  EXPECT_FALSE(off.models_run.contains(metrics::Model::kDynamics)) << "the effect off costs nothing";
  d.effects.dynamics = true;
  const metrics::MetricValues on = eval(d, {"root_bending_stress", "contact_stress", "dynamic_factor"});
  ASSERT_TRUE(on.all_ok());
  const double kv = on.at("dynamic_factor").value;
  ASSERT_GT(kv, 1.0);
  const double ratio = std::max(1.0, kv) / d.load.dynamic_factor;
  EXPECT_NEAR(on.at("root_bending_stress").value, off.at("root_bending_stress").value * ratio,
              1e-12 * on.at("root_bending_stress").value);
  EXPECT_NEAR(on.at("contact_stress").value, off.at("contact_stress").value * std::sqrt(ratio),
              1e-12 * on.at("contact_stress").value);
}

TEST(DriveDynamicsMetrics, NeedTheDynamicsSection) {
  Drive d = gantry();
  d.dynamics.moving_mass = 0;
  try {
    eval(d, {"dynamic_factor"});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "dynamics.moving_mass");
  }
  d.effects.dynamics = true;
  EXPECT_THROW(eval(d, {"contact_stress"}), InputError) << "the stresses with the effect on need it too";
  Drive no_speed = gantry();
  no_speed.load.speed = 0;
  no_speed.dynamics.speed_points = 0;
  try {
    eval(no_speed, {"dynamic_factor"});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "dynamics.speed_range");
  }
}

}  // namespace
}  // namespace rackopt
