// WearModel::life without snapshots (Detail::kNoSnapshots): every other
// field is the same bits as the full result's, with and without the profile
// update and for a life that fails at once; only the snapshots are left
// empty. The life alone (Detail::kLifeOnly, what the reliability's table,
// quantile and sample lives ask for): the life, its criterion, limiting
// member and reason are the same bits as the full result's, and without the
// update they come from the bounded search (WearOptions::bounded_life_search),
// which must pick the same failing point as every point's weights.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "rackopt/wear/wear_life.hpp"
#include "wear_drives.hpp"

namespace rackopt {
namespace {

std::vector<std::uint64_t> bits_of(const std::vector<double>& v) {
  std::vector<std::uint64_t> b;
  for (double x : v) b.push_back(std::bit_cast<std::uint64_t>(x));
  return b;
}

void expect_same_but_snapshots(const WearLifeResult& full, const WearLifeResult& lean, const std::string& what) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.life_cycles), std::bit_cast<std::uint64_t>(lean.life_cycles)) << what;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.life_years), std::bit_cast<std::uint64_t>(lean.life_years)) << what;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.final_contact_ratio),
            std::bit_cast<std::uint64_t>(lean.final_contact_ratio))
      << what;
  EXPECT_EQ(full.criterion, lean.criterion) << what;
  EXPECT_EQ(full.reason, lean.reason) << what;
  EXPECT_EQ(full.limiting_member, lean.limiting_member) << what;
  EXPECT_EQ(bits_of(full.pinion.depth), bits_of(lean.pinion.depth)) << what;
  EXPECT_EQ(bits_of(full.rack.depth), bits_of(lean.rack.depth)) << what;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.max_depth), std::bit_cast<std::uint64_t>(lean.max_depth)) << what;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.max_depth_position),
            std::bit_cast<std::uint64_t>(lean.max_depth_position))
      << what;
  EXPECT_EQ(full.warnings, lean.warnings) << what;
  EXPECT_EQ(full.blocks, lean.blocks) << what;
  EXPECT_EQ(full.load_solves, lean.load_solves) << what;
  EXPECT_EQ(full.snapshots.size(), 4u) << what;
  EXPECT_TRUE(lean.snapshots.empty()) << what;
}

TEST(WearLifeDetail, WithoutSnapshotsEverythingElseIsTheSame) {
  for (bool update : {false, true}) {
    Drive d = test::ship_lift();
    d.wear.update_profile = update;
    d.wear.profile_points = 60;  // the update's many blocks stay fast
    const WearModel m(d);
    for (const WearSample& smp : {WearSample{}, WearSample{.contact_ratio = 1.44}, WearSample{.contact_ratio = 0.9}}) {
      const std::string what = std::string(update ? "update on" : "update off") + ", contact ratio " +
                               (smp.contact_ratio ? std::to_string(*smp.contact_ratio) : std::string("nominal"));
      expect_same_but_snapshots(m.life(smp), m.life(smp, WearModel::Detail::kNoSnapshots), what);
      // The full detail through the two-argument call is the one-argument call.
      expect_same_but_snapshots(m.life(smp, WearModel::Detail::kFull), m.life(smp, WearModel::Detail::kNoSnapshots),
                                what);
    }
  }
}

void expect_same_life_alone(const WearLifeResult& full, const WearLifeResult& lean, const std::string& what) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.life_cycles), std::bit_cast<std::uint64_t>(lean.life_cycles)) << what;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.life_pinion_cycles),
            std::bit_cast<std::uint64_t>(lean.life_pinion_cycles))
      << what;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.life_years), std::bit_cast<std::uint64_t>(lean.life_years)) << what;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.initial_contact_ratio),
            std::bit_cast<std::uint64_t>(lean.initial_contact_ratio))
      << what;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(full.final_contact_ratio),
            std::bit_cast<std::uint64_t>(lean.final_contact_ratio))
      << what;
  EXPECT_EQ(full.criterion, lean.criterion) << what;
  EXPECT_EQ(full.reason, lean.reason) << what;
  EXPECT_EQ(full.limiting_member, lean.limiting_member) << what;
  EXPECT_EQ(full.warnings, lean.warnings) << what;
  EXPECT_EQ(full.blocks, lean.blocks) << what;
  EXPECT_EQ(full.load_solves, lean.load_solves) << what;
}

// The shipped ship lift (240 points, update off), the same at 60 points,
// with the study's case-hardened rack (the case depth ends the life on the
// rack), without the Hertz band, and with the update on (where the life
// alone takes the full path).
TEST(WearLifeDetail, LifeOnlyBoundedSearchEqualsEveryPointsWeightsBitForBit) {
  struct Case {
    std::string name;
    Drive drive;
    WearOptions options;
  };
  std::vector<Case> cases;
  cases.push_back({"ship lift", test::ship_lift(), {}});
  cases.push_back({"ship lift, 60 points", test::ship_lift(), {}});
  cases.back().drive.wear.profile_points = 60;
  for (double case_depth : {2e-3, 6.35e-3}) {
    cases.push_back({"case-hardened rack " + std::to_string(case_depth), test::ship_lift(), {}});
    HardnessProfile& rack = cases.back().drive.wear.rack_hardness;
    rack = HardnessProfile{};
    rack.kind = HardnessProfile::Kind::kCaseHardened;
    rack.surface = 596 * kPaPerHB;
    rack.core = 300 * kPaPerHB;
    rack.case_depth = case_depth;
    cases.back().drive.wear.stop_at_case_depth = true;
  }
  // Measured hardness data that ends above the wear limit: the depths are
  // needed for the warning, so the life takes the full path.
  cases.push_back({"hardness data to 1 mm", test::ship_lift(), {}});
  cases.back().drive.wear.pinion_hardness.valid_depth = 1e-3;
  cases.push_back({"no Hertz band", test::ship_lift(), {}});
  cases.back().options.hertz_band = false;
  cases.push_back({"update on, 60 points", test::ship_lift(), {}});
  cases.back().drive.wear.update_profile = true;
  cases.back().drive.wear.profile_points = 60;
  std::mt19937_64 rng(7);
  for (const Case& c : cases) {
    WearOptions every = c.options;
    every.bounded_life_search = false;
    const WearModel bounded(c.drive, c.options), reference(c.drive, every);
    const double lo = std::max(1.0, c.drive.wear.min_contact_ratio), hi = bounded.max_contact_ratio();
    std::uniform_real_distribution<double> eps(lo - 0.02, hi + 0.02);  // a few fail at once
    std::uniform_real_distribution<double> scale(0.7, 1.4);
    std::vector<WearSample> samples{WearSample{}, WearSample{.force_scale = 1.3}};
    const int n = c.drive.wear.update_profile ? 3 : 40;
    for (int k = 0; k < n; ++k) samples.push_back(WearSample{.contact_ratio = eps(rng)});
    for (int k = 0; k < n / 4; ++k)
      samples.push_back(WearSample{.wear_coefficient_scale = scale(rng),
                                   .force_scale = scale(rng),
                                   .surface_hardness_scale = scale(rng),
                                   .contact_ratio = eps(rng)});
    bool warned = false;
    for (const WearSample& smp : samples) {
      const std::string what = c.name + ", contact ratio " +
                               (smp.contact_ratio ? std::to_string(*smp.contact_ratio) : std::string("nominal")) +
                               ", force x" + std::to_string(smp.force_scale);
      const WearLifeResult full = reference.life(smp);
      expect_same_life_alone(full, bounded.life(smp, WearModel::Detail::kLifeOnly), what);
      expect_same_life_alone(full, reference.life(smp, WearModel::Detail::kLifeOnly), what + " (every point's weights)");
      expect_same_life_alone(full, bounded.life(smp), what + " (full detail, bounded model)");
      warned = warned || !full.warnings.empty();
    }
    if (c.name == "hardness data to 1 mm") {
      EXPECT_TRUE(warned) << "the case must exercise the hardness warning";
    }
  }
}

}  // namespace
}  // namespace rackopt
