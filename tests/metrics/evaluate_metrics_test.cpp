// evaluate_metrics: only the needed models run, each once; every metric
// against an independent number or property; design errors become failed
// values with their code.
#include "rackopt/metrics/evaluate_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "metrics_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/metrics/ks_aggregate.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::metrics {
namespace {

using test::eval;
using test::path;
using test::problem;
using test::requests;

TEST(EvaluateMetrics, OnlyTheNeededModelsRunEachOnce) {
  const Drive railway = problem("rack_railway");
  const Drive ship = problem("ship_lift");
  {
    const MetricValues v = eval(railway, {"contact_ratio"});
    EXPECT_EQ(v.models_run, (ModelSet{Model::kGeometry}));  // no stiffness curve
    EXPECT_EQ(v.model_runs, 1);
  }
  {
    const MetricValues v = eval(railway, {"supports_per_metre"});
    EXPECT_TRUE(v.models_run.empty());
    EXPECT_EQ(v.model_runs, 0);
  }
  {
    // Seven metrics read one curve: one computation, no geometry/wear/stress.
    const MetricValues v = eval(ship, {"min_stiffness", "max_stiffness", "mean_stiffness", "stiffness_fluctuation",
                                       "min_stiffness_ks", "max_stiffness_ks(50)", "stiffness_fluctuation_ks"});
    EXPECT_EQ(v.models_run, (ModelSet{Model::kStiffnessCurve}));  // never a WearModel
    EXPECT_EQ(v.model_runs, 1);
    EXPECT_TRUE(v.all_ok());
  }
  {
    const MetricValues v = eval(ship, {"wear_life", "wear_life_cycles", "wear_life_at_R(0.9)", "wear_life_at_R(0.5)"});
    EXPECT_EQ(v.models_run, (ModelSet{Model::kWearLife, Model::kWearReliability}));
    EXPECT_EQ(v.model_runs, 1);  // one WearModel serves the nominal life and the exact quantiles
  }
  {
    const MetricValues v = eval(ship, {"root_bending_stress", "contact_stress", "rack_root_bending_stress"});
    EXPECT_EQ(v.models_run, (ModelSet{Model::kGeometry, Model::kStress}));
    EXPECT_EQ(v.model_runs, 2);
  }
}

// Stiffness metrics are reads of the curve; what is tested is their order
// and the KS bounds. The aggregates are KS on ln k over N = samples + 2 values
// (the refined extremes are included), so k_min N^(-1/rho) <= ks_min <= k_min
// and k_max <= ks_max <= k_max N^(1/rho).
TEST(EvaluateMetrics, StiffnessOrderAndKsBounds) {
  const Drive d = problem("rack_railway");
  const StiffnessCurve curve = MeshStiffnessModel(d).curve();
  const double n = static_cast<double>(curve.samples.size() + 2);
  const MetricValues v = eval(d, {"min_stiffness", "mean_stiffness", "max_stiffness", "stiffness_fluctuation",
                                  "min_stiffness_ks(100)", "max_stiffness_ks(100)", "stiffness_fluctuation_ks(100)"});
  ASSERT_TRUE(v.all_ok()) << v.first_failure()->message;
  const double kmin = v.values[0].value, kmean = v.values[1].value, kmax = v.values[2].value;
  EXPECT_LT(kmin, kmean);
  EXPECT_LT(kmean, kmax);
  EXPECT_NEAR(v.values[3].value, (kmax - kmin) / kmean, 1e-12);
  const double ksmin = v.values[4].value, ksmax = v.values[5].value;
  EXPECT_LE(ksmin, kmin);
  EXPECT_GE(ksmin, kmin * std::pow(n, -1.0 / 100));
  EXPECT_GE(ksmax, kmax);
  EXPECT_LE(ksmax, kmax * std::pow(n, 1.0 / 100));
  EXPECT_GE(v.values[6].value, v.values[3].value);  // smooth fluctuation bounds the true one from above
  EXPECT_NEAR(v.values[6].value, (ksmax - ksmin) / kmean, 1e-12);
}

// The metrics' own sampling: the curve they read has that many positions
// per period (the KS aggregates count its samples), the refined extremes
// stay the curve's, and the mean moves by the coarser quadrature's error
// only (docs/accuracy.md, "Positions per period for the metrics").
TEST(EvaluateMetrics, MetricSamplingSetsTheCurvesPositions) {
  const Drive d = problem("rack_railway");
  MetricOptions coarse;
  coarse.positions_per_period = 24;
  const auto texts = {"min_stiffness", "max_stiffness", "mean_stiffness", "min_stiffness_ks(100)"};
  const MetricValues own = eval(d, texts);
  const MetricValues few = eval(d, texts, coarse);
  ASSERT_TRUE(own.all_ok() && few.all_ok());
  EXPECT_NEAR(few.values[0].value / own.values[0].value, 1.0, 1e-12);
  EXPECT_NEAR(few.values[1].value / own.values[1].value, 1.0, 1e-12);
  EXPECT_NE(few.values[2].value, own.values[2].value);
  EXPECT_NEAR(few.values[2].value / own.values[2].value, 1.0, 1e-6);
  const StiffnessCurve curve = MeshStiffnessModel(d).curve(CurveDetail::kSummary, 24);
  const double n = static_cast<double>(curve.samples.size() + 2);
  EXPECT_GE(few.values[3].value, few.values[0].value * std::pow(n, -1.0 / 100));
  EXPECT_GT(few.values[3].value, own.values[3].value);  // fewer samples near the minimum
  MetricOptions bad;
  bad.positions_per_period = 3;
  EXPECT_THROW(eval(d, {"min_stiffness"}, bad), InputError);
  // Without a curve metric the sampling is never read, yet still checked.
  EXPECT_THROW(eval(d, {"contact_ratio"}, bad), InputError);
}

TEST(EvaluateMetrics, KsMinConvergesMonotonicallyFromBelowAsRhoGrows) {
  const Drive d = problem("ship_lift");
  const MetricValues v = eval(d, {"min_stiffness", "min_stiffness_ks(10)", "min_stiffness_ks(100)",
                                  "min_stiffness_ks(1000)", "min_stiffness_ks(10000)", "min_stiffness_ks(100000)"});
  ASSERT_TRUE(v.all_ok());
  const double kmin = v.values[0].value;
  double prev_gap = INFINITY;
  for (std::size_t i = 1; i < v.values.size(); ++i) {
    const double gap = kmin - v.values[i].value;
    EXPECT_GE(gap, 0) << v.values[i].label;
    EXPECT_LT(gap, prev_gap) << v.values[i].label;
    prev_gap = gap;
  }
  EXPECT_LT(prev_gap / kmin, 1e-4);  // rho = 1e5: bound ln(N)/rho = 6e-5
}

// Closed form of the KS aggregate on a set where it is known exactly:
// m copies of the minimum and the rest far away give ks_min = min - S ln(m)/rho.
TEST(KsAggregate, ClosedFormAndBounds) {
  const std::vector<double> v{5, 5, 5, 1e3, 2e3};
  EXPECT_NEAR(ks_min(v, 10, 1), 5 - std::log(3.0) / 10, 1e-12);
  EXPECT_NEAR(ks_max(std::vector<double>{7, 7, -1e3}, 4, 2), 7 + 2 * std::log(2.0) / 4, 1e-12);
  const std::vector<double> w{1e8, 1.2e8, 0.9e8, 1.1e8};
  for (double rho : {1.0, 10.0, 100.0}) {
    EXPECT_LE(ks_min(w, rho, 1e8), 0.9e8);
    EXPECT_GE(ks_min(w, rho, 1e8), 0.9e8 - 1e8 * std::log(4.0) / rho);
    EXPECT_GE(ks_max(w, rho, 1e8), 1.2e8);
  }
  EXPECT_THROW(ks_min(std::vector<double>{}, 1, 1), InputError);
  EXPECT_THROW(ks_min(w, 0, 1), InputError);
}

TEST(EvaluateMetrics, ContactRatioIsTheGeometrysAndSupportsPerMetreIsExact) {
  const ProblemTree tree = load_problem_tree_file(path("rack_railway"));
  const std::vector<std::pair<std::string, double>> x{{"rack.span", 1.25}, {"mounting.clearance", 0.002}};
  const Drive d = drive_with_values(tree, x);
  const MetricValues v = eval(d, {"contact_ratio", "supports_per_metre"});
  ASSERT_TRUE(v.all_ok());
  EXPECT_EQ(v.values[0].value, build_mesh_geometry(d).path.contact_ratio);
  EXPECT_EQ(v.values[1].value, 0.8);  // 1/1.25 is exact in binary
  EXPECT_EQ(v.values[1].display, "0.8 1/m");
}

TEST(EvaluateMetrics, WearLifeIsTheWearModelsOnShipLift) {
  const Drive d = problem("ship_lift");
  const MetricValues v = eval(d, {"wear_life", "wear_life_cycles"});
  ASSERT_TRUE(v.all_ok());
  const WearLifeResult direct = WearModel(d).life(WearSample{});
  EXPECT_GT(v.values[0].value, 0);
  EXPECT_TRUE(std::isfinite(v.values[0].value));
  EXPECT_EQ(v.values[0].value, direct.life_years * kSecondsPerYear);
  EXPECT_EQ(v.values[1].value, direct.life_cycles);
  // Seconds from cycles and the duty (passes per year).
  EXPECT_NE(v.values[0].display.find("yr"), std::string::npos);
  EXPECT_NEAR(v.values[0].value, direct.life_cycles / d.duty.rack_meshes_per_year * kSecondsPerYear,
              1e-12 * v.values[0].value);
}

// One monotone random input (the contact ratio, as in the wear paper): the exact
// life at R must lie inside the distribution-free order-statistic interval of
// an independent 300-sample Monte Carlo run, it is the exact quantile that
// run_wear_reliability reports, and the life falls as the demanded R rises.
TEST(EvaluateMetrics, WearLifeAtRExactPathInsideMonteCarloIntervalAndFallsWithR) {
  Drive d = problem("ship_lift");
  d.wear.update_profile = false;  // cheaper; the statistics are what is tested
  RandomInput eps;
  eps.key = "contact_ratio";
  eps.distribution = RandomInput::Distribution::kNormal;
  eps.absolute = true;  // the contact ratio itself (the design is not varied here)
  eps.a = 1.45;  // 4 sd below eps_max = 1.536 (ship_lift.yaml), 7 sd above [eps] = 1.3
  eps.b = 0.02;
  d.reliability.inputs = {eps};
  d.reliability.reliabilities = {0.5, 0.9, 0.99};
  WearReliabilityOptions ro;
  ro.samples = 300;
  ro.bootstrap_replicates = 20;
  ro.threads = 1;
  const WearReliabilityResult mc = run_wear_reliability(d, ro);
  ASSERT_TRUE(mc.exact.available);
  const MetricValues v = eval(d, {"wear_life_at_R(0.5)", "wear_life_at_R(0.9)", "wear_life_at_R(0.99)"});
  ASSERT_TRUE(v.all_ok());
  for (std::size_t i = 0; i < 3; ++i) {
    const statistics::LifeInterval& e = mc.summary.life[i].empirical;
    if (e.lower_bounded) {
      EXPECT_GE(v.values[i].value, e.lower * (1 - 1e-9)) << v.values[i].label;
    }
    if (e.upper_bounded) {
      EXPECT_LE(v.values[i].value, e.upper * (1 + 1e-9)) << v.values[i].label;
    }
    EXPECT_EQ(v.values[i].value, mc.exact.life_at_R_years[i] * kSecondsPerYear);
    EXPECT_NE(v.values[i].message.find("exact quantile"), std::string::npos);
  }
  EXPECT_GT(v.values[0].value, v.values[1].value);
  EXPECT_GT(v.values[1].value, v.values[2].value);
  EXPECT_GT(v.values[2].value, 0.0);
}

// A life at R above the nominal life is a warning of the metric: an
// absolute coefficient distribution (median 3e-6) on a design whose own
// coefficient is 1e-4 (wear 33x faster) says R = 0.9 lives far above the
// design's nominal life. Around the design (a factor with median 1) the
// same scatter gives no warning.
TEST(EvaluateMetrics, WearLifeAtRAboveTheNominalLifeWarns) {
  Drive d = problem("ship_lift");
  d.wear.update_profile = false;
  d.wear.coefficient = 1e-4;
  RandomInput k;
  k.key = "wear.coefficient";
  k.distribution = RandomInput::Distribution::kLognormal;
  k.absolute = true;
  k.a = 3e-6;
  k.b = 0.3;
  d.reliability.inputs = {k};
  auto warned = [](const MetricValues& v) {
    for (const std::string& w : v.warnings)
      if (w.find("above the nominal wear life") != std::string::npos) return true;
    return false;
  };
  const MetricValues a = eval(d, {"wear_life", "wear_life_at_R(0.9)"});
  ASSERT_TRUE(a.all_ok());
  EXPECT_GT(a.values[1].value, a.values[0].value);
  EXPECT_TRUE(warned(a));
  d.reliability.inputs[0].absolute = false;
  d.reliability.inputs[0].a = 1.0;  // median factor: the design's own coefficient
  const MetricValues b = eval(d, {"wear_life", "wear_life_at_R(0.9)"});
  ASSERT_TRUE(b.all_ok());
  EXPECT_LT(b.values[1].value, b.values[0].value);
  EXPECT_FALSE(warned(b));
}

// The metric follows the design: 4 mm of clearance lowers the shipped ship
// lift's wear_life_at_R(0.9) with its nominal life, and it is the exact
// quantile life run_wear_reliability reports for that design
// (tests/wear_reliability/design_scatter_test.cpp checks that life independently).
TEST(EvaluateMetrics, WearLifeAtRFollowsTheClearance) {
  const Drive d0 = problem("ship_lift");
  const Drive d4 = load_problem(path("ship_lift"), {"mounting.clearance=4 mm"});
  const MetricValues v0 = eval(d0, {"wear_life", "wear_life_at_R(0.9)"});
  const MetricValues v4 = eval(d4, {"wear_life", "wear_life_at_R(0.9)"});
  ASSERT_TRUE(v0.all_ok());
  ASSERT_TRUE(v4.all_ok());
  EXPECT_LT(v4.values[0].value, v0.values[0].value - 5 * kSecondsPerYear);
  EXPECT_LT(v4.values[1].value, v0.values[1].value - 3 * kSecondsPerYear);
  Drive r4 = d4;
  r4.reliability.reliabilities = {0.9};
  WearReliabilityOptions ro = wear_reliability_options(r4);
  ro.samples = 1;
  ro.threads = 1;
  ro.life_table = false;
  EXPECT_DOUBLE_EQ(v4.values[1].value, run_wear_reliability(r4, ro).exact.life_at_R_years.at(0) * kSecondsPerYear);
}

// Two random inputs: Monte Carlo through run_wear_reliability with a fixed
// seed, so the same design gives the same number (common random numbers).
TEST(EvaluateMetrics, WearLifeAtRMonteCarloIsDeterministicAndFallsWithR) {
  Drive d = problem("ship_lift");
  d.wear.update_profile = false;  // cheaper; the statistics are what is tested
  RandomInput k;
  k.key = "wear.coefficient";
  k.distribution = RandomInput::Distribution::kLognormal;
  k.absolute = true;  // the coefficient itself (the design is not varied here)
  k.a = 3e-6;
  k.b = 0.2;
  d.reliability.inputs.push_back(k);
  MetricOptions o;
  o.reliability_samples = 60;
  o.bootstrap_replicates = 20;
  const MetricValues a = eval(d, {"wear_life_at_R(0.5)", "wear_life_at_R(0.9)", "wear_life", "wear_life_at_R(0.99)"}, o);
  const MetricValues b = eval(d, {"wear_life_at_R(0.5)", "wear_life_at_R(0.9)", "wear_life", "wear_life_at_R(0.99)"}, o);
  ASSERT_TRUE(a.all_ok()) << a.first_failure()->message;
  EXPECT_EQ(a.model_runs, 1);  // the Monte Carlo run also gives the nominal life
  for (std::size_t i = 0; i < a.values.size(); ++i) EXPECT_EQ(a.values[i].value, b.values[i].value);
  EXPECT_GT(a.values[0].value, a.values[1].value);
  EXPECT_GT(a.values[1].value, a.values[3].value);
  EXPECT_NE(a.values[0].message.find("Monte Carlo, 60 samples"), std::string::npos) << a.values[0].message;
  EXPECT_EQ(a.values[2].value, WearModel(d).life().life_years * kSecondsPerYear);
}

TEST(EvaluateMetrics, DesignErrorsBecomeFailedValuesWithTheirCode) {
  const ProblemTree tree = load_problem_tree_file(path("ship_lift"));
  {
    // Rack datum moved 60 mm away: eps = 1.536 - 0.06/(p_b sin a0) = 1.536 - 0.943 < 1 (docs/models/geometry.md).
    const std::vector<std::pair<std::string, double>> x{{"mounting.clearance", 0.06}};
    const Drive d = drive_with_values(tree, x);
    const MetricValues v = eval(d, {"contact_ratio", "min_stiffness", "supports_per_metre", "contact_stress"});
    EXPECT_FALSE(v.all_ok());
    for (int i : {0, 1, 3}) {
      EXPECT_FALSE(v.values[i].ok);
      EXPECT_EQ(v.values[i].error_code, "contact_ratio_below_one") << v.values[i].label;
      EXPECT_NE(v.values[i].message.find("contact ratio"), std::string::npos) << v.values[i].message;
      EXPECT_EQ(v.values[i].value, 0.0);
    }
    EXPECT_TRUE(v.values[2].ok);  // needs no model
    EXPECT_EQ(v.first_failure(), &v.values[0]);
  }
  {
    // A huge profile shift makes the pinion tooth pointed.
    Drive d = problem("ship_lift");
    d.pinion.profile_shift = 2.0;
    const MetricValues v = eval(d, {"contact_ratio", "wear_life", "root_bending_stress"});
    for (const MetricValue& m : v.values) {
      EXPECT_FALSE(m.ok);
      EXPECT_EQ(m.error_code, "pointed_tooth") << m.label << ": " << m.message;
    }
  }
}

// The railway pinion is undercut: geometry and the stiffness model both warn
// about it, the result lists each warning once.
TEST(EvaluateMetrics, WarningsOfSharedGeometryAppearOnce) {
  const MetricValues v = eval(problem("rack_railway"), {"contact_ratio", "min_stiffness"});
  ASSERT_FALSE(v.warnings.empty());
  for (std::size_t i = 0; i < v.warnings.size(); ++i) {
    for (std::size_t j = i + 1; j < v.warnings.size(); ++j) EXPECT_NE(v.warnings[i], v.warnings[j]);
  }
}

TEST(EvaluateMetrics, MissingConfigurationIsAnInputErrorNotAFailedDesign) {
  Drive railway = problem("rack_railway");  // no wear section
  EXPECT_THROW(eval(railway, {"wear_life"}), InputError);
  // The file gives allowables (materials.steel); without them the safety
  // factors cannot be computed.
  railway.pinion.material.allowable_bending = railway.rack.material.allowable_bending = 0;
  railway.pinion.material.allowable_contact = railway.rack.material.allowable_contact = 0;
  EXPECT_THROW(eval(railway, {"root_bending_safety"}), InputError);
  EXPECT_THROW(eval(railway, {"contact_safety"}), InputError);
  Drive no_duty = problem("ship_lift");
  no_duty.duty.rack_meshes_per_year = 0;
  no_duty.duty.pinion_meshes_per_year = 0;
  EXPECT_THROW(eval(no_duty, {"wear_life"}), InputError);
  EXPECT_TRUE(eval(no_duty, {"wear_life_cycles"}).all_ok());  // cycles need no duty
}

// S = allowable / stress: checked against the stresses of the same call.
TEST(EvaluateMetrics, SafetyFactorsAreAllowableOverStress) {
  const Drive d = problem("ship_lift");
  MetricOptions o;
  o.allowable_bending_pinion = 500e6;
  o.allowable_bending_rack = 400e6;
  o.allowable_contact_pinion = 1500e6;
  o.allowable_contact_rack = 1400e6;
  const MetricValues v = eval(d, {"root_bending_stress", "rack_root_bending_stress", "root_bending_safety",
                                  "contact_stress", "contact_safety"}, o);
  ASSERT_TRUE(v.all_ok());
  EXPECT_DOUBLE_EQ(v.values[2].value, std::min(500e6 / v.values[0].value, 400e6 / v.values[1].value));
  EXPECT_DOUBLE_EQ(v.values[4].value, 1400e6 / v.values[3].value);
  EXPECT_NE(v.values[0].display.find("MPa"), std::string::npos);
}

// A pure function: the same answers from several threads at once.
TEST(EvaluateMetrics, ThreadSafeAndDeterministic) {
  const Drive d = problem("ship_lift");
  const std::vector<MetricRequest> r =
      requests({"min_stiffness_ks", "contact_ratio", "wear_life", "wear_life_at_R(0.9)", "contact_stress"});
  const MetricValues ref = evaluate_metrics(d, r, {});
  std::vector<MetricValues> got(2);
  std::vector<std::thread> th;
  for (int t = 0; t < 2; ++t) th.emplace_back([&, t] { got[t] = evaluate_metrics(d, r, {}); });
  for (auto& t : th) t.join();
  for (const MetricValues& g : got) {
    for (std::size_t i = 0; i < r.size(); ++i) EXPECT_EQ(g.values[i].value, ref.values[i].value) << i;
  }
}

}  // namespace
}  // namespace rackopt::metrics

namespace rackopt::metrics {
namespace {

// Every registered metric computes from the models it declares alone: asked
// for by itself (so no other metric pulls in a model it forgot to declare),
// it gives a finite value on the ship lift (which configures wear, duty,
// reliability and allowables), never a "read an undeclared model" error.
TEST(EvaluateMetrics, EveryRegisteredMetricComputesFromItsDeclaredModelsAlone) {
  Drive ship = problem("ship_lift");
  ship.load.speed = 0.2;   // drive power and pinion speed need it
  MetricOptions o;
  o.cost.rack_length = 100;  // the cost's pinion share needs it
  for (const MetricDefinition& d : metric_registry()) {
    MetricRequest q{std::string(d.name), std::nullopt};
    if (d.parameter.use == ParameterSpec::Use::kRequired) q.parameter = 0.9;
    const std::vector<MetricRequest> one{q};
    MetricValues v;
    ASSERT_NO_THROW(v = evaluate_metrics(ship, one, o)) << d.name;
    EXPECT_TRUE(v.values.at(0).ok) << d.name << ": " << v.values.at(0).message;
    EXPECT_TRUE(std::isfinite(v.values.at(0).value)) << d.name;
    EXPECT_EQ(v.models_run, d.models) << d.name;
  }
}

TEST(MetricRegistryCheck, AMetricWithoutComputationFailsAtStartUp) {
  std::vector<MetricDefinition> r = metric_registry();
  EXPECT_NO_THROW(check_registry(r));
  r.back().compute = nullptr;
  try {
    check_registry(r);
    ADD_FAILURE() << "no logic_error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find(std::string(r.back().name)), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no computation"), std::string::npos) << e.what();
  }
  r = metric_registry();
  r.push_back(r.front());
  EXPECT_THROW(check_registry(r), std::logic_error);
}

}  // namespace
}  // namespace rackopt::metrics

namespace rackopt::metrics {
namespace {

// A design whose geometry is impossible (40 mm of clearance leaves the ship
// lift a contact ratio below 1) fails its wear metric with the geometry as
// the cause, not the wear model.
TEST(EvaluateMetrics, AnImpossibleGeometryIsTheCauseNotTheWearMetric) {
  Drive ship = problem("ship_lift");
  ship.mounting.clearance = 0.040;
  const MetricValues v = eval(ship, {"wear_life_at_R(0.9)", "min_stiffness", "supports_per_metre"});
  ASSERT_FALSE(v.values[0].ok);
  EXPECT_EQ(v.values[0].error_code, "contact_ratio_below_one");
  EXPECT_EQ(v.values[0].cause, "geometry");
  EXPECT_EQ(v.values[1].cause, "geometry");
  EXPECT_TRUE(v.values[2].ok);
  EXPECT_EQ(v.values[2].cause, "");
}

}  // namespace
}  // namespace rackopt::metrics

namespace rackopt::metrics {
namespace {

// Failed samples of the life at R (docs/models/reliability.md, "Failed
// samples"). A hardness of cv 0.5 reaches below 0 at the R = 0.99 quantile:
// the metric is the life conditional on a positive hardness (it threw an
// InputError out of evaluate_metrics). A scatter with no valid sample at all
// is a failed metric with its code (an infeasible design), not an exception.
TEST(EvaluateMetrics, WearLifeAtRWithFailedSamplesIsAValueOrAFailureNeverAnException) {
  Drive d = problem("ship_lift");
  d.wear.update_profile = false;
  RandomInput h;
  h.key = "surface_hardness";
  h.distribution = RandomInput::Distribution::kNormal;
  h.cv = 0.5;
  d.reliability.inputs = {h};
  MetricValues v;
  ASSERT_NO_THROW(v = eval(d, {"wear_life_at_R(0.99)", "wear_life_at_R(0.9)"}));
  ASSERT_TRUE(v.all_ok()) << v.first_failure()->message;
  EXPECT_GT(v.values[0].value, 0.0);
  EXPECT_LT(v.values[0].value, v.values[1].value);
  MetricOptions mc;
  mc.exact_quantile = false;
  mc.reliability_samples = 200;
  ASSERT_NO_THROW(v = eval(d, {"wear_life_at_R(0.99)"}, mc));
  ASSERT_TRUE(v.all_ok()) << v.first_failure()->message;
  EXPECT_TRUE(std::isfinite(v.values[0].value));

  h.absolute = true;
  h.a = -1e9;  // every sampled hardness negative (the loader refuses this; code can build it)
  h.b = 1e6;
  d.reliability.inputs = {h};
  for (bool exact : {true, false}) {
    MetricOptions o;
    o.exact_quantile = exact;
    o.reliability_samples = 20;
    ASSERT_NO_THROW(v = eval(d, {"wear_life_at_R(0.9)"}, o)) << exact;
    ASSERT_FALSE(v.values[0].ok) << exact;
    EXPECT_EQ(v.values[0].error_code, "no_valid_reliability_sample") << exact;
    EXPECT_NE(v.values[0].message.find("no life at reliability R"), std::string::npos) << v.values[0].message;
  }
}

}  // namespace
}  // namespace rackopt::metrics
