// A Monte Carlo computed in shares (what the ranks of an MPI job do: each
// runs the same set-up and its own contiguous samples, joined in order) gives
// the run of one process bit for bit: every life, criterion and the summary.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "life_test_drives.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt {
namespace {

WearReliabilityOptions shares_options(bool life_table) {
  WearReliabilityOptions o;
  o.samples = 60;
  o.life_table = life_table;
  o.threads = 2;
  o.bootstrap_replicates = 20;
  return o;
}

// Shares of `parts` processes: the first computed by the run itself
// (`here`), the others by separate runs with sample_share.
WearReliabilityResult run_in_shares(const Drive& d, WearReliabilityOptions o, unsigned parts,
                                    std::vector<std::size_t>& share_sizes) {
  o.sample_executor = [&, o](std::size_t n, const WearReliabilityOptions::SamplesHere& here) {
    SampleLives all = here(0, n / parts);
    share_sizes.push_back(all.lives.size());
    for (unsigned p = 1; p < parts; ++p) {
      WearReliabilityOptions share = o;
      share.sample_executor = nullptr;
      share.sample_share = std::make_pair(n * p / parts, n * (p + 1) / parts);
      const WearReliabilityResult r = run_wear_reliability(d, share);
      EXPECT_TRUE(r.share_lives);
      EXPECT_TRUE(r.lives.empty());  // a share has no summary of its own
      const SampleLives& s = *r.share_lives;
      share_sizes.push_back(s.lives.size());
      all.lives.insert(all.lives.end(), s.lives.begin(), s.lives.end());
      all.criteria.insert(all.criteria.end(), s.criteria.begin(), s.criteria.end());
      all.interpolated += s.interpolated;
    }
    all.processes = parts;
    return all;
  };
  return run_wear_reliability(d, o);
}

void expect_same_run(const WearReliabilityResult& a, const WearReliabilityResult& b) {
  EXPECT_EQ(a.summary.samples_fitted, b.summary.samples_fitted);
  EXPECT_EQ(a.summary.chosen, b.summary.chosen);
  ASSERT_EQ(a.lives.size(), b.lives.size());
  for (std::size_t i = 0; i < a.lives.size(); ++i) {
    EXPECT_EQ(a.lives[i].status, b.lives[i].status) << i;
    EXPECT_EQ(a.lives[i].value, b.lives[i].value) << i;
    EXPECT_EQ(a.lives[i].message, b.lives[i].message) << i;
  }
  EXPECT_EQ(a.criteria, b.criteria);
  EXPECT_EQ(a.table.samples_interpolated, b.table.samples_interpolated);
  ASSERT_EQ(a.summary.life.size(), b.summary.life.size());
  for (std::size_t k = 0; k < a.summary.life.size(); ++k) {
    EXPECT_EQ(a.summary.life[k].empirical.estimate, b.summary.life[k].empirical.estimate);
    ASSERT_EQ(a.summary.life[k].fit.has_value(), b.summary.life[k].fit.has_value());
    if (a.summary.life[k].fit) {
      EXPECT_EQ(a.summary.life[k].fit->estimate, b.summary.life[k].fit->estimate);
    }
  }
}

TEST(SampleShares, SharesJoinedInOrderGiveTheRunOfOneProcess) {
  for (bool table : {true, false}) {
    SCOPED_TRACE(table ? "life table" : "one model life per sample");
    const Drive d = test::ship_lift_fixed_profile();  // one input: the contact ratio
    const WearReliabilityResult one = run_wear_reliability(d, shares_options(table));
    std::vector<std::size_t> sizes;
    const WearReliabilityResult three = run_in_shares(d, shares_options(table), 3, sizes);
    EXPECT_EQ(sizes, (std::vector<std::size_t>{20, 20, 20}));
    EXPECT_EQ(three.processes_used, 3u);
    EXPECT_EQ(one.processes_used, 1u);
    expect_same_run(one, three);
    if (table) {
      EXPECT_GT(three.table.samples_interpolated, 0u);
    }
  }
}

TEST(SampleShares, AShareBeyondTheSamplesIsEmpty) {
  const Drive d = test::ship_lift_fixed_profile();
  WearReliabilityOptions o = shares_options(true);
  o.sample_share = std::make_pair(std::size_t{100}, std::size_t{200});  // 60 samples
  const WearReliabilityResult r = run_wear_reliability(d, o);
  ASSERT_TRUE(r.share_lives);
  EXPECT_TRUE(r.share_lives->lives.empty());
  EXPECT_TRUE(r.share_lives->criteria.empty());
}

}  // namespace
}  // namespace rackopt
