// The wear life at the default wear.profile_points is converged: within
// 0.5 % of a much finer discretization on the shipped problems and on a
// lifting-platform drive whose pressure angle moves the pinion's wear peak
// across the profile points (docs/accuracy.md, "Profile points"), and a
// frozen-load life does not depend on where the points fall (the peak probe,
// docs/models/wear.md).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/wear/wear_life.hpp"

namespace rackopt {
namespace {

const std::string kProblems = std::string(RACKOPT_SOURCE_DIR) + "/problems/";

// A lifting platform: module 6, 17 teeth, case-hardened, built on the gantry
// axis problem (the "m6 z17 case" drive of accuracy_table wear_points).
Drive lifting_platform(double pressure_angle_deg) {
  const std::string h = "{kind: case_hardened, surface: 650 HV, core: 350 HV, case_depth: 0.9 mm, limit: 550 HV}";
  return load_problem(kProblems + "gantry_axis.yaml",
                      {"pinion.module=6 mm", "pinion.teeth=17", "pinion.face_width=60 mm", "load.thrust=25 kN",
                       "rack.body_height=30 mm", "wear.max_depth=0.3 mm", "duty.travel_per_year=300 km/yr",
                       "duty.stroke=4 m", "wear.pinion_hardness=" + h, "wear.rack_hardness=" + h,
                       "pinion.pressure_angle=" + std::to_string(pressure_angle_deg) + " deg"});
}

double life_at(Drive d, int points) {
  d.wear.profile_points = points;
  return WearModel(d).life({}, WearModel::Detail::kLifeOnly).life_cycles;
}

constexpr int kRefined = 1920;

TEST(ProfilePointsConvergence, DefaultWithinHalfAPercentOnALiftingPlatform) {
  // 17.5 and 23 deg: the angles where 60 points were furthest off (+5.6 %, +5.9 %).
  for (double angle : {17.5, 18.5, 23.0}) {
    const Drive d = lifting_platform(angle);
    ASSERT_TRUE(d.wear.update_profile);
    EXPECT_NEAR(life_at(d, d.wear.profile_points) / life_at(d, kRefined), 1.0, 5e-3) << angle << " deg";
  }
}

TEST(ProfilePointsConvergence, DefaultWithinHalfAPercentOnTheShippedProblems) {
  for (const char* file : {"gantry_axis.yaml", "ship_lift.yaml"}) {
    for (const char* update : {"wear.update_profile=off", "wear.update_profile=on"}) {
      Drive d = load_problem(kProblems + file, {update});
      d.wear.profile_points = Drive{}.wear.profile_points;  // the model default, not the file's
      EXPECT_NEAR(life_at(d, d.wear.profile_points) / life_at(d, kRefined), 1.0, 5e-3) << file << ", " << update;
    }
  }
}

// Frozen loads: the life is the largest wear rate's, wherever the points
// fall. Without the probe, 60 / 90 / 120 points missed the ship lift's
// peak by 1.1e-3 / 1.9e-3 / 2.0e-3 of the life.
TEST(ProfilePointsConvergence, FrozenLoadLifeFindsThePeakBetweenPoints) {
  const Drive d = load_problem(kProblems + "ship_lift.yaml");  // update_profile off
  ASSERT_FALSE(d.wear.update_profile);
  const double ref = life_at(d, kRefined);
  for (int n : {60, 90, 120}) EXPECT_NEAR(life_at(d, n) / ref, 1.0, 2e-4) << n << " points";
}

// The same across sampled contact ratios: without the probe, the 60-point
// life(eps) jittered by 1-4e-3 as the peak moved across the points (the
// clumping of Monte Carlo lives, docs/models/reliability.md, "Resolution").
TEST(ProfilePointsConvergence, FrozenLoadLifeIsSmoothInTheContactRatio) {
  Drive coarse = load_problem(kProblems + "ship_lift.yaml");  // update_profile off
  Drive fine = coarse;
  coarse.wear.profile_points = 60;
  fine.wear.profile_points = 240;
  const WearModel mc(coarse), mf(fine);
  for (int k = 0; k <= 20; ++k) {
    const WearSample s{.contact_ratio = 1.40 + 0.005 * k};
    EXPECT_NEAR(mc.life(s, WearModel::Detail::kLifeOnly).life_cycles / mf.life(s, WearModel::Detail::kLifeOnly).life_cycles,
                1.0, 1e-5)
        << *s.contact_ratio;
  }
}

}  // namespace
}  // namespace rackopt
