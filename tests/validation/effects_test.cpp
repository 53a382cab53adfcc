// "Simulate only the effects a scene calls for": switching one effect off
// changes the component it names and leaves every other component as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/pair_compliance.hpp"
#include "rackopt/stiffness/pair_coupling.hpp"
#include "rackopt/stiffness/rack_span.hpp"
#include "rackopt/stiffness/supported_rack.hpp"
#include "test_drives.hpp"

namespace rackopt {
namespace {

struct Case {
  const char* name;
  std::function<void(Effects&)> off;
  // Which per-pair components may change.
  bool pinion, fillet, hertz, rack, body;
  bool rack_foundation = false;
};

void expect_same(double a, double b, bool may_change, const char* what) {
  if (!may_change) {
    EXPECT_DOUBLE_EQ(a, b) << what;
  }
}

TEST(Effects, OffChangesOnlyItsComponent) {
  // The load-independent contact term: the Weber-Banaschek term follows the
  // pair's force, so any effect that moves the load shares moves it too.
  const Drive base = test::problem("rack_railway.yaml", {"effects.hertz=linear"});
  const std::vector<Case> cases = {
      {"fillet_foundation", [](Effects& e) { e.fillet_foundation = false; }, false, true, false, false, false},
      {"hertz", [](Effects& e) { e.hertz = HertzModel::kOff; }, false, false, true, false, false},
      // The rack foundation stands on the rack tooth: it goes with it.
      {"rack_tooth", [](Effects& e) { e.rack_tooth = false; }, false, false, false, true, false, true},
      {"pinion_tooth", [](Effects& e) { e.pinion_tooth = false; }, true, false, false, false, false},
      {"couple_term", [](Effects& e) { e.couple_term = false; }, false, false, false, false, true},
      {"body_shear", [](Effects& e) { e.body_shear = false; }, false, false, false, false, true},
      {"body_axial", [](Effects& e) { e.body_axial = false; }, false, false, false, false, true},
      // The rack foundation is local on supports (supported_rack.hpp): a
      // rigid body brings back the held-base foundation.
      {"rack_span", [](Effects& e) { e.rack_span = RackSpanModel::kRigid; }, false, false, false, false, true, true},
      {"supported_rack", [](Effects& e) { e.supported_rack = false; }, false, false, false, false, true, true},
      {"fillet_calibration", [](Effects& e) { e.fillet_calibration = false; }, false, true, false, false, false},
      {"rack_foundation", [](Effects& e) { e.rack_foundation = false; }, false, false, false, false, false, true},
  };
  const MeshStiffnessModel full(base);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Drive d = base;
    c.off(d.effects);
    const MeshStiffnessModel reduced(d);
    bool changed = false;
    for (double x : {0.07, 0.61, 1.2, 2.33}) {
      const MeshState a = full.at(x), b = reduced.at(x);
      ASSERT_EQ(a.pairs.size(), b.pairs.size());
      for (std::size_t j = 0; j < a.pairs.size(); ++j) {
        const PairState &p = a.pairs[j], &q = b.pairs[j];
        expect_same(p.pinion.total(), q.pinion.total(), c.pinion, "pinion");
        expect_same(p.fillet, q.fillet, c.fillet, "fillet");
        expect_same(p.hertz, q.hertz, c.hertz, "hertz");
        expect_same(p.rack.total(), q.rack.total(), c.rack, "rack");
        expect_same(p.body, q.body, c.body, "body");
        expect_same(p.rack_foundation, q.rack_foundation, c.rack_foundation, "rack foundation");
        changed = changed || p.pinion.total() != q.pinion.total() || p.fillet != q.fillet ||
                  p.hertz != q.hertz || p.rack.total() != q.rack.total() || p.body != q.body ||
                  p.rack_foundation != q.rack_foundation;
      }
      // Removing a compliance never makes the mesh softer; removing the
      // fillet calibration or the supported rack's corrections (stiffenings)
      // never makes it stiffer.
      if (std::string(c.name) == "fillet_calibration" || std::string(c.name) == "supported_rack") {
        EXPECT_LE(b.stiffness, a.stiffness * (1 + 1e-12));
      } else {
        EXPECT_GE(b.stiffness, a.stiffness * (1 - 1e-12));
      }
    }
    EXPECT_TRUE(changed) << "switching " << c.name << " off changed nothing";
  }
}

TEST(Effects, OffComponentsAreZero) {
  Drive d = test::problem("rack_railway.yaml");
  d.effects.fillet_foundation = false;
  d.effects.hertz = HertzModel::kOff;
  d.effects.rack_span = RackSpanModel::kRigid;
  const MeshState s = MeshStiffnessModel(d).at(0.5);
  for (const PairState& p : s.pairs) {
    EXPECT_EQ(p.fillet, 0.0);
    EXPECT_EQ(p.hertz, 0.0);
    EXPECT_EQ(p.body, 0.0);
  }
  EXPECT_DOUBLE_EQ(s.stiffness, s.local_stiffness);
}

// Weber-Banaschek contact (docs/models/tooth.md): the contact half-width grows with
// sqrt(F), so the secant compliance falls with load and the mesh stiffens;
// the load-share fixed point still sums to one.
TEST(Effects, LoadDependentHertzStiffensWithLoad) {
  Drive d = test::problem("rack_railway.yaml");
  d.effects.hertz = HertzModel::kWeberBanaschek;
  d.numerics.positions_per_period = 20;
  double prev = 0;
  for (double force : {5e3, 5e4, 5e5}) {
    d.load.force = force;
    const MeshStiffnessModel m(d);
    const StiffnessCurve c = m.curve();
    for (const MeshState& s : c.samples) {
      double share = 0;
      for (const PairState& p : s.pairs) {
        EXPECT_GT(p.hertz, 0.0);
        share += p.load_share;
      }
      EXPECT_NEAR(share, 1.0, 1e-12);
    }
    EXPECT_GT(c.k_mean, prev) << force;
    prev = c.k_mean;
  }
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// The load sharing with a load-dependent contact term is a fixed point: at
// the forces f_j = F share_j, every loaded pair's contact sees the same
// approach delta = F / K,
//   (local_j + body_j) f_j + sum_k x_jk f_k = delta,
// with each contact term the secant of its own force (PairCompliance::
// contact at f_j) and x_jk the rack beam's influence plus the pairs' own
// coupling; a pair that carries nothing is carried at least as far as
// delta by the others. Checked over whole periods of the railway on its
// supports, the rack rigid, and with the pairs' coupling off.
TEST(Effects, LoadDependentSharingIsTheFixedPointOfEqualApproaches) {
  for (int variant = 0; variant < 3; ++variant) {
    Drive d = test::problem("rack_railway.yaml");
    ASSERT_EQ(d.effects.hertz, HertzModel::kWeberBanaschek);
    if (variant == 1) d.effects.rack_span = RackSpanModel::kRigid;
    if (variant == 2) d.effects.pair_coupling = false;
    d.numerics.positions_per_period = 40;
    const MeshStiffnessModel model(d);
    const MeshGeometry geo = build_mesh_geometry(d);
    const PairCompliance pair(d, geo);
    std::optional<RackSpanCompliance> span;
    if (d.effects.rack_span == RackSpanModel::kCoupled) span.emplace(rack_beam(d), d.pinion.pressure_angle, d.effects);
    const double F = d.load.force;
    int multi = 0;
    for (const MeshState& s : model.curve().samples) {
      const std::size_t n = s.pairs.size();
      if (n < 2) continue;
      ++multi;
      const double delta = F / s.stiffness;
      EXPECT_NEAR(s.approach, delta, 1e-12 * delta);
      for (std::size_t j = 0; j < n; ++j) {
        const PairState& pj = s.pairs[j];
        const double fj = F * pj.load_share;
        EXPECT_NEAR(pj.hertz, pair.contact(pj.s, fj), 1e-12 * pj.hertz) << "X " << s.travel;
        double u = (pj.local() + pj.body) * fj;
        for (std::size_t k = 0; k < n; ++k) {
          if (k == j) continue;
          const PairState& pk = s.pairs[k];
          double x = 0;
          if (span && pj.segment == pk.segment) x += span->influence(pj.a, pj.e, pk.a, pk.e);
          if (d.effects.pair_coupling && std::abs(pj.rack_tooth - pk.rack_tooth) == 1) {
            x += adjacent_pair_coupling(pj.fillet + pj.rack_foundation, pk.fillet + pk.rack_foundation,
                                        d.pinion.pressure_angle);
          }
          u += x * F * pk.load_share;
        }
        if (pj.load_share > 0) {
          EXPECT_NEAR(u, delta, 1e-8 * delta) << "variant " << variant << " X " << s.travel << " pair " << j;
        } else {
          EXPECT_GE(u, delta * (1 - 1e-8)) << "variant " << variant << " X " << s.travel << " pair " << j;
        }
      }
    }
    EXPECT_GT(multi, 100) << variant;
  }
}

// The effects line of `rackopt check` / `rackopt stiffness` names every
// switch of the FE-grade model, so a run's text says which physics it used.
TEST(Effects, SummaryLineNamesEveryFeGradeSwitch) {
  auto line = [](const std::vector<std::string>& overrides) {
    const Drive d = test::problem("rack_railway.yaml", overrides);
    return geometry_summary(d, build_mesh_geometry(d));
  };
  const std::string on = line({});
  for (const char* part : {"fillet foundation on (FE-calibrated)", "foundation on)", "Weber-Banaschek",
                           "pair coupling on", "supported rack on"}) {
    EXPECT_NE(on.find(part), std::string::npos) << part << "\n" << on;
  }
  const std::string off = line({"effects.fillet_calibration=off", "effects.supported_rack=off",
                                "effects.pair_coupling=off", "effects.rack_foundation=off"});
  for (const char* part : {"fillet foundation on (Sainsot's table)", "foundation off)", "pair coupling off",
                           "supported rack off"}) {
    EXPECT_NE(off.find(part), std::string::npos) << part << "\n" << off;
  }
}

}  // namespace
}  // namespace rackopt
