// The order of convergence of the wear life with the profile update
// (docs/models/wear.md, "Progression and failure"; docs/accuracy.md, "Order
// of convergence with the profile update"): Heun's predictor-corrector makes the life second order in
// wear.block_fraction, so halving the block cuts the error about fourfold. The
// case is the one where the order matters most: the loaded contact ratio
// ends the life (ship lift, sampled contact ratio 1.52, allowable 1.49),
// whose drop follows the unloading of the worn tips. A first-order block
// (the rates of the block's start) halves the error at best. The reference
// is the same model with a block eight times finer, computed here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/wear/wear_life.hpp"

namespace rackopt {
namespace {

const std::string kOrderProblems = std::string(RACKOPT_SOURCE_DIR) + "/problems/";

// 60 points keep the test cheap: the block's order does not depend on them.
WearLifeResult contact_ratio_life(double block_fraction, bool heun) {
  Drive d = load_problem(kOrderProblems + "ship_lift.yaml", {"wear.update_profile=on", "wear.min_contact_ratio=1.49"});
  d.wear.profile_points = 60;
  d.wear.block_fraction = block_fraction;
  return WearModel(d, {.heun_blocks = heun}).life({.contact_ratio = 1.52}, WearModel::Detail::kLifeOnly);
}

double error_ratio(bool heun) {
  const double ref = contact_ratio_life(0.005, heun).life_cycles;
  const WearLifeResult coarse = contact_ratio_life(0.08, heun), fine = contact_ratio_life(0.04, heun);
  EXPECT_EQ(coarse.criterion, "contact_ratio");
  EXPECT_EQ(fine.criterion, "contact_ratio");
  return std::abs(coarse.life_cycles / ref - 1) / std::abs(fine.life_cycles / ref - 1);
}

TEST(WearBlockOrder, ContactRatioLifeIsSecondOrderInTheBlockFraction) {
  EXPECT_GE(error_ratio(true), 3.0);
}

// The same measure sees the first order of the frozen-rate block, so the
// test above can fail.
TEST(WearBlockOrder, FrozenRateBlockIsFirstOrder) {
  const double ratio = error_ratio(false);
  EXPECT_GT(ratio, 1.5);
  EXPECT_LT(ratio, 3.0);
}

// The same case against the profile points, at the default block: the loaded
// contact ratio's zero found from each side of the margin's kink and the
// pair transitions between mesh positions added to the pass loads
// (docs/models/wear.md, "Worn contact ratio", "Load seen by a point"). With
// straight lines across both, the error fell about as 1/N (240 -> 480
// points: a ratio of 2.5-2.9, docs/accuracy.md, "Order of convergence with
// the profile update").
TEST(WearPointsOrder, ContactRatioLifeConvergesFasterThanFirstOrderInThePoints) {
  auto life = [](int points) {
    Drive d = load_problem(kOrderProblems + "ship_lift.yaml", {"wear.update_profile=on", "wear.min_contact_ratio=1.49"});
    d.wear.profile_points = points;
    const WearLifeResult r = WearModel(d).life({.contact_ratio = 1.52}, WearModel::Detail::kLifeOnly);
    EXPECT_EQ(r.criterion, "contact_ratio") << points;
    return r.life_cycles;
  };
  const double ref = life(1920);
  const double e240 = std::abs(life(240) / ref - 1), e480 = std::abs(life(480) / ref - 1);
  EXPECT_GE(e240 / e480, 3.0) << e240 << " " << e480;
  EXPECT_LT(e240, 0.035);
}

}  // namespace
}  // namespace rackopt
