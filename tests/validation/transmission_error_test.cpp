// Mesh ripple and static transmission error on the bundled problems: closed
// forms without relief (delta = F/K), the rigid body's periodic curve, an
// independent dense sampling of one period, two-spring hand values with tip
// relief, and the ordering and monotonicity of relief effects
// (docs/models/transmission_error.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_ripple.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/period_stats.hpp"
#include "rackopt/stiffness/transmission_error.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/studyfile/study_loader.hpp"

#include "test_drives.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt {
namespace {

// The papers' tooth model (constant contact term, clamped rack tooth,
// Sainsot's foundation as published, pairs in parallel), which the relief figures below were
// worked out on. With the FE-grade terms the relief's load switches are not
// yet sampling-independent to these tolerances (the transmission error's
// period mean moves by 5e-6, and with the load-dependent contact term the
// curve's mean by 2e-4: its tangent stiffness is taken on the secant contact
// terms), an open item of the FE-grade model.
const std::vector<std::string> kPaperToothModel = {"effects.hertz=linear", "effects.rack_foundation=off",
                                                   "effects.fillet_calibration=off", "effects.pair_coupling=off"};

Drive railway(RackSpanModel body) {
  Drive d = test::problem("rack_railway.yaml", kPaperToothModel);
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

// An independent look at one period of the coupled mesh: 20001 evaluations
// of the model across the period plus both limits at every discontinuity
// inside it; the ripple from those agrees with the refined period extremes.
TEST(MeshRipple, OnePeriodAgreesWithDenseEvaluation) {
  const Drive d = railway(RackSpanModel::kCoupled);
  const MeshStiffnessModel model(d);
  const StiffnessCurve c = model.curve();
  const std::vector<PeriodStats> periods = period_stats(model, c, CurveQuantity::kStiffness);
  const MeshRipple r = mesh_ripple(periods);
  for (std::size_t k : {std::size_t{0}, std::size_t{7}, std::size_t{12}}) {
    const PeriodStats& w = periods.at(k);
    double k_min = 1e300, k_max = 0, sum = 0;
    const int N = 20000;
    for (int i = 0; i <= N; ++i) {
      const double X = w.start + (w.end - w.start) * i / N;
      const double K = model.stiffness(X, i == N ? -1 : +1);
      k_min = std::min(k_min, K);
      k_max = std::max(k_max, K);
      sum += (i == 0 || i == N) ? 0.5 * K : K;
    }
    for (double xb : model.breakpoints(w.start, w.end)) {
      for (int side : {-1, +1}) {
        if ((xb <= w.start && side < 0) || (xb >= w.end && side > 0)) continue;
        const double K = model.stiffness(xb, side);
        k_min = std::min(k_min, K);
        k_max = std::max(k_max, K);
      }
    }
    const double mean = sum / N;  // trapezoid: jumps cost O(h), fine at 2e4 points
    const double dense = (k_max - k_min) / mean;
    SCOPED_TRACE(k);
    EXPECT_NEAR(w.min, k_min, 1e-6 * k_min);  // dense sampling can only miss an extreme by O(h^2)
    EXPECT_NEAR(w.max, k_max, 1e-6 * k_max);
    EXPECT_LE(w.min, k_min * (1 + 1e-12));  // rounding of the two evaluations
    EXPECT_GE(w.max, k_max * (1 - 1e-12));
    EXPECT_NEAR(w.mean, mean, 1e-4 * mean);
    EXPECT_NEAR(r.ripple.at(k), dense, 1e-4 * dense);
  }
}

// --- profile relief --------------------------------------------------------

// Pinion tip relief as the test computes it, independently of ReliefOnPath.
double tip_relief_at(const ProfileRelief& rel, double s_end, double s) {
  const double u = s - (s_end - rel.length);
  if (u <= 0) return 0.0;
  const double t = std::min(u / rel.length, 1.0);
  return rel.amount * (rel.shape == ProfileRelief::Shape::kLinear ? t : t * t);
}

// Rigid body, two pairs, the one near the pinion tip relieved by e: two
// springs c1 (unrelieved) and c2 in parallel with a gap e on c2:
//   e >= F c1: delta = F c1, f2 = 0, K = 1/c1;
//   else       delta = (F + e/c2)/(1/c1 + 1/c2), f2 = (delta - e)/c2, K = 1/c1 + 1/c2.
TEST(ProfileRelief, TwoSpringHandValuesWithLinearTipRelief) {
  for (ProfileRelief::Shape shape : {ProfileRelief::Shape::kLinear, ProfileRelief::Shape::kParabolic}) {
    Drive d = railway(RackSpanModel::kRigid);
    d.pinion.tip_relief = {60e-6, 0.8 * d.pinion.module, shape};
    const MeshStiffnessModel model(d);
    const StiffnessCurve c = model.curve();
    const double F = d.load.force;
    const double s_end = model.geometry().path.s_end;
    int loaded = 0, open = 0;
    for (const MeshState& st : c.samples) {
      if (st.pairs.size() != 2) continue;
      const bool first_at_tip = st.pairs[0].s > st.pairs[1].s;
      const PairState& p1 = st.pairs[first_at_tip ? 1 : 0];  // p2: the pair nearer the pinion tip
      const PairState& p2 = st.pairs[first_at_tip ? 0 : 1];
      const double e = tip_relief_at(d.pinion.tip_relief, s_end, p2.s);
      ASSERT_NEAR(p2.relief, e, 1e-15);
      ASSERT_EQ(p1.relief, 0.0);
      if (e == 0) continue;
      const double c1 = p1.local(), c2 = p2.local();
      double delta = 0, f2 = 0, K = 0;
      if (e >= F * c1) {
        delta = F * c1;
        K = 1 / c1;
        ++open;
      } else {
        delta = (F + e / c2) / (1 / c1 + 1 / c2);
        f2 = (delta - e) / c2;
        K = 1 / c1 + 1 / c2;
        ++loaded;
      }
      ASSERT_NEAR(st.approach, delta, 1e-12 * delta) << "X = " << st.travel;
      ASSERT_NEAR(p2.load_share, f2 / F, 1e-11);
      ASSERT_NEAR(st.stiffness, K, 1e-12 * K);
    }
    EXPECT_GT(loaded, 10);
    EXPECT_GT(open, 3);  // near the zone end the relief (up to 60 um) exceeds F c1 (about 45 um)
  }
}

// A relief far larger than the double-contact deflection: inside the
// relieved zone (past its first few micrometres) the pair never carries load
// and the transmission error is the single pair's, F c1 (hand value).
TEST(ProfileRelief, LargeReliefKeepsThePairOutAndGivesTheSinglePairValue) {
  Drive d = railway(RackSpanModel::kRigid);
  d.pinion.tip_relief = {1e-3, 0.5 * d.pinion.module, ProfileRelief::Shape::kLinear};
  const MeshStiffnessModel model(d);
  const StiffnessCurve c = model.curve();
  const double F = d.load.force;
  int checked = 0;
  for (const MeshState& st : c.samples) {
    if (st.pairs.size() != 2) continue;
    const bool first_at_tip = st.pairs[0].s > st.pairs[1].s;
    const PairState& p1 = st.pairs[first_at_tip ? 1 : 0];
    const PairState& p2 = st.pairs[first_at_tip ? 0 : 1];
    if (p2.relief <= F * p1.local()) continue;
    ++checked;
    EXPECT_EQ(p2.load_share, 0.0);
    EXPECT_NEAR(st.approach, F * p1.local(), 1e-12 * st.approach);
    EXPECT_NEAR(st.stiffness, 1 / p1.local(), 1e-12 * st.stiffness);
  }
  EXPECT_GT(checked, 20);
  // The relieved stretch is single contact: the ripple grows, the mean falls.
  const StiffnessCurve plain = MeshStiffnessModel(railway(RackSpanModel::kRigid)).curve();
  EXPECT_GT(c.k_fluctuation, plain.k_fluctuation);
  EXPECT_LT(c.k_mean, plain.k_mean);
}

// Relief only adds gaps: delta(X) grows with the amount at every position,
// a parabolic relief (less material removed than linear everywhere inside
// the zone) gives a delta no larger than the linear one, and a zero amount
// is exactly the unrelieved mesh.
TEST(ProfileRelief, OrderingAndMonotonicity) {
  for (RackSpanModel body : {RackSpanModel::kRigid, RackSpanModel::kCoupled}) {
    SCOPED_TRACE(static_cast<int>(body));
    const Drive base = railway(body);
    const StiffnessCurve plain = MeshStiffnessModel(base).curve();
    auto with = [&](double amount, ProfileRelief::Shape shape) {
      Drive d = base;
      d.pinion.tip_relief = {amount, 1.0 * d.pinion.module, shape};
      d.pinion.root_relief = {amount, 1.0 * d.pinion.module, shape};
      return MeshStiffnessModel(d);
    };
    const StiffnessCurve zero = with(0.0, ProfileRelief::Shape::kLinear).curve();
    ASSERT_EQ(zero.samples.size(), plain.samples.size());
    for (std::size_t i = 0; i < plain.samples.size(); ++i) {
      ASSERT_EQ(zero.samples[i].approach, plain.samples[i].approach);
      ASSERT_EQ(zero.samples[i].stiffness, plain.samples[i].stiffness);
    }
    std::vector<MeshStiffnessModel> linear;
    for (double a : {10e-6, 20e-6, 40e-6, 80e-6}) linear.push_back(with(a, ProfileRelief::Shape::kLinear));
    const MeshStiffnessModel parabolic = with(40e-6, ProfileRelief::Shape::kParabolic);
    int strictly_less = 0;
    // Every sample position of the unrelieved curve, each one-sided limit.
    for (std::size_t i = 0; i < plain.samples.size(); ++i) {
      const double X = plain.samples[i].travel;
      const bool left = i + 1 < plain.samples.size() && plain.samples[i + 1].travel == X;
      const int side = left ? -1 : +1;
      double prev = plain.samples[i].approach;
      for (const MeshStiffnessModel& l : linear) {
        const double delta = l.at(X, side).approach;
        ASSERT_GE(delta, prev * (1 - 1e-13)) << "X = " << X;
        prev = delta;
      }
      const double lin40 = linear[2].at(X, side).approach, par40 = parabolic.at(X, side).approach;
      ASSERT_LE(par40, lin40 * (1 + 1e-13));
      ASSERT_GE(par40, plain.samples[i].approach * (1 - 1e-13));
      if (par40 < lin40 * (1 - 1e-6)) ++strictly_less;
    }
    EXPECT_GT(strictly_less, 100);
  }
}

// Where a relieved pair starts or stops carrying load the tangent stiffness
// jumps; the curve locates those positions by bisection and treats them like
// geometric breakpoints, so extremes, mean and ripple do not depend on where
// the uniform samples fall (as without relief, docs/models/mesh.md).
TEST(ProfileRelief, LoadSwitchesAreBreakpointsSoFiguresDoNotDependOnSampling) {
  for (RackSpanModel body : {RackSpanModel::kRigid, RackSpanModel::kCoupled}) {
    SCOPED_TRACE(static_cast<int>(body));
    std::vector<Figures> f;
    std::size_t plain_breaks = 0;
    for (int n : {37, 100, 163}) {
      Drive d = railway(body);
      d.numerics.positions_per_period = n;
      plain_breaks = MeshStiffnessModel(d).breakpoints(0, d.rack.span).size();
      d.pinion.tip_relief = {60e-6, 1.72 * d.pinion.module, ProfileRelief::Shape::kLinear};
      d.pinion.root_relief = d.pinion.tip_relief;
      f.push_back(figures(d));
    }
    EXPECT_GT(f[1].curve.breakpoints.size(), plain_breaks);  // the load switches were added
    for (const Figures& g : f) {
      EXPECT_NEAR(g.curve.k_min, f[1].curve.k_min, 1e-7 * f[1].curve.k_min);
      EXPECT_NEAR(g.curve.k_max, f[1].curve.k_max, 1e-7 * f[1].curve.k_max);
      EXPECT_NEAR(g.curve.k_mean, f[1].curve.k_mean, 2e-6 * f[1].curve.k_mean);
      EXPECT_NEAR(g.ripple.max, f[1].ripple.max, 1e-5 * f[1].ripple.max);
      EXPECT_NEAR(g.ripple.mean, f[1].ripple.mean, 1e-5 * f[1].ripple.mean);
      // The deflection on the supported rack (tooth layer in the beam) moves
      // by up to 8e-6 between samplings: an extreme between samples of a
      // period is refined only where it is a sampled local extreme.
      EXPECT_NEAR(g.te.peak_to_peak, f[1].te.peak_to_peak, 2e-5 * f[1].te.peak_to_peak);
      EXPECT_NEAR(g.te.period_mean, f[1].te.period_mean, 1e-5 * f[1].te.period_mean);
    }
  }
}

// Transmission error peak-to-peak against the amount of a long relief on the
// pinion tip and root (1.72 modules each: the length of the double-contact stretch,
// (eps - 1) p_b): it falls from the unrelieved value to a minimum inside the
// range and rises again once the relieved pairs stop sharing load.
double te_for_amount(RackSpanModel body, double amount, bool period_mean) {
  Drive d = railway(body);
  d.pinion.tip_relief = {amount, 1.72 * d.pinion.module, ProfileRelief::Shape::kLinear};
  d.pinion.root_relief = d.pinion.tip_relief;
  const MeshStiffnessModel model(d);
  const TransmissionError te = transmission_error(period_stats(model, model.curve(), CurveQuantity::kApproach));
  return period_mean ? te.period_mean : te.peak_to_peak;
}

TEST(ProfileRelief, RackRailwayHasAnOptimalReliefInsideASensibleRange) {
  struct ReliefSearch {
    RackSpanModel body;
    bool period_mean;
    double hi;
  };
  for (const ReliefSearch& k :
       {ReliefSearch{RackSpanModel::kRigid, false, 100e-6}, ReliefSearch{RackSpanModel::kCoupled, true, 300e-6}}) {
    auto f = [&](double a) { return te_for_amount(k.body, a, k.period_mean); };
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = 0, b = k.hi, x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = f(x1), f2 = f(x2);
    while (b - a > 0.2e-6) {
      if (f1 < f2) {
        b = x2; x2 = x1; f2 = f1; x1 = b - g * (b - a); f1 = f(x1);
      } else {
        a = x1; x1 = x2; f1 = f2; x2 = a + g * (b - a); f2 = f(x2);
      }
    }
    const double best = 0.5 * (a + b), te_best = f(best), te_none = f(0.0), te_hi = f(k.hi);
    std::printf("rack railway, body %s, %s: no relief %.3f um, best %.3f um at %.1f um, at %.0f um %.3f um\n",
                k.body == RackSpanModel::kRigid ? "rigid" : "coupled",
                k.period_mean ? "mean period STE_pp" : "STE_pp", te_none * 1e6, te_best * 1e6, best * 1e6,
                k.hi * 1e6, te_hi * 1e6);
    EXPECT_GT(best, 10e-6);
    EXPECT_LT(best, 0.8 * k.hi);
    EXPECT_LT(te_best, te_none);
    EXPECT_LT(te_best, te_hi);
  }
}

// The shipped study varies relief amount and length on pinion tip and root
// and finds the flat STE the sweep above predicts (22.1 -> about 4 um);
// re-evaluated here from the problem file with the design's values.
TEST(ProfileRelief, ShippedStudyFlattensTheTransmissionError) {
  study::StudySpec spec =
      studyfile::load_study_file(std::string(RACKOPT_SOURCE_DIR) + "/studies/rack_railway_tip_relief.yaml");
  // As railway(): the relief on the papers' tooth model.
  spec.problem_overrides.insert(spec.problem_overrides.end(), kPaperToothModel.begin(), kPaperToothModel.end());
  study::RunOptions o;
  o.out_dir = test_support::scratch_path("te_study");
  o.threads = 1;
  const study::StudyResult r = study::run_study(spec, o);
  std::filesystem::remove_all(o.out_dir);
  ASSERT_TRUE(r.best);
  const double best = r.best->objectives.at(0);
  const ProblemTree tree = load_problem_tree_file(spec.problem_path, spec.problem_overrides);
  std::vector<std::pair<std::string, double>> values;
  for (std::size_t i = 0; i < spec.variables.size(); ++i) values.emplace_back(spec.variables[i].key, r.best->x.at(i));
  const Drive d = drive_with_values(tree, values);
  const std::vector<metrics::MetricRequest> want{metrics::parse_metric_request("transmission_error_pp")};
  EXPECT_EQ(metrics::evaluate_metrics(d, want).values.at(0).value, best);
  const double none = figures(railway(RackSpanModel::kRigid)).te.peak_to_peak;
  std::printf("study: STE %.3f um (no relief %.3f um), tip %.1f um over %.2f m, root %.1f um over %.2f m\n",
              best * 1e6, none * 1e6, d.pinion.tip_relief.amount * 1e6, d.pinion.tip_relief.length / d.pinion.module,
              d.pinion.root_relief.amount * 1e6, d.pinion.root_relief.length / d.pinion.module);
  EXPECT_LT(best, 0.25 * none);
  EXPECT_GT(d.pinion.tip_relief.amount, 10e-6);
  EXPECT_LT(d.pinion.tip_relief.amount, 90e-6);
}

}  // namespace
}  // namespace rackopt
