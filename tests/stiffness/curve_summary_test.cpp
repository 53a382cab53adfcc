// The summary curve (CurveDetail::kSummary, what the stiffness metrics ask
// for) against the full curve: the same samples, extremes, mean and
// breakpoints bit for bit, only without the pairs. Both compute every
// sample into one reused scratch state (the full curve then copies its
// pairs out), the full one with the relief bisection's pairs of neighbouring
// samples kept as well.
#include "rackopt/stiffness/mesh_stiffness.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/shipped_problems.hpp"

namespace rackopt {
namespace {

void expect_same_summary(const Drive& d) {
  const MeshStiffnessModel model(d);
  const StiffnessCurve full = model.curve();
  const StiffnessCurve summary = model.curve(CurveDetail::kSummary);
  // Exact equality on purpose: the two paths do the same arithmetic.
  EXPECT_EQ(summary.k_min, full.k_min);
  EXPECT_EQ(summary.k_max, full.k_max);
  EXPECT_EQ(summary.k_mean, full.k_mean);
  EXPECT_EQ(summary.travel_at_min, full.travel_at_min);
  EXPECT_EQ(summary.travel_at_max, full.travel_at_max);
  EXPECT_EQ(summary.k_fluctuation, full.k_fluctuation);
  EXPECT_EQ(summary.max_pairs, full.max_pairs);
  EXPECT_EQ(summary.breakpoints, full.breakpoints);
  EXPECT_EQ(summary.warnings, full.warnings);
  ASSERT_EQ(summary.samples.size(), full.samples.size());
  for (std::size_t i = 0; i < full.samples.size(); ++i) {
    const MeshState& a = summary.samples[i];
    const MeshState& b = full.samples[i];
    ASSERT_EQ(a.travel, b.travel) << "sample " << i;
    ASSERT_EQ(a.stiffness, b.stiffness) << "X = " << b.travel;
    ASSERT_EQ(a.approach, b.approach) << "X = " << b.travel;
    ASSERT_EQ(a.local_stiffness, b.local_stiffness) << "X = " << b.travel;
    ASSERT_TRUE(a.pairs.empty()) << "X = " << b.travel;
    ASSERT_FALSE(b.pairs.empty()) << "X = " << b.travel;
  }
}

TEST(CurveSummary, EqualsTheFullCurveOnEveryShippedProblem) {
  for (const char* file :
       {"rack_railway.yaml", "rack_railway_paper.yaml", "ship_lift.yaml", "large_module.yaml", "gantry_axis.yaml"}) {
    SCOPED_TRACE(file);
    expect_same_summary(test_support::load_shipped_problem(file));
  }
}

// Coarse sampling (more golden-section refinements per sample) and each
// body model: the paths that solve a sample differently.
TEST(CurveSummary, EqualsTheFullCurveForEachBodyModelAndSampling) {
  for (const char* body : {"rigid", "per_pair", "coupled"}) {
    for (const char* ppp : {"7", "24"}) {
      SCOPED_TRACE(std::string(body) + ", " + ppp + " positions per period");
      expect_same_summary(test_support::load_shipped_problem(
          "rack_railway.yaml",
          {std::string("effects.rack_span=") + body, std::string("numerics.positions_per_period=") + ppp}));
    }
  }
  SCOPED_TRACE("constant contact term");
  expect_same_summary(test_support::load_shipped_problem("rack_railway.yaml", {"effects.hertz=linear"}));
}

// With profile relief the loaded set of pairs decides extra breakpoints:
// the summary keeps the pairs while it bisects and drops them at the end.
TEST(CurveSummary, EqualsTheFullCurveWithProfileRelief) {
  Drive d = test_support::load_shipped_problem("rack_railway.yaml");
  d.pinion.tip_relief = {42e-6, 1.72 * d.pinion.module, ProfileRelief::Shape::kLinear};
  d.pinion.root_relief = d.pinion.tip_relief;
  expect_same_summary(d);
}

// A model given the drive's geometry (as evaluate_metrics does, which built
// it for the geometry metrics) is the model that builds it itself.
TEST(CurveSummary, ModelWithPrebuiltGeometryIsTheSame) {
  for (const char* file : {"rack_railway.yaml", "ship_lift.yaml", "large_module.yaml"}) {
    SCOPED_TRACE(file);
    const Drive d = test_support::load_shipped_problem(file);
    const StiffnessCurve own = MeshStiffnessModel(d).curve(CurveDetail::kSummary);
    const StiffnessCurve given = MeshStiffnessModel(d, build_mesh_geometry(d)).curve(CurveDetail::kSummary);
    EXPECT_EQ(given.k_min, own.k_min);
    EXPECT_EQ(given.k_max, own.k_max);
    EXPECT_EQ(given.k_mean, own.k_mean);
    EXPECT_EQ(given.travel_at_min, own.travel_at_min);
    EXPECT_EQ(given.warnings, own.warnings);
    ASSERT_EQ(given.samples.size(), own.samples.size());
    for (std::size_t i = 0; i < own.samples.size(); ++i) ASSERT_EQ(given.samples[i].stiffness, own.samples[i].stiffness);
  }
}

}  // namespace
}  // namespace rackopt
