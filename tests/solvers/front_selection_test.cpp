// Choosing a front of a requested size from many feasible evaluations.
#include "rackopt/solvers/front_selection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace rs = rackopt::solvers;

namespace {

rs::ParetoPoint point(std::vector<double> f, std::string label = "") {
  rs::ParetoPoint p;
  p.x = {f[0]};
  p.evaluation.objectives = std::move(f);
  p.label = std::move(label);
  p.feasible = true;
  return p;
}

TEST(CrowdingDistance, EndsAreInfiniteAndTheMiddleSumsNormalizedGaps) {
  // On the line f1 + f2 = 3 with unit steps: each middle point's neighbours
  // are 2 apart in both objectives (range 3): 2/3 + 2/3.
  const auto d = rs::crowding_distances({{0, 3}, {1, 2}, {2, 1}, {3, 0}});
  EXPECT_TRUE(std::isinf(d[0]));
  EXPECT_TRUE(std::isinf(d[3]));
  EXPECT_NEAR(d[1], 4.0 / 3.0, 1e-15);
  EXPECT_NEAR(d[2], 4.0 / 3.0, 1e-15);
  EXPECT_TRUE(std::isinf(rs::crowding_distances({{0, 1}, {1, 0}})[0]));
}

TEST(SelectFront, DropsDominatedAndNearDuplicatePointsAndSorts) {
  std::vector<rs::ParetoPoint> pts{point({2, 1}, "a"), point({0, 3}, "b"), point({1, 2}, "c"),
                                   point({1.0000001, 2.0000001}, "c-twin"), point({2, 2}, "dominated")};
  const rs::ParetoResult r = rs::select_front(pts, 10, 1e-4);
  ASSERT_EQ(r.front.size(), 3u);
  EXPECT_EQ(r.front[0].label, "b");
  EXPECT_EQ(r.front[1].label, "c");
  EXPECT_EQ(r.front[2].label, "a");
  EXPECT_EQ(r.ideal, (std::vector<double>{0, 1}));
  EXPECT_EQ(r.nadir, (std::vector<double>{2, 3}));
}

TEST(SelectFront, ThinsToTheRequestedCountKeepingTheExtremesAndTheSpread) {
  // 41 points on f2 = 1 - f1, densely packed in [0, 0.1] and sparse above:
  // thinning to 5 must keep both ends and spread the rest over the line.
  std::vector<rs::ParetoPoint> pts;
  for (int i = 0; i <= 30; ++i) pts.push_back(point({0.1 * i / 30.0, 1 - 0.1 * i / 30.0}));
  for (int i = 1; i <= 10; ++i) pts.push_back(point({0.1 + 0.09 * i, 0.9 - 0.09 * i}));
  const rs::ParetoResult r = rs::select_front(pts, 5, 0.0);
  ASSERT_EQ(r.front.size(), 5u);
  EXPECT_EQ(r.front.front().evaluation.objectives[0], 0.0);
  EXPECT_NEAR(r.front.back().evaluation.objectives[0], 1.0, 1e-12);
  int above = 0;
  for (const auto& p : r.front) above += p.evaluation.objectives[0] > 0.1 + 1e-12 ? 1 : 0;
  EXPECT_GE(above, 3);  // the sparse part holds 90 % of the front's length
}

TEST(SelectFront, EmptyInputGivesAnEmptyFront) {
  EXPECT_TRUE(rs::select_front({}, 5, 1e-4).front.empty());
}

}  // namespace
