// What a full curve keeps per sample: its pairs in storage of their own size,
// so a curve of 150 000 samples (the rack railway at 6250 positions per
// period) stays under 100 MiB with its CSV (docs/performance.md, "Long
// curves").
#include "rackopt/stiffness/mesh_stiffness.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/shipped_problems.hpp"

namespace rackopt {
namespace {

TEST(CurveMemory, EachSampleHoldsItsPairsInStorageOfTheirOwnSize) {
  for (const std::string file : {"rack_railway.yaml", "gantry_axis.yaml", "ship_lift.yaml"}) {
    SCOPED_TRACE(file);
    const StiffnessCurve c = MeshStiffnessModel(test_support::load_shipped_problem(file)).curve();
    ASSERT_GT(c.samples.size(), 100u);
    std::size_t loose = 0;
    for (const MeshState& s : c.samples) loose += s.pairs.capacity() != s.pairs.size() ? 1 : 0;
    EXPECT_EQ(loose, 0u) << "of " << c.samples.size() << " samples";
  }
}

}  // namespace
}  // namespace rackopt
