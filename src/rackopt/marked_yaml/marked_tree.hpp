// A YAML document as a plain tree that remembers where every key and value
// was written, checked for what yaml-cpp 0.7 lets through silently
// (docs/dependencies.md, "yaml-cpp 0.7"): duplicate keys, merge keys `<<`, alias fan-out and
// deep nesting. The problem loader reads this tree, never yaml-cpp nodes, so
// every error it raises can name file:line:column.
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/marked_yaml/input_limits.hpp"

namespace rackopt {

struct MarkedEntry;

struct MarkedNode {
  enum class Type { kNull, kScalar, kMap, kSequence };
  Type type = Type::kNull;
  std::string scalar;                // kScalar: the text as written (quotes removed)
  SourceMark mark;                   // where the value starts (1-based)
  std::vector<MarkedEntry> entries;  // kMap: in file order, keys unique
  std::vector<MarkedNode> items;     // kSequence

  bool is_map() const { return type == Type::kMap; }
  bool is_null() const { return type == Type::kNull; }
  // The value stored under `key` in a map (nullptr when absent or not a map).
  const MarkedNode* find(const std::string& key) const;
  MarkedNode* find(const std::string& key);
  // "a map", "a list", "a value", "nothing": for "expected X, found Y" messages.
  std::string type_name() const;
};

struct MarkedEntry {
  std::string key;
  SourceMark key_mark;  // where the key is written
  MarkedNode value;
};

// Parses YAML text into a MarkedNode. `file` is used in every mark.
// Throws InputError (file:line:column) for everything load_one_yaml_document
// refuses (marked_yaml/bounded_yaml.hpp: text over kMaxInputBytes, syntax errors,
// more than kMaxTreeNodes nodes or kMaxExpandedTextBytes of text after alias
// expansion, a stray ',', more than one document), nesting deeper than
// kMaxTreeDepth, a key that is
// not a plain scalar, a duplicate key in one map (pointing at the second
// occurrence and naming the first), a merge key `<<`.
// Marks of values given on the command line have line 0 (`from_command_line`).
MarkedNode parse_marked_yaml(const std::string& text, const std::string& file, bool from_command_line = false);

// Applies one `--set` assignment "dotted.key[0].path=value" to `root`.
// The value is read as a YAML scalar or flow value ("1.2 m", "off",
// "{E: 200 GPa, nu: 0.3}"); an empty value or `~` removes the key. Missing
// maps on the path are created (so a key absent from the file can be added;
// whether it is allowed is decided by the schema later); "[n]" indexes a list
// (n == size appends). Marks of created nodes are "<command line>".
// Throws InputError naming "<command line>" and the key path for a malformed
// assignment or a path that runs through a value that is not a map/list.
void apply_override(MarkedNode& root, const std::string& assignment);

// apply_override(root, key_path + "=" + text) for a `text` that YAML reads
// as the plain scalar `text` itself (a number with a unit such as
// "1.25e-3 m"), without parsing it: a study sets every design value this way
// and the YAML parser was a tenth of a stiffness-only design's time. The
// caller guarantees the text needs no quoting; the node and its key get the
// same "<command line>" marks as through apply_override.
void set_plain_scalar(MarkedNode& root, const std::string& key_path, std::string text);

// The key part of an assignment ("rack.span" for "rack.span=1.2 m"), trimmed.
std::string override_key(const std::string& assignment);

// Merges `patch` over `base`: maps merge key by key recursively; anything
// else in the patch (scalar, list, null) replaces the base value.
void merge_over(MarkedNode& base, const MarkedNode& patch);

}  // namespace rackopt
