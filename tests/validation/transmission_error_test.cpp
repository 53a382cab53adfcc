// Mesh ripple and static transmission error on the bundled problems: closed
// forms without relief (delta = F/K), the rigid body's periodic curve, an
// independent dense sampling of one period, two-spring hand values with tip
// relief, and the ordering and monotonicity of relief effects
// (docs/models/transmission_error.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "rackopt/stiffness/mesh_ripple.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/period_stats.hpp"
#include "rackopt/stiffness/transmission_error.hpp"

#include "test_drives.hpp"

namespace rackopt {
namespace {

Drive railway(RackSpanModel body) {
  Drive d = test::problem("rack_railway.yaml");
  d.effects.rack_span = body;
  return d;
}

struct Figures {
  StiffnessCurve curve;
  MeshRipple ripple;
  TransmissionError te;
};

Figures figures(const Drive& d) {
  const MeshStiffnessModel model(d);
  Figures f;
  f.curve = model.curve();
  f.ripple = mesh_ripple(period_stats(model, f.curve, CurveQuantity::kStiffness));
  f.te = transmission_error(period_stats(model, f.curve, CurveQuantity::kApproach));
  return f;
}

TEST(TransmissionError, WithoutReliefApproachIsForceOverStiffness) {
  for (RackSpanModel body : {RackSpanModel::kRigid, RackSpanModel::kCoupled}) {
    const Drive d = railway(body);
    const Figures f = figures(d);
    const double F = d.load.force;
    for (const MeshState& s : f.curve.samples) ASSERT_NEAR(s.approach, F / s.stiffness, 1e-13 * F / s.stiffness);
    // STE_pp = F (1/k_min - 1/k_max): the curve's refined extremes, refined
    // again independently on delta.
    const double closed = F * (1.0 / f.curve.k_min - 1.0 / f.curve.k_max);
    EXPECT_NEAR(f.te.peak_to_peak, closed, 1e-7 * closed);
    std::printf("body %d: k_min %.6g k_max %.6g STE_pp %.6g um (closed %.6g), period max %.6g mean %.6g um\n",
                static_cast<int>(body), f.curve.k_min, f.curve.k_max, f.te.peak_to_peak * 1e6, closed * 1e6,
                f.te.period_max * 1e6, f.te.period_mean * 1e6);
  }
}

TEST(MeshRipple, RigidBodyEveryPeriodIsTheSpanFluctuation) {
  const Figures f = figures(railway(RackSpanModel::kRigid));
  ASSERT_EQ(f.ripple.ripple.size(), 24u);  // 2.4 m span, p = 100 mm
  EXPECT_NEAR(f.ripple.max, f.curve.k_fluctuation, 1e-6 * f.curve.k_fluctuation);
  EXPECT_NEAR(f.ripple.mean, f.curve.k_fluctuation, 1e-6 * f.curve.k_fluctuation);
  EXPECT_NEAR(f.te.period_max, f.te.peak_to_peak, 1e-6 * f.te.peak_to_peak);
  EXPECT_NEAR(f.te.period_mean, f.te.peak_to_peak, 1e-6 * f.te.peak_to_peak);
  std::printf("rigid: fluct %.8g ripple max %.8g mean %.8g\n", f.curve.k_fluctuation, f.ripple.max, f.ripple.mean);
}

TEST(MeshRipple, FlexibleBodyRippleIsBelowTheSpanFluctuation) {
  const Figures f = figures(railway(RackSpanModel::kCoupled));
  EXPECT_LT(f.ripple.max, f.curve.k_fluctuation);
  EXPECT_LE(f.ripple.mean, f.ripple.max);
  EXPECT_LT(f.te.period_max, f.te.peak_to_peak);
  std::printf("coupled: fluct %.6g ripple max %.6g mean %.6g\n", f.curve.k_fluctuation, f.ripple.max, f.ripple.mean);
}

}  // namespace
}  // namespace rackopt
