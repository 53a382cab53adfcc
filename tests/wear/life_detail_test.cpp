// WearModel::life without snapshots (Detail::kNoSnapshots, what the
// reliability's table, quantile and sample lives ask for): every other field
// is the same bits as the full result's, with and without the profile update
// and for a life that fails at once; only the snapshots are left empty.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
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

}  // namespace
}  // namespace rackopt
