// One map of a marked YAML tree (a problem section, a study section) as the
// loaders read it: unknown keys are refused on construction with "did you
// mean" and the allowed list, values are read as scalars with their marks,
// missing keys are reported at the map's own mark. SectionReader
// (section_reader.hpp) adds the typed readers both loaders use, so both
// files give the same errors for the same mistakes.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/core/text.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"

namespace rackopt {

// The rule that proposes a key for a mistyped one (closest_name by default).
using NameSuggester = std::optional<std::string> (*)(std::string_view word, const std::vector<std::string>& candidates);

class MarkedMap {
 public:
  // `node` may be nullptr or null (section absent or empty): then every key
  // is absent and errors point at `fallback` (the parent's mark). Throws
  // InputError when the node is not a map ("expected a map of keys (...)",
  // with `example` when given) or holds a key not in `allowed`. An empty
  // `allowed` accepts any key (free-form names: materials, variants).
  MarkedMap(const MarkedNode* node, std::string path, const SourceMark& fallback, std::vector<std::string> allowed,
            const std::string& example = {}, NameSuggester suggest = nullptr);

  const MarkedNode* node() const { return node_; }
  bool present() const { return node_ != nullptr; }
  const SourceMark& mark() const { return mark_; }
  const std::string& path() const { return path_; }
  std::string child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  // Present and not null.
  const MarkedNode* get(const std::string& key) const;
  bool has(const std::string& key) const { return get(key) != nullptr; }
  // Where the key is written, else the map's mark.
  SourceMark key_mark(const std::string& key) const;
  // Where the value is written, else where the key is, else the map.
  SourceMark value_mark(const std::string& key) const;

  [[noreturn]] void missing(const std::string& key, const std::string& expected) const;

  // The scalar text of `key` with its mark; nullopt when absent (a key written
  // with an empty value, `key:` or `key: ~`, is absent). `expected` names the
  // kind for the message when the value is a map or a list.
  std::optional<std::pair<std::string, SourceMark>> scalar(const std::string& key, const std::string& expected) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  // on/off (also true/false, yes/no, any case).
  bool flag(const std::string& key, bool fallback) const;

 private:
  const MarkedNode* node_;
  std::string path_;
  SourceMark mark_;
  std::vector<std::string> allowed_;
};

}  // namespace rackopt
