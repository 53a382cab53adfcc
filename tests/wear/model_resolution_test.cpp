// The wear model's resolution knobs (WearOptions: positions_cap,
// compliance_intervals, hardness_cells) against the finest settings of
// before them: the defaults stay within the errors documented in
// docs/accuracy.md ("Compliance tables and mesh positions per point"), the
// cap leaves a drive with few profile points alone, and a much coarser
// setting is caught by the same comparison.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/wear/wear_life.hpp"
#include "support/shipped_problems.hpp"
#include "wear_drives.hpp"

namespace rackopt {
namespace {

// The settings before the knobs: 2 mesh positions per profile point at any
// point count, 512 compliance-table intervals, 4096 hardness cells.
WearOptions finest() {
  WearOptions o;
  o.positions_cap = 1e9;
  o.compliance_intervals = 512;
  o.hardness_cells = 4096;
  return o;
}

// Lives of the ship lift's metrics: the nominal one and those at contact
// ratios across its scatter (the lives at R = 0.99 ... 0.5 lie among them).
std::vector<double> ship_lift_lives(const WearModel& m) {
  std::vector<double> out{m.life().life_years};
  for (double eps : {1.34, 1.39, 1.44, 1.50}) out.push_back(m.life({.contact_ratio = eps}).life_years);
  return out;
}

double largest_relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(a[k] - b[k]) / b[k]);
  return worst;
}

TEST(WearModelResolution, DefaultsStayWithinTheirDocumentedErrorOnTheShipLift) {
  const Drive d = test::ship_lift();
  ASSERT_EQ(d.wear.profile_points, 240);  // where the cap takes effect
  const std::vector<double> fine = ship_lift_lives(WearModel(d, finest()));
  const std::vector<double> deflt = ship_lift_lives(WearModel(d));
  // Documented: 1.3e-5 at most (the nominal life), lives at R within 5e-8.
  EXPECT_LT(largest_relative_difference(deflt, fine), 3e-5);
  for (std::size_t k = 1; k < fine.size(); ++k) EXPECT_NEAR(deflt[k] / fine[k], 1.0, 1e-6) << "life " << k;
}

TEST(WearModelResolution, TheComparisonCatchesACoarseTable) {
  // 16 intervals: measured 2.7e-3 on the nominal life. The same comparison
  // as above must see it, or it could not fail.
  const Drive d = test::ship_lift();
  WearOptions coarse = finest();
  coarse.compliance_intervals = 16;
  const std::vector<double> fine = ship_lift_lives(WearModel(d, finest()));
  EXPECT_GT(largest_relative_difference(ship_lift_lives(WearModel(d, coarse)), fine), 3e-5);
}

TEST(WearModelResolution, HardnessCellsChangeTheLifeByLessThan1e9) {
  const Drive d = test::ship_lift();
  WearOptions half = finest();
  half.hardness_cells = 2048;
  const std::vector<double> fine = ship_lift_lives(WearModel(d, finest()));
  EXPECT_LT(largest_relative_difference(ship_lift_lives(WearModel(d, half)), fine), 1e-9);
}

TEST(WearModelResolution, TheCapLeavesFewProfilePointsAlone) {
  // Below 120 profile points 2 positions per point stay under the cap: the
  // same model bit for bit, with and without it.
  Drive d = test::ship_lift();
  d.wear.profile_points = 60;
  WearOptions capped = finest();
  capped.positions_cap = 240;
  const WearModel a(d, finest()), b(d, capped);
  for (std::optional<double> eps : {std::optional<double>{}, std::optional<double>{1.44}}) {
    const WearLifeResult ra = a.life({.contact_ratio = eps}), rb = b.life({.contact_ratio = eps});
    EXPECT_EQ(std::bit_cast<std::uint64_t>(ra.life_cycles), std::bit_cast<std::uint64_t>(rb.life_cycles));
    EXPECT_EQ(ra.rack.depth, rb.rack.depth);
  }
  // At 240 points it does take effect (else the first test compares a model with itself).
  d.wear.profile_points = 240;
  EXPECT_NE(WearModel(d, finest()).life().life_cycles, WearModel(d, capped).life().life_cycles);
}

TEST(WearModelResolution, KnobsOutsideTheirRangeAreRejected) {
  const Drive d = test::ship_lift();
  WearOptions o;
  o.positions_cap = 0;
  EXPECT_THROW(WearModel(d, o), InputError);
  o = {};
  o.compliance_intervals = 1;
  EXPECT_THROW(WearModel(d, o), InputError);
  o = {};
  o.hardness_cells = 0;
  EXPECT_THROW(WearModel(d, o), InputError);
}

}  // namespace
}  // namespace rackopt
