// MarkedMap: a section with its allowed keys. An unknown key is refused at
// its own mark with "did you mean" and the allowed list; a missing key is
// reported at the map; an absent or empty section has every key absent.
#include <gtest/gtest.h>

#include <string>

#include "marked_yaml_test_support.hpp"
#include "rackopt/marked_yaml/marked_map.hpp"

namespace rackopt {
namespace {

const std::vector<std::string> kPinionKeys = {"teeth", "module", "face_width"};

TEST(MarkedMap, UnknownKeyGetsDidYouMeanAndTheAllowedKeys) {
  const MarkedNode root = parse_marked_yaml("pinion:\n  teeth: 20\n  modul: 10 mm\n", "t.yaml");
  const auto make = [&] { MarkedMap(root.find("pinion"), "pinion", root.mark, kPinionKeys); };
  test::expect_input_error(make, 3, 3, "pinion.modul", "unknown key 'modul' in pinion; did you mean 'module'?");
  test::expect_input_error(make, 3, 3, "pinion.modul", "Allowed keys: teeth, module, face_width");
}

TEST(MarkedMap, UnknownTopLevelKeyWithoutANearMiss) {
  const MarkedNode root = parse_marked_yaml("zzzzzz: 1\n", "t.yaml");
  const auto make = [&] { MarkedMap(&root, "", root.mark, {"pinion", "rack"}); };
  test::expect_input_error(make, 1, 1, "zzzzzz", "unknown key 'zzzzzz' at the top level Allowed keys: pinion, rack");
}

TEST(MarkedMap, NotAMapNamesTheKeysAndTheExample) {
  const MarkedNode root = parse_marked_yaml("pinion: [1, 2]\n", "t.yaml");
  const auto make = [&] { MarkedMap(root.find("pinion"), "pinion", root.mark, kPinionKeys, "{teeth: 20}"); };
  test::expect_input_error(make, 1, 9, "pinion",
                           "expected a map of keys (teeth, module, face_width), e.g. {teeth: 20}, found a list");
}

TEST(MarkedMap, MissingKeyIsReportedAtTheMap) {
  const MarkedNode root = parse_marked_yaml("pinion:\n  teeth: 20\n", "t.yaml");
  const MarkedMap pinion(root.find("pinion"), "pinion", root.mark, kPinionKeys);
  EXPECT_TRUE(pinion.present());
  EXPECT_TRUE(pinion.has("teeth"));
  EXPECT_FALSE(pinion.has("module"));
  EXPECT_EQ(pinion.child_path("module"), "pinion.module");
  test::expect_input_error([&] { pinion.missing("module", "a length"); }, 2, 3, "pinion.module",
                           "required key 'module' is missing; expected a length");
}

TEST(MarkedMap, AbsentSectionPointsAtTheFallback) {
  const MarkedNode root = parse_marked_yaml("rack: {span: 2 m}\npinion:\n", "t.yaml");
  const MarkedMap pinion(root.find("pinion"), "pinion", root.entries[1].key_mark, kPinionKeys);
  EXPECT_FALSE(pinion.present());
  EXPECT_FALSE(pinion.has("teeth"));
  EXPECT_EQ(pinion.text("teeth", "none"), "none");
  test::expect_input_error([&] { pinion.missing("teeth", "a whole number"); }, 2, 1, "pinion.teeth",
                           "required key 'teeth' is missing");
}

TEST(MarkedMap, SwitchesAndTheirMessage) {
  const MarkedNode root = parse_marked_yaml("a: On\nb: no\nc: maybe\nd: [1]\n", "t.yaml");
  const MarkedMap m(&root, "", root.mark, {"a", "b", "c", "d", "e"});
  EXPECT_TRUE(m.flag("a", false));
  EXPECT_FALSE(m.flag("b", true));
  EXPECT_TRUE(m.flag("e", true));
  test::expect_input_error([&] { m.flag("c", true); }, 3, 4, "c", "'maybe' is not a switch; allowed: on, off");
  test::expect_input_error([&] { m.flag("d", true); }, 4, 4, "d", "expected on or off, found a list");
}

}  // namespace
}  // namespace rackopt
