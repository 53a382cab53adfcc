// The wear model's nominal start built once per model (WearModel::Impl::
// NominalStart, WearOptions::reuse_nominal_start): every life equals, bit
// for bit, the one of a model that rebuilds its start for each life, in any
// order of calls and from several threads at once; another design (another
// drive, hence another model) gets its own start.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "rackopt/wear/wear_life.hpp"
#include "wear_drives.hpp"

namespace rackopt {
namespace {

std::vector<std::uint64_t> bit_pattern(const std::vector<double>& v) {
  std::vector<std::uint64_t> b;
  b.reserve(v.size());
  for (double x : v) b.push_back(std::bit_cast<std::uint64_t>(x));
  return b;
}
std::uint64_t bit_pattern(double x) { return std::bit_cast<std::uint64_t>(x); }

void expect_same_profile(const WearProfile& a, const WearProfile& b, const std::string& what) {
  EXPECT_EQ(bit_pattern(a.s), bit_pattern(b.s)) << what;
  EXPECT_EQ(bit_pattern(a.position), bit_pattern(b.position)) << what;
  EXPECT_EQ(bit_pattern(a.radius_or_height), bit_pattern(b.radius_or_height)) << what;
  EXPECT_EQ(bit_pattern(a.depth), bit_pattern(b.depth)) << what;
}

// Every field but the wall time, bit for bit.
void expect_same_life(const WearLifeResult& a, const WearLifeResult& b, const std::string& what) {
  EXPECT_EQ(bit_pattern(a.life_cycles), bit_pattern(b.life_cycles)) << what;
  EXPECT_EQ(bit_pattern(a.life_pinion_cycles), bit_pattern(b.life_pinion_cycles)) << what;
  EXPECT_EQ(bit_pattern(a.life_years), bit_pattern(b.life_years)) << what;
  EXPECT_EQ(a.criterion, b.criterion) << what;
  EXPECT_EQ(a.reason, b.reason) << what;
  EXPECT_EQ(a.limiting_member, b.limiting_member) << what;
  EXPECT_EQ(bit_pattern(a.initial_contact_ratio), bit_pattern(b.initial_contact_ratio)) << what;
  EXPECT_EQ(bit_pattern(a.final_contact_ratio), bit_pattern(b.final_contact_ratio)) << what;
  expect_same_profile(a.pinion, b.pinion, what + " pinion");
  expect_same_profile(a.rack, b.rack, what + " rack");
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size()) << what;
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    EXPECT_EQ(bit_pattern(a.snapshots[k].cycles), bit_pattern(b.snapshots[k].cycles)) << what;
    EXPECT_EQ(bit_pattern(a.snapshots[k].contact_ratio), bit_pattern(b.snapshots[k].contact_ratio)) << what;
    expect_same_profile(a.snapshots[k].pinion, b.snapshots[k].pinion, what + " snapshot pinion");
    expect_same_profile(a.snapshots[k].rack, b.snapshots[k].rack, what + " snapshot rack");
  }
  EXPECT_EQ(bit_pattern(a.max_depth), bit_pattern(b.max_depth)) << what;
  EXPECT_EQ(a.max_depth_member, b.max_depth_member) << what;
  EXPECT_EQ(bit_pattern(a.max_depth_s), bit_pattern(b.max_depth_s)) << what;
  EXPECT_EQ(bit_pattern(a.max_depth_position), bit_pattern(b.max_depth_position)) << what;
  EXPECT_EQ(a.warnings, b.warnings) << what;
  EXPECT_EQ(a.blocks, b.blocks) << what;
  EXPECT_EQ(a.load_solves, b.load_solves) << what;
}

struct NamedSample {
  std::string name;
  WearSample sample;
};
// Samples that start from the nominal start as it is (K, hardness), from its
// path only (force), and from a path of their own (contact ratio, also out of
// range: the zero profiles of an immediate failure).
std::vector<NamedSample> samples() {
  return {{"nominal", {}},
          {"K x1.3", {.wear_coefficient_scale = 1.3}},
          {"hardness x0.8", {.surface_hardness_scale = 0.8}},
          {"K x0.7, hardness x1.1", {.wear_coefficient_scale = 0.7, .surface_hardness_scale = 1.1}},
          {"force x1.2", {.force_scale = 1.2}},
          {"force x0.9, K x1.3", {.wear_coefficient_scale = 1.3, .force_scale = 0.9}},
          {"contact ratio 1.45", {.contact_ratio = 1.45}},
          {"contact ratio 0.5 (fails at once)", {.contact_ratio = 0.5}}};
}

// The model's defaults (60 points, profile update on: many blocks) and the
// shipped calibration (240 points, update off: one block).
std::vector<Drive> drives() {
  Drive shipped = test::ship_lift_wear();
  shipped.wear.profile_points = 240;
  shipped.wear.update_profile = false;
  return {test::ship_lift_wear(), shipped};
}

TEST(NominalStart, ReusedStartGivesTheLivesOfARebuiltOneBitForBit) {
  for (const Drive& d : drives()) {
    const WearModel reused(d);
    const WearModel rebuilt(d, WearOptions{.reuse_nominal_start = false});
    const std::vector<NamedSample> all = samples();
    // A force-scaled sample first: the start is then built by a life that
    // does not use its weights as they are.
    for (std::size_t k = all.size(); k-- > 0;) {
      const std::string what = all[k].name + ", " + std::to_string(d.wear.profile_points) + " points";
      expect_same_life(reused.life(all[k].sample), rebuilt.life(all[k].sample), what);
    }
    for (const NamedSample& s : all) expect_same_life(reused.life(s.sample), rebuilt.life(s.sample), s.name + " again");
  }
}

TEST(NominalStart, ThreadsBuildingItAtOnceGetTheSameLives) {
  const Drive d = drives()[1];
  const WearModel rebuilt(d, WearOptions{.reuse_nominal_start = false});
  std::vector<WearLifeResult> want;
  for (int t = 0; t < 4; ++t) want.push_back(rebuilt.life({.wear_coefficient_scale = 1.0 + 0.1 * t}));
  for (int round = 0; round < 3; ++round) {
    const WearModel fresh(d);  // nobody has built its start yet
    std::vector<WearLifeResult> got(4);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
      threads.emplace_back([&, t] { got[t] = fresh.life({.wear_coefficient_scale = 1.0 + 0.1 * t}); });
    for (std::thread& th : threads) th.join();
    for (int t = 0; t < 4; ++t) expect_same_life(got[t], want[t], "thread " + std::to_string(t));
  }
}

// A design change makes a new drive and a new model: its start is its own,
// not the previous design's (the lives differ and equal a rebuilt start's),
// and a model moved elsewhere keeps its start.
TEST(NominalStart, ADesignChangeGetsItsOwnStart) {
  Drive d = drives()[1];
  WearModel first(d);
  const WearLifeResult first_life = first.life({.wear_coefficient_scale = 1.2});
  d.mounting.clearance = 2e-3;  // the drive the first model copied is not affected
  d.pinion.module *= 1.05;
  const WearModel second(d);
  const WearLifeResult second_life = second.life({.wear_coefficient_scale = 1.2});
  EXPECT_NE(second_life.life_cycles, first_life.life_cycles);
  EXPECT_NE(second.nominal_contact_ratio(), first.nominal_contact_ratio());
  expect_same_life(second_life, WearModel(d, {.reuse_nominal_start = false}).life({.wear_coefficient_scale = 1.2}),
                   "second design");
  const WearModel moved(std::move(first));
  expect_same_life(moved.life({.wear_coefficient_scale = 1.2}), first_life, "moved model");
}

}  // namespace
}  // namespace rackopt
