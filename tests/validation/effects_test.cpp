// "Simulate only the effects a scene calls for": switching one effect off
// changes the component it names and leaves every other component as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "rackopt/stiffness/mesh_stiffness.hpp"
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
      {"rack_span", [](Effects& e) { e.rack_span = RackSpanModel::kRigid; }, false, false, false, false, true},
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
      // fillet calibration (a stiffening) never makes it stiffer.
      if (std::string(c.name) == "fillet_calibration") {
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

// Weber-Banaschek contact (physics.md 4.2): the contact half-width grows with
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
