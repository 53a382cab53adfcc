// Hypervolume and spacing against values worked out by hand in each comment.
#include "rackopt/solvers/front_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace rs = rackopt::solvers;

namespace {

TEST(Hypervolume, TwoObjectiveStaircase) {
  // Sorted by f1, each point adds (next f1 - f1) * (ref2 - f2):
  // (1,3): 1 * 1 = 1; (2,2): 1 * 2 = 2; (3,1): 1 * 3 = 3 -> 6.
  const std::vector<double> ref{4, 4};
  EXPECT_DOUBLE_EQ(rs::hypervolume({{1, 3}, {2, 2}, {3, 1}}, ref), 6.0);
  // A dominated point adds nothing; a point outside the box adds nothing.
  EXPECT_DOUBLE_EQ(rs::hypervolume({{1, 3}, {2, 2}, {3, 1}, {3, 3}, {5, 0}}, ref), 6.0);
  EXPECT_DOUBLE_EQ(rs::hypervolume({{5, 5}}, ref), 0.0);
  EXPECT_DOUBLE_EQ(rs::hypervolume({}, ref), 0.0);
}

TEST(Hypervolume, ThreeAndFourObjectiveBoxes) {
  // One point: the box to the reference, 1 * 2 * 3.
  EXPECT_DOUBLE_EQ(rs::hypervolume({{1, 1, 1}}, std::vector<double>{2, 3, 4}), 6.0);
  // (0,0,1) -> 2*2*1 = 4, (0,1,0) -> 2*1*2 = 4, shared box from (0,1,1): 2*1*1 = 2 -> 6.
  EXPECT_NEAR(rs::hypervolume({{0, 0, 1}, {0, 1, 0}}, std::vector<double>{2, 2, 2}), 6.0, 1e-12);
  EXPECT_NEAR(rs::hypervolume({{0, 0, 0, 0}}, std::vector<double>{1, 2, 3, 4}), 24.0, 1e-12);
  // Two 4-objective points: 1*1*2*2 + 2*2*1*1 - overlap from (1,1,1,1): 1*1*1*1 -> 7.
  EXPECT_NEAR(rs::hypervolume({{1, 1, 0, 0}, {0, 0, 1, 1}}, std::vector<double>{2, 2, 2, 2}), 7.0, 1e-12);
}

TEST(Hypervolume, RefusesVectorsOfTheWrongSize) {
  EXPECT_THROW(rs::hypervolume({{1, 2, 3}}, std::vector<double>{4, 4}), std::invalid_argument);
}

TEST(Spacing, EvenFrontIsZeroAndAnUnevenOneMatchesSchott) {
  EXPECT_NEAR(rs::spacing({{0, 3}, {1, 2}, {2, 1}, {3, 0}}), 0.0, 1e-15);
  // Ranges 3 and 3. Nearest normalized L1 distances: d0 = 2/3, d1 = 2/3,
  // d2 = 4/3; mean 8/9; sum of squared deviations 24/81; / (n - 1) = 12/81.
  EXPECT_NEAR(rs::spacing({{0, 3}, {1, 2}, {3, 0}}), std::sqrt(12.0) / 9.0, 1e-15);
  EXPECT_EQ(rs::spacing({{0, 1}, {1, 0}}), 0.0);
}

TEST(FrontQuality, NormalizedHypervolumeWithTheDefaultReference) {
  // Ideal (1,1), worst (3,3), range 2: reference 3 + 0.2 = 3.2 in both.
  // Staircase: (1,3): 1 * 0.2; (2,2): 1 * 1.2; (3,1): 0.2 * 2.2 -> 1.84 of a
  // 2.2 * 2.2 = 4.84 box.
  const rs::FrontQuality q = rs::front_quality({{1, 3}, {2, 2}, {3, 1}});
  EXPECT_EQ(q.points, 3u);
  EXPECT_EQ(q.non_dominated, 3u);
  ASSERT_EQ(q.reference.size(), 2u);
  EXPECT_DOUBLE_EQ(q.reference[0], 3.2);
  EXPECT_DOUBLE_EQ(q.ideal[1], 1.0);
  EXPECT_NEAR(q.hypervolume, 1.84 / 4.84, 1e-14);
  EXPECT_NEAR(q.spacing, 0.0, 1e-15);
  // A given reference replaces the default: (4,4) -> 6 of a 3 * 3 box.
  const std::vector<double> ref{4, 4};
  EXPECT_NEAR(rs::front_quality({{1, 3}, {2, 2}, {3, 1}}, ref).hypervolume, 6.0 / 9.0, 1e-14);
  // A dominated member is counted as a point but not as non-dominated.
  EXPECT_EQ(rs::front_quality({{1, 3}, {2, 2}, {3, 1}, {3, 3}}).non_dominated, 3u);
  EXPECT_EQ(rs::front_quality({}).points, 0u);
}

}  // namespace
