// The mesh ripple and transmission error metrics: registered with their
// units and models, computed only when asked, equal to the stiffness
// module's functions, the closed form without relief, and reachable as
// design variables through the relief keys.
#include "rackopt/metrics/mesh_dynamics_metrics.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "metrics_test_support.hpp"
#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/metrics/model_results.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/period_stats.hpp"

namespace rackopt::metrics {
namespace {

using test::path;
using test::requests;

const char* const kNames[] = {"mesh_ripple_max", "mesh_ripple_mean", "transmission_error_pp",
                              "transmission_error_pp_period_max", "transmission_error_pp_period_mean"};

TEST(MeshDynamicsMetrics, RegisteredWithUnitsAndTheCurveModel) {
  for (const char* n : kNames) {
    SCOPED_TRACE(n);
    const MetricDefinition& d = find_metric(n);
    const bool te = std::string(n).rfind("transmission_error", 0) == 0;
    // The figure it reads and the curve that figure comes from.
    EXPECT_EQ(d.models, (ModelSet{Model::kStiffnessCurve, te ? Model::kTransmissionError : Model::kMeshRipple}));
    EXPECT_FALSE(d.smooth);  // extremes over periods: kinks in the design
    EXPECT_EQ(d.requirements, 0);
    EXPECT_EQ(d.unit, te ? "m" : "-");
    EXPECT_EQ(d.display_unit, te ? "um" : "");
  }
}

TEST(MeshDynamicsMetrics, ComputedOnlyWhenAskedFor) {
  const Drive d = load_problem(path("rack_railway"));
  const MeshStiffnessModel model(d);
  const StiffnessCurve curve = model.curve();
  const auto none = mesh_dynamics_figures(model, curve, ModelSet{Model::kStiffnessCurve});
  EXPECT_FALSE(none.ripple);
  EXPECT_FALSE(none.transmission_error);
  const auto ripple_only = mesh_dynamics_figures(model, curve, find_metric("mesh_ripple_mean").models);
  EXPECT_TRUE(ripple_only.ripple);
  EXPECT_FALSE(ripple_only.transmission_error);
  // Through evaluate_metrics: the figures a request needs, and nothing else.
  const MetricValues te = evaluate_metrics(d, requests({"transmission_error_pp", "min_stiffness"}));
  ASSERT_TRUE(te.all_ok());
  EXPECT_EQ(te.models_run, (ModelSet{Model::kStiffnessCurve, Model::kTransmissionError}));
  EXPECT_EQ(te.model_runs, 1);
}

// The accessors refuse a figure that was not declared (a registry mistake),
// with a message instead of std::bad_optional_access.
TEST(MeshDynamicsMetrics, AnUndeclaredFigureIsALogicError) {
  ModelResults m;
  m.curve_slot.value = StiffnessCurve{};
  EXPECT_THROW(m.mesh_ripple(), std::logic_error);
  EXPECT_THROW(m.transmission_error(), std::logic_error);
}

TEST(MeshDynamicsMetrics, ValuesAreTheStiffnessModulesAndTheClosedForm) {
  const Drive d = load_problem(path("rack_railway"));
  const MetricValues v = evaluate_metrics(
      d, requests({"mesh_ripple_max", "mesh_ripple_mean", "transmission_error_pp", "transmission_error_pp_period_max",
                   "transmission_error_pp_period_mean", "min_stiffness", "max_stiffness", "stiffness_fluctuation"}));
  ASSERT_TRUE(v.all_ok());
  EXPECT_EQ(v.model_runs, 1);  // one curve serves all
  const MeshStiffnessModel model(d);
  const StiffnessCurve curve = model.curve();
  const MeshRipple r = mesh_ripple(period_stats(model, curve, CurveQuantity::kStiffness));
  const TransmissionError te = transmission_error(period_stats(model, curve, CurveQuantity::kApproach));
  EXPECT_EQ(v.at("mesh_ripple_max").value, r.max);
  EXPECT_EQ(v.at("mesh_ripple_mean").value, r.mean);
  EXPECT_EQ(v.at("transmission_error_pp").value, te.peak_to_peak);
  EXPECT_EQ(v.at("transmission_error_pp_period_max").value, te.period_max);
  EXPECT_EQ(v.at("transmission_error_pp_period_mean").value, te.period_mean);
  // No relief: delta = F/K, so STE_pp = F (1/k_min - 1/k_max).
  const double F = d.load.force;
  const double closed = F * (1 / v.at("min_stiffness").value - 1 / v.at("max_stiffness").value);
  EXPECT_NEAR(v.at("transmission_error_pp").value, closed, 1e-7 * closed);
  EXPECT_LT(v.at("mesh_ripple_max").value, v.at("stiffness_fluctuation").value);
  EXPECT_NE(v.at("transmission_error_pp").display.find("um"), std::string::npos);
}

// Relief amount and length are design variables: a study writes them into
// the problem tree like any numeric key, and the transmission error follows.
TEST(MeshDynamicsMetrics, ReliefKeysAreDesignVariables) {
  const ProblemTree tree = load_problem_tree_file(path("rack_railway"), {"effects.rack_span=rigid"});
  const auto want = requests({"transmission_error_pp"});
  auto te = [&](double amount) {
    const std::vector<std::pair<std::string, double>> x{{"pinion.tip_relief.amount", amount},
                                                        {"pinion.tip_relief.length", 1.72},
                                                        {"pinion.root_relief.amount", amount},
                                                        {"pinion.root_relief.length", 1.72}};
    const MetricValues v = evaluate_metrics(drive_with_values(tree, x), want);
    EXPECT_TRUE(v.all_ok());
    return v.values.at(0).value;
  };
  const double none = te(0), some = te(40e-6), much = te(100e-6);
  EXPECT_LT(some, 0.5 * none);  // the long relief flattens the rigid-body STE (22.1 -> 4.3 um)
  EXPECT_GT(much, some);
}

}  // namespace
}  // namespace rackopt::metrics
