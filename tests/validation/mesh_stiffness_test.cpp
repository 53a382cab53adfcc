// Properties of the assembled mesh stiffness curve:
// positive and finite everywhere, continuous inside a zone and jumping only at
// zone transitions / support crossings, min/max/mean independent of where the
// uniform samples fall, load shares summing to one, and the coupled beam
// giving the right limits.
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/pair_coupling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "rackopt/stiffness/rack_span.hpp"
#include "rackopt/stiffness/supported_rack.hpp"

#include "test_drives.hpp"

namespace rackopt {
namespace {

TEST(MeshStiffnessCurve, PositiveFiniteAndLoadSharesSumToOne) {
  for (const char* file : {"rack_railway.yaml", "rack_railway_paper.yaml", "ship_lift.yaml", "large_module.yaml"}) {
    SCOPED_TRACE(file);
    const MeshStiffnessModel model(test::problem(file));
    const StiffnessCurve c = model.curve();
    ASSERT_GT(c.samples.size(), 100u);
    for (const MeshState& s : c.samples) {
      ASSERT_TRUE(std::isfinite(s.stiffness)) << "X = " << s.travel;
      ASSERT_GT(s.stiffness, 0.0) << "X = " << s.travel;
      ASSERT_GE(s.pairs.size(), 1u);
      double share = 0;
      for (const PairState& p : s.pairs) {
        EXPECT_GT(p.local(), 0.0);
        share += p.load_share;
      }
      EXPECT_NEAR(share, 1.0, 1e-12) << "X = " << s.travel;
    }
    EXPECT_LE(c.k_min, c.k_mean);
    EXPECT_GE(c.k_max, c.k_mean);
  }
}

// The rigid-body mesh is periodic in travel with the rack pitch, and the
// number of pairs alternates between floor(eps) and floor(eps)+1 exactly at
// the zone lengths reported by the geometry.
TEST(MeshStiffnessCurve, RigidBodyZonesMatchGeometry) {
  Drive d = test::problem("rack_railway.yaml");
  d.effects.rack_span = RackSpanModel::kRigid;
  const MeshStiffnessModel model(d);
  const StiffnessCurve c = model.curve();
  const double p = M_PI * d.pinion.module;
  // Travel spent with n pairs over whole periods, from the samples.
  std::map<int, double> length;
  for (std::size_t i = 0; i + 1 < c.samples.size(); ++i) {
    const double dx = c.samples[i + 1].travel - c.samples[i].travel;
    if (dx <= 0) continue;
    length[static_cast<int>(c.samples[i].pairs.size())] += dx;
  }
  const double periods = d.rack.span / p;
  for (const Zone& z : model.geometry().zones) {
    EXPECT_NEAR(length[z.pairs] / periods, z.length_travel, 1e-6 * p) << z.pairs << " pairs";
  }
}

// Within a smooth piece neighbouring samples differ by no more than the local
// slope allows; across a breakpoint the curve may jump. The slope bound is
// taken from the steepest change seen between uniform samples, times 3.
TEST(MeshStiffnessCurve, ContinuousInsideZonesJumpsOnlyAtBreakpoints) {
  const MeshStiffnessModel model(test::problem("rack_railway.yaml"));
  const StiffnessCurve c = model.curve();
  const double p = M_PI * model.drive().pinion.module;
  const double h = p / model.drive().numerics.positions_per_period;
  double max_jump_at_break = 0;
  double max_step_inside = 0;
  for (std::size_t i = 0; i + 1 < c.samples.size(); ++i) {
    const double dx = c.samples[i + 1].travel - c.samples[i].travel;
    const double dk = std::abs(c.samples[i + 1].stiffness - c.samples[i].stiffness);
    if (dx == 0) {
      max_jump_at_break = std::max(max_jump_at_break, dk);
      // Two samples at one travel value must be a listed breakpoint.
      EXPECT_TRUE(std::any_of(c.breakpoints.begin(), c.breakpoints.end(),
                              [&](double b) { return std::abs(b - c.samples[i].travel) < 1e-9; }));
    } else {
      ASSERT_LE(dx, h * (1 + 1e-9));
      max_step_inside = std::max(max_step_inside, dk / dx * h);
    }
  }
  // Pairs entering or leaving change the stiffness by far more than one
  // uniform step inside a zone does.
  EXPECT_GT(max_jump_at_break, 5 * max_step_inside);
  // A fine resampling inside one piece never jumps: check the first piece.
  const double x0 = c.breakpoints.at(1), x1 = c.breakpoints.at(2);
  double prev = model.stiffness(x0, +1);
  const int n = 400;
  for (int i = 1; i < n; ++i) {
    const double x = x0 + (x1 - x0) * i / n;
    const double k = model.stiffness(x);
    EXPECT_LT(std::abs(k - prev), 2 * max_step_inside * (x1 - x0) / n / h + 1e-9 * k) << "x = " << x;
    prev = k;
  }
}

// min, max and mean must not depend on where the uniform samples fall.
TEST(MeshStiffnessCurve, ExtremaAndMeanIndependentOfSampling) {
  for (const char* file : {"rack_railway.yaml", "ship_lift.yaml"}) {
    SCOPED_TRACE(file);
    Drive d = test::problem(file);
    std::vector<StiffnessCurve> curves;
    for (int n : {37, 100, 163}) {
      d.numerics.positions_per_period = n;
      curves.push_back(MeshStiffnessModel(d).curve());
    }
    for (const StiffnessCurve& c : curves) {
      EXPECT_NEAR(c.k_min / curves[1].k_min, 1.0, 1e-7);
      EXPECT_NEAR(c.k_max / curves[1].k_max, 1.0, 1e-7);
      EXPECT_NEAR(c.k_mean / curves[1].k_mean, 1.0, 2e-6);
    }
  }
}

// Right after a second pair enters, the stiffness of this rack railway
// design rises for about 1.3 mm of travel (a tenth of a sample step at 8 to
// 32 positions per period) and then falls: the largest sample is the piece's
// first limit, with no sampled local maximum around the peak. The extremes
// must still be the curve's own, found by refinement, at any sampling.
TEST(MeshStiffnessCurve, ExtremeInsideTheFirstStepOfAPieceIsFoundAtAnySampling) {
  const std::vector<std::string> design = {"pinion.pressure_angle=0.39481062 rad", "pinion.module=36 mm",
                                           "rack.span=2.26544833 m", "mounting.clearance=0.174840144 mm"};
  const MeshStiffnessModel model(test::problem("rack_railway.yaml", design));
  const StiffnessCurve fine = model.curve(CurveDetail::kSummary, 800);
  for (int n : {8, 16, 24, 32, 37, 100}) {
    SCOPED_TRACE(n);
    const StiffnessCurve c = model.curve(CurveDetail::kSummary, n);
    EXPECT_NEAR(c.k_max / fine.k_max, 1.0, 1e-12);
    EXPECT_NEAR(c.k_min / fine.k_min, 1.0, 1e-12);
    // The peak is not at a sample of the coarse curve.
    EXPECT_NEAR(c.travel_at_max, fine.travel_at_max, 1e-6);
  }
  // ... and it does lie strictly inside, after a breakpoint.
  const auto after = std::upper_bound(fine.breakpoints.begin(), fine.breakpoints.end(), fine.travel_at_max);
  ASSERT_NE(after, fine.breakpoints.begin());
  EXPECT_GT(fine.travel_at_max - *std::prev(after), 1e-4);
  EXPECT_GT(fine.k_max, model.stiffness(*std::prev(after), +1) * (1 + 1e-4));
}

// A metric's coarser sampling (positions_per_period of curve()) outside the
// problem key's range is refused; 0 keeps the drive's own.
TEST(MeshStiffnessCurve, SamplingOverrideRangeAndDefault) {
  const MeshStiffnessModel model(test::problem("ship_lift.yaml"));
  EXPECT_THROW(model.curve(CurveDetail::kSummary, 3), std::invalid_argument);
  EXPECT_THROW(model.curve(CurveDetail::kSummary, 10001), std::invalid_argument);
  EXPECT_THROW(model.curve(CurveDetail::kSummary, -1), std::invalid_argument);
  const StiffnessCurve own = model.curve(CurveDetail::kSummary);
  const StiffnessCurve same = model.curve(CurveDetail::kSummary, model.drive().numerics.positions_per_period);
  ASSERT_EQ(own.samples.size(), same.samples.size());
  EXPECT_EQ(own.k_mean, same.k_mean);
  EXPECT_LT(model.curve(CurveDetail::kSummary, 24).samples.size(), own.samples.size());
}

// With a rigid rack body the mean over one mesh period does not depend on the
// phase of the teeth relative to the supports (the curve is periodic).
TEST(MeshStiffnessCurve, RigidMeanIndependentOfPhase) {
  Drive d = test::problem("rack_railway.yaml");
  d.effects.rack_span = RackSpanModel::kRigid;
  const double p = M_PI * d.pinion.module;
  d.rack.span = 3 * p;  // three whole periods
  std::vector<double> means;
  for (double phase : {0.5, 0.13, 0.77}) {
    d.rack.tooth_offset = phase * p;
    means.push_back(MeshStiffnessModel(d).curve().k_mean);
  }
  EXPECT_NEAR(means[1] / means[0], 1.0, 1e-7);
  EXPECT_NEAR(means[2] / means[0], 1.0, 1e-7);
}

// Rack body on: the coupled stiffness is below the rigid-body one everywhere,
// the seed-000 per-pair model is stiffer than the coupled one when two or more
// pairs share the beam (it counts the body once per pair), and with one pair
// both agree (on the same beam and foundation: the supported rack's
// corrections are the coupled model's only).
TEST(MeshStiffnessCurve, CoupledBodyVersusPerPairAndRigid) {
  Drive d = test::problem("rack_railway.yaml");
  d.effects.supported_rack = false;
  const MeshStiffnessModel coupled(d);
  d.effects.rack_span = RackSpanModel::kPerPair;
  const MeshStiffnessModel per_pair(d);
  for (double x : {0.3, 0.71, 1.2, 1.93}) {
    const MeshState a = coupled.at(x);
    const MeshState b = per_pair.at(x);
    EXPECT_LT(a.stiffness, a.local_stiffness);
    ASSERT_EQ(a.pairs.size(), b.pairs.size());
    if (a.pairs.size() == 1) {
      EXPECT_NEAR(a.stiffness / b.stiffness, 1.0, 1e-12);
    } else {
      EXPECT_GT(b.stiffness, a.stiffness);
    }
  }
}

// Coupled solve against a direct inverse of C = diag(local + body) + C_b built
// here from the reported contact positions and the beam model itself, on the
// pairs that carry load; the open pairs (share 0) must really open: the
// approach there is smaller than the body carries the contact away.
TEST(MeshStiffnessCurve, CoupledSolveMatchesDirectInverse) {
  const Drive d = test::problem("rack_railway.yaml");
  const MeshStiffnessModel model(d);
  const RackSpanCompliance beam(rack_beam(d), d.pinion.pressure_angle, d.effects);
  int open_pairs_seen = 0;
  for (double x : {0.05, 0.4, 1.111, 1.6, 2.3}) {
    SCOPED_TRACE(x);
    const MeshState s = model.at(x);
    std::vector<const PairState*> act, open;
    for (const PairState& p : s.pairs) (p.load_share > 0 ? act : open).push_back(&p);
    const std::size_t n = act.size();
    ASSERT_GE(n, 1u);
    // The beam's influence, and between adjacent pairs their own coupling.
    auto infl = [&](const PairState& a, const PairState& b) {
      double c = a.segment == b.segment ? beam.influence(a.a, a.e, b.a, b.e) : 0.0;
      if (std::abs(a.rack_tooth - b.rack_tooth) == 1) {
        c += adjacent_pair_coupling(a.fillet + a.rack_foundation, b.fillet + b.rack_foundation,
                                    d.pinion.pressure_angle);
      }
      return c;
    };
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t k = 0; k < n; ++k) C(j, k) = infl(*act[j], *act[k]);
      C(j, j) += act[j]->local();
    }
    const Eigen::MatrixXd Cinv = C.inverse();
    EXPECT_NEAR(Cinv.sum() / s.stiffness, 1.0, 1e-10);
    for (std::size_t j = 0; j < n; ++j) {
      EXPECT_NEAR(Cinv.row(j).sum() / Cinv.sum(), act[j]->load_share, 1e-10);
    }
    // Approach delta = 1/K per unit force; an open pair's contact moves away
    // by at least that much under the loads of the others.
    for (const PairState* o : open) {
      ++open_pairs_seen;
      double moved = 0;
      for (const PairState* a : act) moved += infl(*o, *a) * a->load_share;
      EXPECT_GE(moved, 1.0 / s.stiffness * (1 - 1e-9));
    }
  }
  RecordProperty("open_pairs_seen", open_pairs_seen);
}

}  // namespace
}  // namespace rackopt
