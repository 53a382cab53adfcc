#include "rackopt/study/sweep_sensitivity.hpp"
#include "rackopt/study/study_result.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rackopt/doe/samplers.hpp"

namespace rackopt::study {
namespace {

constexpr double kPi = std::numbers::pi;

using Model = std::function<double(const std::vector<double>&)>;

DesignVariable variable(const std::string& key, double lower, double upper, std::optional<int> levels = std::nullopt) {
  DesignVariable v;
  v.key = key;
  v.lower = lower;
  v.upper = upper;
  v.levels = levels;
  return v;
}

DesignVariable discrete_variable(const std::string& key, std::vector<double> values) {
  DesignVariable v;
  v.key = key;
  v.values = values;
  v.lower = values.front();
  v.upper = values.back();
  return v;
}

StudySpec sweep_spec(SweepSpec::Method method, std::vector<DesignVariable> vars, int levels = 5) {
  StudySpec s;
  s.name = "sensitivity test";
  s.kind = StudyKind::kSweep;
  s.variables = std::move(vars);
  s.sweep.method = method;
  s.sweep.levels = levels;
  return s;
}

// The points the runner builds for a grid sweep of `spec`.
std::vector<std::vector<double>> grid_of(const StudySpec& spec) {
  std::vector<std::vector<double>> levels;
  for (const auto& v : spec.variables)
    levels.push_back(v.discrete() ? v.values
                                  : doe::linspace_levels(v.lower, v.upper, v.levels.value_or(spec.sweep.levels)));
  return doe::full_grid(levels);
}

// One DesignResult per x with every model's value under its label.
std::vector<DesignResult> evaluate(const std::vector<std::vector<double>>& xs, const std::vector<std::string>& labels,
                                   const std::vector<Model>& models) {
  std::vector<DesignResult> out;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    DesignResult d;
    d.x = xs[k];
    d.label = "sweep " + std::to_string(k);
    d.metric_labels = labels;
    for (const Model& m : models) {
      d.metric_values.push_back(m(xs[k]));
      d.metric_ok.push_back(true);
    }
    d.ok = d.feasible = true;
    out.push_back(d);
  }
  return out;
}

const VariableSensitivity& find(const MetricSensitivity& m, const std::string& key) {
  for (const auto& v : m.variables)
    if (v.variable == key) return v;
  throw std::runtime_error("no variable " + key + " for " + m.metric);
}

// Variance of n equally spaced levels over [lo, hi] with equal weights.
double grid_variance(double lo, double hi, int n) {
  const double r = hi - lo;
  return r * r * (n + 1) / (12.0 * (n - 1));
}

double ishigami(const std::vector<double>& x) {
  constexpr double a = 7, b = 0.1;
  return std::sin(x[0]) + a * std::sin(x[1]) * std::sin(x[1]) + b * std::pow(x[2], 4) * std::sin(x[0]);
}

// Ishigami & Homma (1990) with a = 7, b = 0.1 on the uniform cube [-pi, pi]^3:
// V1 = (1 + b pi^4/5)^2 / 2, V2 = a^2/8, V13 = 8 b^2 pi^8 / 225, V3 = 0.
struct Indices {
  double s1, s2, s3, st1, st2, st3;
};
Indices ishigami_indices(double e_sin2_x1, double e_x3_4, double e_x3_8, double e_sin2_x2, double e_sin4_x2) {
  constexpr double a = 7, b = 0.1;
  const double v1 = e_sin2_x1 * (1 + b * e_x3_4) * (1 + b * e_x3_4);
  const double v2 = a * a * (e_sin4_x2 - e_sin2_x2 * e_sin2_x2);
  const double v13 = e_sin2_x1 * b * b * (e_x3_8 - e_x3_4 * e_x3_4);
  const double v = v1 + v2 + v13;
  return {v1 / v, v2 / v, 0.0, (v1 + v13) / v, v2 / v, v13 / v};
}
Indices ishigami_analytic() {
  return ishigami_indices(0.5, std::pow(kPi, 4) / 5, std::pow(kPi, 8) / 9, 0.5, 3.0 / 8);
}
// The same decomposition for the uniform distribution on n equally spaced
// levels of [-pi, pi] (the grid's own distribution): the moments are 1-D sums.
Indices ishigami_on_levels(int n) {
  const auto lv = doe::linspace_levels(-kPi, kPi, n);
  double s2 = 0, x4 = 0, x8 = 0, s4 = 0;
  for (double x : lv) {
    s2 += std::sin(x) * std::sin(x);
    s4 += std::pow(std::sin(x), 4);
    x4 += std::pow(x, 4);
    x8 += std::pow(x, 8);
  }
  return ishigami_indices(s2 / n, x4 / n, x8 / n, s2 / n, s4 / n);
}

TEST(SweepSensitivity, AnalyticIshigamiValues) {
  // The closed form above against the published values (Saltelli et al. 2008, the Primer).
  const Indices a = ishigami_analytic();
  EXPECT_NEAR(a.s1, 0.3139, 5e-5);
  EXPECT_NEAR(a.s2, 0.4424, 5e-5);
  EXPECT_NEAR(a.st1, 0.5576, 5e-5);
  EXPECT_NEAR(a.st3, 0.2437, 5e-5);
}

TEST(SweepSensitivity, AdditiveFunctionOnGridIsExact) {
  // Y = 3 X1 - 2 X2: no interaction, so S_i = S_Ti = a_i^2 Var X_i / sum.
  StudySpec spec = sweep_spec(SweepSpec::Method::kGrid, {variable("x1", 0, 2, 5), variable("x2", 1, 2, 9)});
  auto pts = evaluate(grid_of(spec), {"y"}, {[](const auto& x) { return 3 * x[0] - 2 * x[1]; }});
  std::reverse(pts.begin(), pts.end());  // any order
  const auto s = sweep_sensitivity(spec, pts);
  ASSERT_EQ(s.size(), 1u);
  const auto& m = s[0];
  EXPECT_EQ(m.method, "grid ANOVA");
  EXPECT_EQ(m.points_used, 45u);
  EXPECT_EQ(m.points_left_out, 0u);
  const double v1 = 9 * grid_variance(0, 2, 5), v2 = 4 * grid_variance(1, 2, 9);
  EXPECT_NEAR(m.variance, v1 + v2, 1e-12);
  ASSERT_EQ(m.variables.size(), 2u);
  EXPECT_EQ(m.variables[0].variable, "x1");  // ranked: 9 * 0.5 > 4 * 0.1042
  EXPECT_EQ(m.variables[0].classes, 5u);
  EXPECT_NEAR(find(m, "x1").first_order, v1 / (v1 + v2), 1e-12);
  EXPECT_NEAR(find(m, "x2").first_order, v2 / (v1 + v2), 1e-12);
  EXPECT_NEAR(*find(m, "x1").total, v1 / (v1 + v2), 1e-12);
  EXPECT_NEAR(*find(m, "x2").total, v2 / (v1 + v2), 1e-12);
}

TEST(SweepSensitivity, IshigamiOnDenseGrid) {
  constexpr int n = 41;
  StudySpec spec = sweep_spec(SweepSpec::Method::kGrid,
                              {variable("x1", -kPi, kPi), variable("x2", -kPi, kPi), variable("x3", -kPi, kPi)}, n);
  const auto s = sweep_sensitivity(spec, evaluate(grid_of(spec), {"ishigami"}, {ishigami}));
  ASSERT_EQ(s.size(), 1u);
  const auto& m = s[0];
  ASSERT_EQ(m.method, "grid ANOVA");
  ASSERT_EQ(m.variables.size(), 3u);
  // Ranked by first order: x2, x1, x3.
  EXPECT_EQ(m.variables[0].variable, "x2");
  EXPECT_EQ(m.variables[1].variable, "x1");
  EXPECT_EQ(m.variables[2].variable, "x3");
  const auto& x1 = find(m, "x1");
  const auto& x2 = find(m, "x2");
  const auto& x3 = find(m, "x3");

  // Exact for the grid's own (discrete uniform) distribution: the 3-D
  // decomposition equals the closed form built from 1-D level moments.
  const Indices g = ishigami_on_levels(n);
  EXPECT_NEAR(x1.first_order, g.s1, 1e-12);
  EXPECT_NEAR(x2.first_order, g.s2, 1e-12);
  EXPECT_NEAR(x3.first_order, g.s3, 1e-12);
  EXPECT_NEAR(*x1.total, g.st1, 1e-12);
  EXPECT_NEAR(*x2.total, g.st2, 1e-12);
  EXPECT_NEAR(*x3.total, g.st3, 1e-12);

  // Against the continuous indices: equal weights on levels that include both
  // ends are a first-order quadrature, each level moment is off by about
  // (f(end) - mean f) / n; for x3^8 the end value is 9 times the mean, which
  // makes the indices' error about 1.1/n (0.027 here). 1.5/n = 0.037 bounds it.
  const Indices a = ishigami_analytic();
  const double tol = 1.5 / n;
  EXPECT_NEAR(x1.first_order, a.s1, tol);
  EXPECT_NEAR(x2.first_order, a.s2, tol);
  EXPECT_NEAR(x3.first_order, a.s3, tol);
  EXPECT_NEAR(*x1.total, a.st1, tol);
  EXPECT_NEAR(*x2.total, a.st2, tol);
  EXPECT_NEAR(*x3.total, a.st3, tol);
  // And the error is first order in the level spacing: n times it is nearly
  // the same on a grid half as fine (n = 21) and one twice as fine (n = 81).
  const Indices coarse = ishigami_on_levels(21), fine = ishigami_on_levels(81);
  const double e41 = n * std::abs(x2.first_order - a.s2);
  EXPECT_NEAR(21 * std::abs(coarse.s2 - a.s2), e41, 0.15 * e41);
  EXPECT_NEAR(81 * std::abs(fine.s2 - a.s2), e41, 0.15 * e41);
}

void expect_ishigami_binned(const std::vector<std::vector<double>>& xs, SweepSpec::Method method, double tol) {
  StudySpec spec = sweep_spec(method, {variable("x1", -kPi, kPi), variable("x2", -kPi, kPi), variable("x3", -kPi, kPi)});
  const auto s = sweep_sensitivity(spec, evaluate(xs, {"ishigami"}, {ishigami}));
  ASSERT_EQ(s.size(), 1u);
  const auto& m = s[0];
  EXPECT_EQ(m.method, "given-data binning");
  EXPECT_EQ(m.points_used, xs.size());
  const Indices a = ishigami_analytic();
  EXPECT_NEAR(find(m, "x1").first_order, a.s1, tol);
  EXPECT_NEAR(find(m, "x2").first_order, a.s2, tol);
  EXPECT_NEAR(find(m, "x3").first_order, a.s3, tol);
  for (const auto& v : m.variables) {
    EXPECT_FALSE(v.total.has_value()) << v.variable;
    EXPECT_EQ(v.classes, 64u) << v.variable;  // sqrt(4096) equal-count bins
  }
  EXPECT_NE(m.note.find("Total indices need a complete grid"), std::string::npos);
  EXPECT_EQ(m.variables[0].variable, "x2");
  EXPECT_EQ(m.variables[1].variable, "x1");
}

TEST(SweepSensitivity, IshigamiFromSobolSample) {
  const std::vector<double> lo(3, -kPi), hi(3, kPi);
  // Over 20 shifts the error's rms was below 0.002 (docs/models/sensitivity.md):
  // the net balances the other variables inside each dyadic bin.
  expect_ishigami_binned(doe::sobol_points(lo, hi, 4096, 11), SweepSpec::Method::kSobol, 0.01);
}

TEST(SweepSensitivity, IshigamiFromLatinHypercube) {
  const std::vector<double> lo(3, -kPi), hi(3, kPi);
  // Random within its strata: rms error about 0.01 over 20 seeds; 0.05 is 5 sigma.
  expect_ishigami_binned(doe::latin_hypercube(lo, hi, 4096, 5), SweepSpec::Method::kLatinHypercube, 0.05);
}

TEST(SweepSensitivity, BinningBiasCorrectionOnIrrelevantVariable) {
  // Y depends on x1 only; x2 is noise to it. The raw correlation ratio of x2
  // would be about (M-1)/N = 7/64 = 0.11 with 64 points in 8 bins; the
  // corrected one is near 0. (The LHS sample makes x1 and x2 unrelated.)
  StudySpec spec = sweep_spec(SweepSpec::Method::kLatinHypercube, {variable("x1", 0, 1), variable("x2", 0, 1)});
  const std::vector<double> lo(2, 0.0), hi(2, 1.0);
  const auto s = sweep_sensitivity(
      spec, evaluate(doe::latin_hypercube(lo, hi, 64, 3), {"y"}, {[](const auto& x) { return std::sin(6 * x[0]); }}));
  EXPECT_LT(find(s[0], "x2").first_order, 0.06);
  EXPECT_GT(find(s[0], "x1").first_order, 0.9);
  EXPECT_EQ(find(s[0], "x1").classes, 8u);
}

TEST(SweepSensitivity, InteractionOnlyFunction) {
  // Y = X1 X2 on [-1, 1]^2: E[Y|X1] = X1 E[X2] = 0, so no first-order effect,
  // and everything is interaction: S_T1 = S_T2 = 1.
  StudySpec spec = sweep_spec(SweepSpec::Method::kGrid, {variable("x1", -1, 1), variable("x2", -1, 1)}, 11);
  const auto s = sweep_sensitivity(spec, evaluate(grid_of(spec), {"y"}, {[](const auto& x) { return x[0] * x[1]; }}));
  const auto& m = s[0];
  EXPECT_EQ(m.method, "grid ANOVA");
  for (const auto& v : m.variables) {
    EXPECT_NEAR(v.first_order, 0.0, 1e-12) << v.variable;
    EXPECT_NEAR(*v.total, 1.0, 1e-12) << v.variable;
  }

  // On [0, 1]^2 (levels 0, 0.5, 1): Var(X) = 1/6, E[X] = 1/2, E[X^2] = 5/12:
  // V1 = Var(X1) E[X2]^2 = 1/24, Var(Y) = (5/12)^2 - 1/16 = 16/144,
  // S1 = 3/8, S_T1 = 1 - S2 = 5/8.
  StudySpec spec01 = sweep_spec(SweepSpec::Method::kGrid, {variable("x1", 0, 1), variable("x2", 0, 1)}, 3);
  const auto s01 =
      sweep_sensitivity(spec01, evaluate(grid_of(spec01), {"y"}, {[](const auto& x) { return x[0] * x[1]; }}));
  EXPECT_NEAR(find(s01[0], "x1").first_order, 3.0 / 8, 1e-12);
  EXPECT_NEAR(*find(s01[0], "x1").total, 5.0 / 8, 1e-12);
}

TEST(SweepSensitivity, ConstantMetricHasNoRanking) {
  StudySpec spec = sweep_spec(SweepSpec::Method::kGrid, {variable("x1", 0, 1), variable("x2", 0, 1)}, 4);
  const auto s = sweep_sensitivity(spec, evaluate(grid_of(spec), {"flat", "y"},
                                                  {[](const auto&) { return 0.1 + 0.2; },
                                                   [](const auto& x) { return x[0]; }}));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].metric, "flat");
  EXPECT_EQ(s[0].method, "none");
  EXPECT_TRUE(s[0].variables.empty());
  EXPECT_EQ(s[0].variance, 0.0);
  EXPECT_NE(s[0].note.find("Constant"), std::string::npos);
  EXPECT_EQ(s[0].points_used, 16u);
  // The other metric still ranks: x1 all, x2 nothing.
  EXPECT_EQ(s[1].method, "grid ANOVA");
  EXPECT_NEAR(find(s[1], "x1").first_order, 1.0, 1e-12);
  EXPECT_NEAR(find(s[1], "x2").first_order, 0.0, 1e-12);
  EXPECT_NEAR(*find(s[1], "x2").total, 0.0, 1e-12);
}

TEST(SweepSensitivity, FailedPointsAreLeftOutAndBreakTheGrid) {
  StudySpec spec = sweep_spec(SweepSpec::Method::kGrid, {variable("x1", 0, 1), variable("x2", 0, 1)}, 9);
  auto pts = evaluate(grid_of(spec), {"y", "z"},
                      {[](const auto& x) { return 2 * x[0] + x[1]; }, [](const auto& x) { return 2 * x[0] + x[1]; }});
  // "y" fails at 3 points (one of them reported ok but not finite); "z" is complete.
  pts[5].metric_ok[0] = false;
  pts[40].metric_ok[0] = false;
  pts[77].metric_values[0] = std::nan("");
  const auto s = sweep_sensitivity(spec, pts);
  ASSERT_EQ(s.size(), 2u);
  const auto& y = s[0];
  EXPECT_EQ(y.points_used, 78u);
  EXPECT_EQ(y.points_left_out, 3u);
  EXPECT_EQ(y.method, "given-data binning");
  EXPECT_NE(y.note.find("3 of 81 points left out"), std::string::npos);
  EXPECT_NE(y.note.find("incomplete"), std::string::npos);
  // Classes are the 9 grid levels; the estimate stays close to the complete
  // grid's S1 = 4/5, S2 = 1/5 (3 of 81 points missing, no chance correction:
  // the grid keeps the other variable balanced inside each level).
  for (const auto& v : y.variables) {
    EXPECT_EQ(v.classes, 9u);
    EXPECT_FALSE(v.total.has_value());
    EXPECT_TRUE(std::isfinite(v.first_order));
  }
  EXPECT_NEAR(find(y, "x1").first_order, 0.8, 0.03);
  EXPECT_NEAR(find(y, "x2").first_order, 0.2, 0.03);
  const auto& z = s[1];
  EXPECT_EQ(z.method, "grid ANOVA");
  EXPECT_EQ(z.points_left_out, 0u);
  EXPECT_NEAR(find(z, "x1").first_order, 0.8, 1e-12);
}

TEST(SweepSensitivity, TooFewPointsAndNoPoints) {
  StudySpec spec = sweep_spec(SweepSpec::Method::kSobol, {variable("x1", 0, 1)});
  EXPECT_TRUE(sweep_sensitivity(spec, {}).empty());
  auto pts = evaluate({{0.1}, {0.6}}, {"y"}, {[](const auto& x) { return x[0]; }});
  pts[1].metric_ok[0] = false;
  const auto s = sweep_sensitivity(spec, pts);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].method, "none");
  EXPECT_EQ(s[0].variance, 0.0);
  EXPECT_TRUE(s[0].variables.empty());
  EXPECT_NE(s[0].note.find("Fewer than 2"), std::string::npos);
}

TEST(SweepSensitivity, SingleValueVariableIsSkipped) {
  // x2 has one grid level (the centre): it cannot drive anything.
  StudySpec spec = sweep_spec(SweepSpec::Method::kGrid, {variable("x1", 0, 1, 6), variable("x2", 0, 1, 1)});
  const auto s = sweep_sensitivity(spec, evaluate(grid_of(spec), {"y"}, {[](const auto& x) { return x[0] * x[1]; }}));
  EXPECT_EQ(s[0].method, "grid ANOVA");
  ASSERT_EQ(s[0].variables.size(), 1u);
  EXPECT_EQ(s[0].variables[0].variable, "x1");
  EXPECT_NEAR(s[0].variables[0].first_order, 1.0, 1e-12);
  EXPECT_NE(s[0].note.find("Not varied: x2"), std::string::npos);
}

TEST(SweepSensitivity, DiscreteVariableInSobolSampleUsesItsValues) {
  // x1 discrete {1, 2, 4} (snapped like the runner does), x2 continuous.
  // Y = x1 + x2 with x2 uniform on [0, 3]: Var x2 = 3/4.
  StudySpec spec = sweep_spec(SweepSpec::Method::kSobol, {discrete_variable("x1", {1, 2, 4}), variable("x2", 0, 3)});
  const std::vector<double> lo{1, 0}, hi{4, 3};
  auto xs = doe::sobol_points(lo, hi, 1024, 2);
  std::vector<std::size_t> count(3, 0);
  for (auto& x : xs) {
    const double snapped = x[0] < 1.5 ? 1 : (x[0] <= 3 ? 2 : 4);
    count[snapped == 1 ? 0 : snapped == 2 ? 1 : 2]++;
    x[0] = snapped;
  }
  const auto s = sweep_sensitivity(spec, evaluate(xs, {"y"}, {[](const auto& x) { return x[0] + x[1]; }}));
  const auto& m = s[0];
  EXPECT_EQ(find(m, "x1").classes, 3u);
  // The sample's own distribution of x1 (weights 1/6, 1/2, 1/3 from snapping).
  const double n = 1024;
  const double p1 = count[0] / n, p2 = count[1] / n, p4 = count[2] / n;
  const double mean1 = p1 * 1 + p2 * 2 + p4 * 4;
  const double var1 = p1 * 1 + p2 * 4 + p4 * 16 - mean1 * mean1;
  const double s1 = var1 / (var1 + 0.75);
  EXPECT_NEAR(find(m, "x1").first_order, s1, 0.02);
  EXPECT_NEAR(find(m, "x2").first_order, 1 - s1, 0.05);
}

TEST(SweepSensitivity, MarkdownAndJson) {
  StudySpec spec = sweep_spec(SweepSpec::Method::kGrid, {variable("x1", 0, 2, 5), variable("x2", 1, 2, 9)});
  auto pts = evaluate(grid_of(spec), {"y", "c|d"},
                      {[](const auto& x) { return 3 * x[0] - 2 * x[1]; }, [](const auto&) { return 1.0; }});
  pts[0].metric_ok[0] = false;
  const auto s = sweep_sensitivity(spec, pts);
  const std::string md = sensitivity_markdown(s);
  EXPECT_NE(md.find("**y** (given-data binning, 44 points)"), std::string::npos) << md;
  EXPECT_NE(md.find("| variable | first order S_i | total S_Ti |"), std::string::npos) << md;
  EXPECT_NE(md.find("| x1 | 0.9"), std::string::npos) << md;
  EXPECT_NE(md.find(" | - |"), std::string::npos) << md;
  EXPECT_NE(md.find("**c\\|d** (none, 45 points)"), std::string::npos) << md;
  EXPECT_NE(md.find("Constant over the sweep"), std::string::npos) << md;

  JsonWriter w;
  w.begin_object().key("sensitivity");
  sensitivity_json(w, s);
  w.end_object();
  const std::string& j = w.str();
  EXPECT_EQ(j.rfind("{\"sensitivity\":[{\"metric\":\"y\",\"method\":\"given-data binning\",\"points_used\":44,"
                    "\"points_left_out\":1,",
                    0),
            0u)
      << j;
  EXPECT_NE(j.find("\"variable\":\"x1\""), std::string::npos) << j;
  EXPECT_NE(j.find("\"total\":null"), std::string::npos) << j;
  EXPECT_NE(j.find("\"metric\":\"c|d\",\"method\":\"none\""), std::string::npos) << j;
  EXPECT_NE(j.find("\"variables\":[]"), std::string::npos) << j;
  EXPECT_EQ(j.find("nan"), std::string::npos) << j;
}

TEST(SweepSensitivity, CoordinateCountMismatchThrows) {
  StudySpec spec = sweep_spec(SweepSpec::Method::kGrid, {variable("x1", 0, 1), variable("x2", 0, 1)});
  auto pts = evaluate({{0.0, 1.0}, {1.0}}, {"y"}, {[](const auto& x) { return x[0]; }});
  EXPECT_THROW(sweep_sensitivity(spec, pts), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt::study
