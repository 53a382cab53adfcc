#include "rackopt/core/sobol_sequence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace rackopt {
namespace {

// The first 2^m points (origin included) of a Sobol dimension are a (0, m, 1)
// net: exactly one point in each interval [j / 2^m, (j + 1) / 2^m).
TEST(SobolSequence, EachDimensionStratifiesPowersOfTwo) {
  const std::size_t dims = 5, n = 64;
  const std::vector<std::uint32_t> k = sobol_numerators(0, n, dims);
  ASSERT_EQ(k.size(), n * dims);
  for (std::size_t d = 0; d < dims; ++d) {
    EXPECT_EQ(k[d], 0u) << "index 0 is the origin";
    std::set<std::uint32_t> cells;
    for (std::size_t i = 0; i < n; ++i) cells.insert(k[i * dims + d] >> (kSobolBits - 6));
    EXPECT_EQ(cells.size(), n) << "dimension " << d;
  }
  // Dimension 0 is the van der Corput sequence in Gray-code order: 1/2, 3/4, 1/4.
  EXPECT_EQ(k[1 * dims], 1u << 29);
  EXPECT_EQ(k[2 * dims], 3u << 28);
  EXPECT_EQ(k[3 * dims], 1u << 28);
}

TEST(SobolSequence, AnOffsetIsTheSameSequenceLater) {
  const std::vector<std::uint32_t> all = sobol_numerators(0, 20, 3);
  const std::vector<std::uint32_t> later = sobol_numerators(7, 13, 3);
  EXPECT_TRUE(std::equal(later.begin(), later.end(), all.begin() + 7 * 3));
  EXPECT_TRUE(sobol_numerators(5, 0, 3).empty());
}

TEST(SobolSequence, RefusesWhatGslCannotGive) {
  EXPECT_EQ(sobol_max_dimension(), 40u);
  EXPECT_THROW(sobol_numerators(0, 4, 0), std::invalid_argument);
  EXPECT_THROW(sobol_numerators(0, 4, 41), std::invalid_argument);
  EXPECT_THROW(sobol_numerators(kSobolMaxIndex, 2, 1), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt
