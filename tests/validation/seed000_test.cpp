// Seed 000 (hinged rack, mountain railway): trends and the rack-length table.
// physics.md 14.3: with the paper's reduced model (body compliance inside each
// pair, no couple term, interference ignored) and one rack body section for
// all lengths, the minimum mesh stiffness at span 2.4 / 1.8 / 1.2 m must be
// within 5% of the paper's 26.095 / 59.713 / 177.777 MN/m.
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "test_drives.hpp"

namespace rackopt {
namespace {

TEST(Seed000, PaperModelMinimumStiffnessVersusSpan) {
  const struct {
    const char* span;
    double k_min_paper;  // seed 000 Table 5 [N/m]
  } rows[] = {{"rack.span=2.4 m", 26.095e6}, {"rack.span=1.8 m", 59.713e6}, {"rack.span=1.2 m", 177.777e6}};
  for (const auto& row : rows) {
    SCOPED_TRACE(row.span);
    const MeshStiffnessModel model(test::problem("rack_railway_paper.yaml", {row.span}));
    const StiffnessCurve c = model.curve();
    EXPECT_NEAR(c.k_min / row.k_min_paper, 1.0, 0.05) << "k_min = " << c.k_min * 1e-6 << " MN/m";
  }
}

// The longer span is softer, in the paper model and in the full model alike.
TEST(Seed000, MinimumStiffnessFallsWithSpan) {
  for (const char* file : {"rack_railway.yaml", "rack_railway_paper.yaml"}) {
    SCOPED_TRACE(file);
    double prev = INFINITY;
    for (const char* span : {"rack.span=1.2 m", "rack.span=1.8 m", "rack.span=2.4 m"}) {
      const double k = MeshStiffnessModel(test::problem(file, {span})).curve().k_min;
      EXPECT_LT(k, prev) << span;
      prev = k;
    }
  }
}

// Clearance 0 -> 2 -> 4 mm and pressure angle 14 -> 16 deg shorten the zone
// with more pairs (the paper's Tables 3 and 4 trend; interference ignored as
// the paper did).
TEST(Seed000, ZoneWithMorePairsShrinks) {
  auto more_pairs_zone = [](const std::vector<std::string>& sets) {
    const MeshStiffnessModel m(test::problem("rack_railway_paper.yaml", sets));
    const auto& zones = m.geometry().zones;
    return std::make_pair(zones.back().pairs, zones.back().length_travel);
  };
  auto z0 = more_pairs_zone({"mounting.clearance=0 mm"});
  auto z2 = more_pairs_zone({"mounting.clearance=2 mm"});
  auto z4 = more_pairs_zone({"mounting.clearance=4 mm"});
  ASSERT_EQ(z0.first, z2.first);
  EXPECT_LT(z2.second, z0.second);
  if (z4.first == z2.first) {
    EXPECT_LT(z4.second, z2.second);
  }
  auto a14 = more_pairs_zone({"pinion.pressure_angle=14 deg"});
  auto a15 = more_pairs_zone({"pinion.pressure_angle=15 deg"});
  ASSERT_EQ(a14.first, a15.first);
  EXPECT_LT(a15.second, a14.second);
}

}  // namespace
}  // namespace rackopt
