// MarkedTree: every key and value keeps the line and column it was written
// at, nested maps and lists included; what yaml-cpp lets through silently
// (duplicate keys, merge keys) is refused with a mark.
#include <gtest/gtest.h>

#include <string>

#include "marked_yaml_test_support.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"

namespace rackopt {
namespace {

bool same_mark(const SourceMark& a, const SourceMark& b) {
  return a.file == b.file && a.line == b.line && a.column == b.column;
}

bool same_tree(const MarkedNode& a, const MarkedNode& b) {
  if (a.type != b.type || a.scalar != b.scalar || !same_mark(a.mark, b.mark)) return false;
  if (a.entries.size() != b.entries.size() || a.items.size() != b.items.size()) return false;
  for (std::size_t i = 0; i < a.entries.size(); ++i) {
    const MarkedEntry &x = a.entries[i], &y = b.entries[i];
    if (x.key != y.key || !same_mark(x.key_mark, y.key_mark) || !same_tree(x.value, y.value)) return false;
  }
  for (std::size_t i = 0; i < a.items.size(); ++i) {
    if (!same_tree(a.items[i], b.items[i])) return false;
  }
  return true;
}

const char* const kNested =
    "pinion:\n"                     // 1
    "  teeth: 20\n"                 // 2
    "  tip_relief:\n"               // 3
    "    amount: 20 um\n"           // 4
    "faults:\n"                     // 5
    "  - {type: spall, tooth: 3}\n"  // 6
    "  - type: spall\n"             // 7
    "    tooth: 4\n";               // 8

TEST(MarkedTree, NestedKeysAndValuesKeepTheirLineAndColumn) {
  const MarkedNode root = parse_marked_yaml(kNested, "t.yaml");
  ASSERT_TRUE(root.is_map());
  ASSERT_EQ(root.entries.size(), 2u);
  EXPECT_EQ(root.entries[0].key, "pinion");
  EXPECT_EQ(root.entries[0].key_mark.line, 1);
  EXPECT_EQ(root.entries[0].key_mark.column, 1);

  const MarkedNode* teeth = root.find("pinion")->find("teeth");
  ASSERT_NE(teeth, nullptr);
  EXPECT_EQ(teeth->scalar, "20");
  EXPECT_EQ(teeth->mark.file, "t.yaml");
  EXPECT_EQ(teeth->mark.line, 2);
  EXPECT_EQ(teeth->mark.column, 10);

  const MarkedNode* amount = root.find("pinion")->find("tip_relief")->find("amount");
  ASSERT_NE(amount, nullptr);
  EXPECT_EQ(amount->scalar, "20 um");
  EXPECT_EQ(amount->mark.line, 4);
  EXPECT_EQ(amount->mark.column, 13);
  const MarkedEntry& amount_entry = root.find("pinion")->find("tip_relief")->entries.front();
  EXPECT_EQ(amount_entry.key_mark.line, 4);
  EXPECT_EQ(amount_entry.key_mark.column, 5);
}

TEST(MarkedTree, ListItemsFlowAndBlockKeepTheirMarks) {
  const MarkedNode root = parse_marked_yaml(kNested, "t.yaml");
  const MarkedNode* faults = root.find("faults");
  ASSERT_NE(faults, nullptr);
  ASSERT_EQ(faults->type, MarkedNode::Type::kSequence);
  ASSERT_EQ(faults->items.size(), 2u);
  // A flow map item starts at its '{'; its values where they are written.
  EXPECT_EQ(faults->items[0].mark.line, 6);
  EXPECT_EQ(faults->items[0].mark.column, 5);
  EXPECT_EQ(faults->items[0].find("tooth")->mark.column, 26);
  // A block map item: its keys on their own lines.
  EXPECT_EQ(faults->items[1].find("tooth")->mark.line, 8);
  EXPECT_EQ(faults->items[1].find("tooth")->mark.column, 12);
}

TEST(MarkedTree, TypeNamesForMessages) {
  const MarkedNode root = parse_marked_yaml("a: 1\nb: [1]\nc: {d: 1}\ne:\n", "t.yaml");
  EXPECT_EQ(root.find("a")->type_name(), "the value '1'");
  EXPECT_EQ(root.find("b")->type_name(), "a list");
  EXPECT_EQ(root.find("c")->type_name(), "a map");
  EXPECT_TRUE(root.find("e")->is_null());
  EXPECT_EQ(root.find("missing"), nullptr);
}

TEST(MarkedTree, DuplicateKeyPointsAtTheSecond) {
  test::expect_input_error([] { parse_marked_yaml("pinion:\n  teeth: 20\n  teeth: 21\n", "t.yaml"); }, 3, 3,
                           "pinion.teeth", "duplicate");
}

TEST(MarkedTree, OverridesCarryTheCommandLineMark) {
  MarkedNode root = parse_marked_yaml(kNested, "t.yaml");
  apply_override(root, "pinion.module=10 mm");
  const MarkedNode* module = root.find("pinion")->find("module");
  ASSERT_NE(module, nullptr);
  EXPECT_EQ(module->scalar, "10 mm");
  EXPECT_EQ(module->mark.file, "<command line>");
  EXPECT_EQ(override_key(" pinion.module = 10 mm"), "pinion.module");
}

// A design value set without the YAML parser must leave the tree exactly as
// the --set path does: the loader's messages quote these marks.
TEST(MarkedTree, PlainScalarIsTheOverrideWithoutTheParser) {
  for (const char* key : {"pinion.teeth", "pinion.module", "pinion.tip_relief.amount", "faults[1].tooth",
                          "mounting.clearance"}) {
    for (const char* text : {"20", "1.2500000000000001e-02 m", "-3.0000000000000001e-05 m"}) {
      MarkedNode parsed = parse_marked_yaml(kNested, "t.yaml");
      MarkedNode direct = parsed;
      apply_override(parsed, std::string(key) + "=" + text);
      set_plain_scalar(direct, key, text);
      EXPECT_TRUE(same_tree(parsed, direct)) << key << " = " << text;
    }
  }
}

}  // namespace
}  // namespace rackopt
