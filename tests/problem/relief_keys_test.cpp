// Profile relief keys (pinion/rack tip_relief and root_relief): units,
// the module-relative length, defaults, errors with file:line:column,
// overrides and design variables.
//
// Expected numbers are hand arithmetic written next to the assertion.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "problem_test_support.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt {
namespace {

using test::kMinimal;

void expect_error_at(const std::string& text, int line, int column, const std::string& key, const std::string& fragment) {
  test::expect_error(text, {line, column, key, fragment});
}

TEST(ReliefKeys, DefaultIsNone) {
  const Drive d = load_problem_text(kMinimal, "t.yaml");
  for (const ProfileRelief* r : {&d.pinion.tip_relief, &d.pinion.root_relief, &d.rack.tip_relief, &d.rack.root_relief}) {
    EXPECT_FALSE(r->active());
    EXPECT_EQ(r->amount, 0.0);
  }
}

TEST(ReliefKeys, UnitsModuleRelativeLengthAndShape) {
  const Drive d = load_problem_text(
      "pinion:\n  teeth: 20\n  module: 10 mm\n  face_width: 50 mm\n"
      "  tip_relief: {amount: 20 um, length: 0.3, shape: parabolic}\n"
      "  root_relief: {amount: 0.015, length: 4 mm}\n"
      "rack:\n  body_height: 80 mm\n  span: 2 m\n"
      "  tip_relief: {amount: 12 um, length: 0.5}\n"
      "load:\n  force: 10 kN\n",
      "t.yaml");
  EXPECT_DOUBLE_EQ(d.pinion.tip_relief.amount, 20e-6);
  EXPECT_DOUBLE_EQ(d.pinion.tip_relief.length, 0.3 * 0.010);  // 0.3 m_n = 3 mm
  EXPECT_EQ(d.pinion.tip_relief.shape, ProfileRelief::Shape::kParabolic);
  EXPECT_DOUBLE_EQ(d.pinion.root_relief.amount, 15e-6);         // bare number: mm
  EXPECT_DOUBLE_EQ(d.pinion.root_relief.length, 4e-3);          // with its unit: a length
  EXPECT_EQ(d.pinion.root_relief.shape, ProfileRelief::Shape::kLinear);
  EXPECT_DOUBLE_EQ(d.rack.tip_relief.amount, 12e-6);
  EXPECT_DOUBLE_EQ(d.rack.tip_relief.length, 5e-3);
  EXPECT_FALSE(d.rack.root_relief.active());
}

TEST(ReliefKeys, Errors) {
  const std::string head = "pinion:\n  teeth: 20\n  module: 10 mm\n  face_width: 50 mm\n";  // lines 1-4
  const std::string tail = "rack:\n  body_height: 80 mm\n  span: 2 m\nload:\n  force: 10 kN\n";
  // line 5
  expect_error_at(head + "  tip_relief: {amount: -5 um, length: 0.3}\n" + tail, 5, 24, "pinion.tip_relief.amount",
                  "amount");
  expect_error_at(head + "  tip_relief: {amount: 2 mm, length: 0.3}\n" + tail, 5, 24, "pinion.tip_relief.amount",
                  "a tenth of the module");
  expect_error_at(head + "  tip_relief: {amount: 20 um}\n" + tail, 5, 15, "pinion.tip_relief.length",
                  "multiple of the module");
  expect_error_at(head + "  tip_relief: {amount: 20 um, length: 0}\n" + tail, 5, 39, "pinion.tip_relief.length",
                  "0 < length");
  expect_error_at(head + "  tip_relief: {amount: 20 um, length: 80 mm}\n" + tail, 5, 39, "pinion.tip_relief.length",
                  "multiples of the module");
  expect_error_at(head + "  tip_relief: {amount: 20 um, length: 3 deg}\n" + tail, 5, 39, "pinion.tip_relief.length",
                  "length");
  expect_error_at(head + "  tip_relief: {amount: 20 um, length: 0.3, shape: round}\n" + tail, 5, 51,
                  "pinion.tip_relief.shape", "linear | parabolic");
  expect_error_at(head + "  tip_relief: {amount: 20 um, lenght: 0.3}\n" + tail, 5, 31, "pinion.tip_relief.lenght",
                  "did you mean 'length'");
  expect_error_at(head + "  tip_relief: 20 um\n" + tail, 5, 15, "pinion.tip_relief", "map");
  expect_error_at(head + "rack:\n  body_height: 80 mm\n  span: 2 m\n  root_relief: {amount: 20 um, length: 0.3, shape: x}\n"
                         "load:\n  force: 10 kN\n",
                  8, 52, "rack.root_relief.shape", "linear | parabolic");
}

TEST(ReliefKeys, OverridesAndDesignVariables) {
  const Drive d = load_problem_text(kMinimal, "t.yaml",
                                    {"pinion.tip_relief.amount=25 um", "pinion.tip_relief.length=0.4"});
  EXPECT_DOUBLE_EQ(d.pinion.tip_relief.amount, 25e-6);
  EXPECT_DOUBLE_EQ(d.pinion.tip_relief.length, 4e-3);
  EXPECT_EQ(problem_key_kind("pinion.tip_relief.amount"), QuantityKind::kLength);
  EXPECT_EQ(problem_key_kind("rack.root_relief.length"), QuantityKind::kDimensionless);
  EXPECT_EQ(problem_key_kind("pinion.tip_relief.shape"), std::nullopt);
  // A study varies amount (SI) and length (multiple of the module): the
  // length follows the module.
  const ProblemTree tree = load_problem_tree(kMinimal, "t.yaml", {"pinion.tip_relief.amount=10 um",
                                                               "pinion.tip_relief.length=0.3"});
  const std::vector<std::pair<std::string, double>> x{
      {"pinion.tip_relief.amount", 30e-6}, {"pinion.tip_relief.length", 0.5}, {"pinion.module", 0.02}};
  const Drive v = drive_with_values(tree, x);
  EXPECT_DOUBLE_EQ(v.pinion.tip_relief.amount, 30e-6);
  EXPECT_DOUBLE_EQ(v.pinion.tip_relief.length, 0.5 * 0.02);  // 10 mm
}

}  // namespace
}  // namespace rackopt
