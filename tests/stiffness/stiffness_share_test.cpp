// PairState::stiffness_share: each loaded pair's part of the mesh stiffness,
// (C_A^-1 1)_i / K. Without relief it is the load share; with relief the
// loaded pairs' forces are f = delta C_A^-1 1 - C_A^-1 e, so
// sum_i K share_i (delta - e_i) = F (C symmetric) and sum_i share_i = 1,
// which the load shares do not satisfy.
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt {
namespace {

TEST(StiffnessShare, IsTheLoadShareWithoutRelief) {
  for (const char* file : {"gantry_axis.yaml", "rack_railway.yaml", "rack_railway_paper.yaml"}) {
    const Drive d = test_support::load_shipped_problem(file);
    const StiffnessCurve c = MeshStiffnessModel(d).curve(CurveDetail::kFull, 20);
    for (const MeshState& st : c.samples) {
      for (const PairState& p : st.pairs) ASSERT_EQ(p.stiffness_share, p.load_share) << file << " X = " << st.travel;
    }
  }
}

TEST(StiffnessShare, CarriesTheLoadAtTheApproachWithRelief) {
  for (const char* body : {"coupled", "rigid"}) {
    SCOPED_TRACE(body);
    const Drive d = test_support::load_shipped_problem(
        "gantry_axis.yaml", {std::string("effects.rack_span=") + body, "pinion.tip_relief.amount=15 um",
                             "pinion.tip_relief.length=1.0", "pinion.root_relief.amount=10 um",
                             "pinion.root_relief.length=0.8"});
    const StiffnessCurve c = MeshStiffnessModel(d).curve(CurveDetail::kFull, 20);
    const double F = d.load.force;
    int relieved_and_loaded = 0;
    for (const MeshState& st : c.samples) {
      double f = 0, shares = 0;
      for (const PairState& p : st.pairs) {
        ASSERT_GE(p.stiffness_share, 0.0);
        ASSERT_EQ(p.stiffness_share > 0, p.load_share > 0);
        f += st.stiffness * p.stiffness_share * (st.approach - p.relief);
        shares += p.stiffness_share;
        relieved_and_loaded += p.relief > 0 && p.load_share > 0;
      }
      ASSERT_NEAR(f, F, 1e-9 * F) << "X = " << st.travel;
      ASSERT_NEAR(shares, 1.0, 1e-12) << "X = " << st.travel;
    }
    EXPECT_GT(relieved_and_loaded, 0);
  }
}

}  // namespace
}  // namespace rackopt
