// The spalling paper's trends for its spall levels (normal, mild 5 mm, moderate 10 mm,
// severe 15 mm; depth 2 mm, width 5 mm) on problems/large_module.yaml:
// the stiffness dips only while the spalled tooth is in mesh, the dip lasts
// longer as the spall grows, and the mean falls monotonically.
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "test_drives.hpp"

namespace rackopt {
namespace {

TEST(SpallingPaperSpall, DipOnlyWhileSpalledToothInMeshLongerAndDeeperOnAverage) {
  const StiffnessCurve normal = MeshStiffnessModel(test::problem("large_module.yaml", {"variant=normal"})).curve();
  double prev_mean = normal.k_mean;
  double prev_dip_length = 0;
  for (const char* level : {"mild", "moderate", "severe"}) {
    SCOPED_TRACE(level);
    const Drive d = test::problem("large_module.yaml", {std::string("variant=") + level});
    ASSERT_FALSE(d.spalls.empty());
    const MeshStiffnessModel model(d);
    const StiffnessCurve c = model.curve();
    ASSERT_EQ(c.samples.size(), normal.samples.size());
    double dip_length = 0;
    for (std::size_t i = 0; i < c.samples.size(); ++i) {
      const MeshState& s = c.samples[i];
      ASSERT_DOUBLE_EQ(s.travel, normal.samples[i].travel);
      bool spalled_tooth_in_mesh = false;
      for (const PairState& p : s.pairs) {
        const Spall& sp = d.spalls.front();
        if ((sp.member == Member::kPinion && p.pinion_tooth == sp.tooth) ||
            (sp.member == Member::kRack && p.rack_tooth == sp.tooth)) {
          spalled_tooth_in_mesh = true;
        }
      }
      if (!spalled_tooth_in_mesh) {
        std::string teeth;
        for (const PairState& p : s.pairs) teeth += " " + std::to_string(p.pinion_tooth);
        // Equal up to rounding: the tooth tables are cached by LOA position.
        EXPECT_NEAR(s.stiffness / normal.samples[i].stiffness, 1.0, 1e-12) << "X = " << s.travel << " pinion teeth" << teeth;
      } else {
        EXPECT_LE(s.stiffness, normal.samples[i].stiffness * (1 + 1e-12));
      }
      if (i + 1 < c.samples.size() && s.stiffness < normal.samples[i].stiffness * (1 - 1e-9)) {
        dip_length += c.samples[i + 1].travel - s.travel;
      }
    }
    EXPECT_GT(dip_length, prev_dip_length);
    EXPECT_LT(c.k_mean, prev_mean);
    prev_dip_length = dip_length;
    prev_mean = c.k_mean;
  }
}

// A spall on a rack tooth acts only while that rack tooth is in mesh, and a
// rack tooth meshes once per span: the dip happens once along the travel.
TEST(SpallingPaperSpall, RackToothSpallActsOnlyOnThatTooth) {
  Drive d = test::problem("large_module.yaml", {"variant=severe"});
  d.spalls.front().member = Member::kRack;
  d.spalls.front().tooth = 5;
  const StiffnessCurve normal = MeshStiffnessModel(test::problem("large_module.yaml", {"variant=normal"})).curve();
  const StiffnessCurve c = MeshStiffnessModel(d).curve();
  ASSERT_EQ(c.samples.size(), normal.samples.size());
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i < c.samples.size(); ++i) {
    bool on = false;
    for (const PairState& p : c.samples[i].pairs) on = on || p.rack_tooth == 5;
    const double ratio = c.samples[i].stiffness / normal.samples[i].stiffness;
    if (!on) {
      EXPECT_NEAR(ratio, 1.0, 1e-12) << c.samples[i].travel;
    } else if (ratio < 1 - 1e-9) {
      lo = std::min(lo, c.samples[i].travel);
      hi = std::max(hi, c.samples[i].travel);
    }
  }
  const double p = M_PI * d.pinion.module;
  ASSERT_TRUE(std::isfinite(lo));
  EXPECT_LT(hi - lo, 2 * p);  // one passage of tooth 5, not periodic
}

}  // namespace
}  // namespace rackopt
