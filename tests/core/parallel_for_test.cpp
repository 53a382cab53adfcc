// The one thread pool (core/parallel_for.hpp): every index once, results by
// index whatever the thread count, the lowest failing index after joining,
// stop and progress.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "rackopt/core/parallel_for.hpp"

namespace rackopt {
namespace {

TEST(ParallelFor, EveryIndexOnceForAnyThreadCount) {
  for (unsigned threads : {0u, 1u, 2u, 7u, 64u}) {
    std::vector<int> hits(257, 0);
    std::atomic<int> calls{0};
    parallel_for(hits.size(), threads, [&](std::size_t i) {
      ++hits[i];
      ++calls;
    });
    EXPECT_EQ(calls.load(), 257) << threads;
    for (int h : hits) ASSERT_EQ(h, 1) << threads;
  }
}

TEST(ParallelFor, RethrowsAfterJoining) {
  std::vector<int> out(1000, 0);
  EXPECT_THROW(parallel_for(1000, 4,
                            [&](std::size_t i) {
                              if (i == 500) throw std::runtime_error("x");
                              out[i] = 1;
                            }),
               std::runtime_error);
  EXPECT_NO_THROW(parallel_for(0, 4, [](std::size_t) {}));
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// Several jobs fail: the lowest failing index is reported on any thread
// count (the jobs handed out before the first failure all finish).
TEST(ParallelFor, TheLowestFailingIndexIsRethrown) {
  for (unsigned threads : {1u, 2u, 4u}) {
    try {
      parallel_for(40, threads, [](std::size_t i) {
        if (i == 3 || i == 5) throw std::runtime_error("job " + std::to_string(i));
      });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "job 3") << threads << " threads";
    }
  }
}

TEST(ParallelFor, AStopHandsOutNoMoreJobsAndProgressCountsEachOnce) {
  std::atomic<std::size_t> started{0};
  std::vector<std::size_t> reported;
  ParallelControl control;
  control.stop = [&] { return started.load() >= 10; };
  control.progress = [&](std::size_t done, std::size_t count) {
    EXPECT_EQ(count, 100u);
    reported.push_back(done);
  };
  parallel_for(100, 2, [&](std::size_t) { ++started; }, control);
  EXPECT_GE(started.load(), 10u);
  EXPECT_LE(started.load(), 11u);  // at most one job per thread was already handed out
  ASSERT_EQ(reported.size(), started.load());
  for (std::size_t k = 0; k < reported.size(); ++k) EXPECT_EQ(reported[k], k + 1);
}

}  // namespace
}  // namespace rackopt
