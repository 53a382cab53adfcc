// SectionReader, the typed reader both loaders use: quantities with units and
// ranges, whole numbers, choices (without case), lists, and the schema rules
// with their messages; absent keys come back as nullopt.
#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <string_view>

#include "marked_yaml_test_support.hpp"
#include "rackopt/marked_yaml/section_reader.hpp"

namespace rackopt {
namespace {

const char* const kGearText =
    "gear:\n"                          // 1
    "  module: 10 mm\n"                // 2
    "  angle: 60 deg\n"                // 3
    "  teeth: 2.5\n"                   // 4
    "  count: 3000000000\n"            // 5
    "  shape: PARABOLIC\n"             // 6
    "  model: linaer\n"                // 7
    "  ratio: 1.5\n"                   // 8
    "  times: \"[40, 55] yr\"\n"       // 9
    "  depths: [0, 1 mm, 2]\n"         // 10
    "  radius: 0\n";                   // 11

const std::vector<std::string> kGearKeys = {"module", "angle", "teeth", "count", "shape", "model",
                                            "ratio", "times", "depths", "radius"};

SectionReader gear_section(const MarkedNode& root, ReaderStyle style = {}) {
  return SectionReader(root.find("gear"), "gear", root.mark, kGearKeys, std::move(style));
}

const NumberRule* gear_rule(std::string_view path) {
  static const NumberRule kModule{QuantityKind::kLength, {0.05e-3, 1.0}};
  static const NumberRule kRadius{QuantityKind::kLength, {1e-6, 1.0}, true};
  if (path == "gear.module") return &kModule;
  if (path == "gear.radius") return &kRadius;
  return nullptr;
}

TEST(SectionReader, QuantitiesInSIWithTheirUnits) {
  const MarkedNode root = parse_marked_yaml(kGearText, "t.yaml");
  const SectionReader gear = gear_section(root);
  EXPECT_DOUBLE_EQ(*gear.quantity("module", QuantityKind::kLength), 0.010);
  EXPECT_NEAR(*gear.quantity("angle", QuantityKind::kAngle), 60 * std::numbers::pi / 180, 1e-15);
  EXPECT_EQ(gear.quantity("absent", QuantityKind::kLength), std::nullopt);
  EXPECT_DOUBLE_EQ(*gear.plain_number("ratio", {.lo = 1, .hi = 2}), 1.5);
}

TEST(SectionReader, RangeMessagesNameTheKeyAndTheLimits) {
  const MarkedNode root = parse_marked_yaml(kGearText, "t.yaml");
  const SectionReader gear = gear_section(root);
  test::expect_input_error(
      [&] { gear.quantity_in("angle", QuantityKind::kAngle, {.lo = 5 * std::numbers::pi / 180, .hi = 45 * std::numbers::pi / 180}); }, 3, 10,
      "gear.angle", "60 deg is out of range; allowed: 5 deg <= angle <= 45 deg");
  test::expect_input_error([&] { gear.plain_number("ratio", {.lo = 2, .lo_open = true}); }, 8, 10, "gear.ratio",
                           "1.5 is out of range; allowed: 2 < ratio");
  test::expect_input_error([&] { gear.quantity("module", QuantityKind::kAngle); }, 2, 11, "gear.module", "mm");
}

TEST(SectionReader, WholeNumbersAndTheirRange) {
  const MarkedNode root = parse_marked_yaml(kGearText, "t.yaml");
  const SectionReader gear = gear_section(root);
  test::expect_input_error([&] { gear.integer("teeth", {.lo = 5, .hi = 1000}); }, 4, 10, "gear.teeth", "whole");
  // Compared before the conversion: out of range, not an overflow.
  test::expect_input_error([&] { gear.integer("count", {.lo = 1, .hi = 100000000}); }, 5, 10, "gear.count",
                           "3000000000 is out of range; allowed: 1 <= count <= 100000000");
  EXPECT_EQ(gear.integer("absent", {.lo = 1, .hi = 2}), std::nullopt);
}

TEST(SectionReader, ChoicesIgnoreCaseAndSuggestANearMiss) {
  const MarkedNode root = parse_marked_yaml(kGearText, "t.yaml");
  const SectionReader gear = gear_section(root);
  EXPECT_EQ(gear.choice("shape", {"linear", "parabolic"}), "parabolic");
  EXPECT_EQ(gear.choice("absent", {"linear", "parabolic"}), std::nullopt);
  test::expect_input_error([&] { gear.choice("model", {"off", "linear", "weber_banaschek"}); }, 7, 10, "gear.model",
                           "'linaer' is not allowed; allowed: off | linear | weber_banaschek (did you mean 'linear'?)");
}

TEST(SectionReader, ListsWithATrailingUnitOrPerItemUnits) {
  const MarkedNode root = parse_marked_yaml(kGearText, "t.yaml");
  const SectionReader gear = gear_section(root);
  const auto times = gear.quantity_list("times", QuantityKind::kTime, {.lo = 0, .lo_open = true});
  ASSERT_EQ(times.size(), 2u);
  EXPECT_DOUBLE_EQ(times[1].si, 55 * 365.25 * 24 * 3600);
  EXPECT_EQ(times[1].path, "gear.times[1]");
  const auto depths = gear.quantity_list("depths", QuantityKind::kLength, {.lo = 0, .hi = 3e-3}, "mm");
  ASSERT_EQ(depths.size(), 3u);
  EXPECT_DOUBLE_EQ(depths[1].si, 1e-3);
  // A bare item is in the bare unit: 2 m.
  test::expect_input_error([&] { gear.quantity_list("depths", QuantityKind::kLength, {.lo = 0, .hi = 3e-3}, "m"); },
                           10, 21, "gear.depths[2]", "2000 mm is out of range; allowed: 0 mm <= depths <= 3 mm");
}

TEST(SectionReader, SchemaRulesWithDefaultsAndZeroAsDefault) {
  const MarkedNode root = parse_marked_yaml(kGearText, "t.yaml");
  ReaderStyle style;
  style.schema = gear_rule;
  style.schema_path = "gear";
  const SectionReader gear = gear_section(root, style);
  EXPECT_DOUBLE_EQ(gear.number("module", std::nullopt), 0.010);
  EXPECT_EQ(gear.number("radius", 0.5), 0.0);  // written 0: the zero_is_default rule lets it through
  test::expect_input_error([&] { gear.check_range("module", 0.5, {.lo = 0, .hi = 0.1}, " (a tenth)"); }, 2, 11,
                           "gear.module", "500 mm is out of range; allowed: 0 mm <= module <= 100 mm (a tenth)");
  const MarkedNode empty = parse_marked_yaml("gear: {}\n", "t.yaml");
  const SectionReader none = gear_section(empty, style);
  EXPECT_DOUBLE_EQ(none.number("module", 0.002), 0.002);
  test::expect_input_error([&] { none.number("module", std::nullopt); }, 1, 7, "gear.module",
                           "required key 'module' is missing; expected a length (e.g. 60 mm)");
}

TEST(SectionReader, StyleSetsTheDigitsOfRangeMessages) {
  const MarkedNode root = parse_marked_yaml("gear:\n  ratio: 1.23456789\n", "t.yaml");
  ReaderStyle ten;
  ten.digits = 10;
  const SectionReader six_digits = gear_section(root);
  const SectionReader ten_digits = gear_section(root, ten);
  test::expect_input_error([&] { six_digits.plain_number("ratio", {.lo = 2}); }, 2, 10, "gear.ratio",
                           "1.23457 is out of range");
  test::expect_input_error([&] { ten_digits.plain_number("ratio", {.lo = 2}); }, 2, 10, "gear.ratio",
                           "1.23456789 is out of range");
}

}  // namespace
}  // namespace rackopt
