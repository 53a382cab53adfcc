// The one thread pool (core/parallel_for.hpp): every index once, results by
// index whatever the thread count, the first exception after joining.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <stdexcept>
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
