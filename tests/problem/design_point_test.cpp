#include "rackopt/problem/design_point.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rackopt {
namespace {

const std::string kDir = RACKOPT_SOURCE_DIR;

TEST(DesignPoint, ValuesReachTheDriveBitExactly) {
  const ProblemTree tree = load_problem_tree_file(kDir + "/problems/rack_railway.yaml");
  const double alpha = 0.1 + 0.2 + 0.0012345678901234;  // an angle no unit conversion reproduces by luck
  const std::vector<std::pair<std::string, double>> values{
      {"pinion.pressure_angle", alpha}, {"rack.span", 1.2345678901234567}, {"pinion.teeth", 24}};
  const Drive d = drive_with_values(tree, values);
  EXPECT_EQ(d.pinion.pressure_angle, alpha);
  EXPECT_EQ(d.rack.span, 1.2345678901234567);
  EXPECT_EQ(d.pinion.teeth, 24);
  // The template itself is untouched.
  const Drive original = drive_from_tree(tree);
  EXPECT_NE(original.rack.span, 1.2345678901234567);
}

TEST(DesignPoint, DerivedDefaultsFollowTheDesign) {
  // ship_lift gives no bore radius: the loader's default 0.5 r_f must follow
  // the module (r_f = m (z/2 - h_f* + x)).
  const ProblemTree tree = load_problem_tree_file(kDir + "/problems/ship_lift.yaml");
  const std::vector<std::pair<std::string, double>> values{{"pinion.module", 0.05}};
  const Drive d = drive_with_values(tree, values);
  EXPECT_NEAR(d.pinion.bore_radius, 0.5 * 0.05 * (16 / 2.0 - 1.25 + 0.5), 1e-12);
}

TEST(DesignPoint, LoaderChecksApplyToDesignValues) {
  const ProblemTree tree = load_problem_tree_file(kDir + "/problems/rack_railway.yaml");
  const std::vector<std::pair<std::string, double>> negative{{"pinion.module", -0.01}};
  EXPECT_THROW(drive_with_values(tree, negative), InputError);
  const std::vector<std::pair<std::string, double>> fractional{{"pinion.teeth", 22.5}};
  EXPECT_THROW(drive_with_values(tree, fractional), InputError);
  const std::vector<std::pair<std::string, double>> not_numeric{{"rack.supports", 1.0}};
  try {
    drive_with_values(tree, not_numeric);
    FAIL() << "a non-numeric key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rack.supports"), std::string::npos) << e.what();
  }
}

TEST(DesignPoint, TreeRoundTripEqualsLoadProblem) {
  const std::string path = kDir + "/problems/large_module.yaml";
  const Drive a = load_problem(path, {"variant=severe", "rack.span=1.5 m"});
  const Drive b = drive_from_tree(load_problem_tree_file(path, {"variant=severe", "rack.span=1.5 m"}));
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.rack.span, b.rack.span);
  EXPECT_EQ(a.spalls.size(), b.spalls.size());
  EXPECT_EQ(b.rack.span, 1.5);
}

}  // namespace
}  // namespace rackopt
