// The one "did you mean" rule every loader uses.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rackopt/core/suggest.hpp"

namespace rackopt {
namespace {

TEST(EditDistance, TextbookValues) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // k->s, e->i, +g
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("flaw", "lawn"), 2u);
  EXPECT_EQ(edit_distance("same", "same"), 0u);
  EXPECT_EQ(edit_distance("Span", "span"), 1u);  // case counts here
}

TEST(ClosestName, NearMissesOnlyIgnoringCase) {
  const std::vector<std::string> keys{"module", "pressure_angle", "face_width"};
  EXPECT_EQ(closest_name("modul", keys), "module");
  EXPECT_EQ(closest_name("PRESSURE_ANGEL", keys), "pressure_angle");  // distance 2 after lowering
  // Threshold max(2, len/3): "xyz" is at least 5 edits from every key.
  EXPECT_FALSE(closest_name("xyz", keys));
  EXPECT_FALSE(closest_name("anything", {}));
  // Ties go to the first candidate.
  EXPECT_EQ(closest_name("ab", {"aa", "bb"}), "aa");
}

}  // namespace
}  // namespace rackopt
