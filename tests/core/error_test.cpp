#include "rackopt/core/error.hpp"

#include <gtest/gtest.h>

namespace rackopt {
namespace {

TEST(InputError, FormatsFileLineColumnAndKey) {
  InputError e({"problems/x.yaml", 12, 5}, "pinion.module", "expected a length");
  EXPECT_STREQ(e.what(), "problems/x.yaml:12:5: pinion.module: expected a length");
  EXPECT_EQ(e.mark().line, 12);
}

TEST(InputError, CommandLineValueHasNoLine) {
  InputError e({"<command line>", 0, 0}, "rack.span", "bad unit");
  EXPECT_STREQ(e.what(), "<command line>: rack.span: bad unit");
}

TEST(DesignError, KeepsCode) {
  DesignError e("pointed_tooth", "tip thickness -0.1 mm");
  EXPECT_EQ(e.code(), "pointed_tooth");
}

}  // namespace
}  // namespace rackopt
