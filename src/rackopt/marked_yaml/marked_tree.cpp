#include "rackopt/marked_yaml/marked_tree.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>

#include "rackopt/marked_yaml/bounded_yaml.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {

const MarkedNode* MarkedNode::find(const std::string& key) const {
  if (type != Type::kMap) return nullptr;
  for (const auto& e : entries) {
    if (e.key == key) return &e.value;
  }
  return nullptr;
}

MarkedNode* MarkedNode::find(const std::string& key) {
  return const_cast<MarkedNode*>(static_cast<const MarkedNode*>(this)->find(key));
}

std::string MarkedNode::type_name() const {
  switch (type) {
    case Type::kNull: return "nothing";
    case Type::kScalar: return "the value '" + scalar + "'";
    case Type::kMap: return "a map";
    case Type::kSequence: return "a list";
  }
  return "?";
}

namespace {

const char* const kCommandLine = "<command line>";

struct Converter {
  std::string file;
  bool command_line = false;
  int nodes = 0;

  SourceMark mark_of(const YAML::Mark& m) const {
    if (command_line || m.line < 0) return SourceMark{file, 0, 0};
    return SourceMark{file, m.line + 1, m.column + 1};
  }

  MarkedNode convert(const YAML::Node& node, const SourceMark& fallback, int depth, const std::string& path) {
    if (++nodes > kMaxTreeNodes) {
      throw InputError(fallback, "",
                       "the document expands to more than " + std::to_string(kMaxTreeNodes) +
                           " nodes (alias fan-out?); a problem file needs a few hundred");
    }
    if (depth > kMaxTreeDepth) {
      throw InputError(fallback, "",
                       "nesting deeper than " + std::to_string(kMaxTreeDepth) +
                           " levels; a problem file needs at most 5");
    }
    MarkedNode out;
    out.mark = mark_of(node.Mark());
    if (out.mark.line == 0 && !command_line) out.mark = fallback;
    switch (node.Type()) {
      case YAML::NodeType::Undefined:
      case YAML::NodeType::Null:
        out.type = MarkedNode::Type::kNull;
        break;
      case YAML::NodeType::Scalar:
        out.type = MarkedNode::Type::kScalar;
        out.scalar = node.Scalar();
        break;
      case YAML::NodeType::Sequence:
        out.type = MarkedNode::Type::kSequence;
        for (const auto& item : node) {
          const std::string item_path = path + "[" + std::to_string(out.items.size()) + "]";
          out.items.push_back(convert(item, out.mark, depth + 1, item_path));
        }
        break;
      case YAML::NodeType::Map:
        out.type = MarkedNode::Type::kMap;
        for (const auto& kv : node) {
          const SourceMark key_mark = mark_of(kv.first.Mark());
          if (!kv.first.IsScalar()) {
            const char* found = kv.first.IsMap() ? "a map" : kv.first.IsSequence() ? "a list" : "an empty key";
            throw InputError(key_mark, "", std::string("a key must be a plain name, found ") + found);
          }
          const std::string key = kv.first.Scalar();
          const std::string key_path = path.empty() ? key : path + "." + key;
          if (key == "<<") {
            throw InputError(key_mark, key_path,
                             "YAML merge keys '<<' are not supported (yaml-cpp 0.7 would keep '<<' as "
                             "an ordinary key); write the keys out, or use 'variants' for alternatives");
          }
          for (const auto& seen : out.entries) {
            if (seen.key == key) {
              throw InputError(key_mark, key_path,
                               "duplicate key '" + key + "' (first given at " + to_string(seen.key_mark) +
                                   "); each key may appear once in a map");
            }
          }
          ++nodes;  // the key itself
          out.entries.push_back(MarkedEntry{key, key_mark, convert(kv.second, key_mark, depth + 1, key_path)});
        }
        break;
    }
    return out;
  }
};

// One step of a dotted override path: a map key, or a list index.
struct PathStep {
  std::string key;
  int index = -1;  // >= 0 for "[n]"
};

std::vector<PathStep> split_path(const std::string& path) {
  const SourceMark where{kCommandLine, 0, 0};
  std::vector<PathStep> steps;
  std::string current;
  auto flush_key = [&](bool required) {
    if (current.empty()) {
      if (required) throw InputError(where, path, "empty key name in the path of a --set assignment");
      return;
    }
    steps.push_back(PathStep{current, -1});
    current.clear();
  };
  for (std::size_t i = 0; i < path.size(); ++i) {
    const char c = path[i];
    if (c == '.') {
      flush_key(steps.empty() || steps.back().index < 0);
    } else if (c == '[') {
      flush_key(steps.empty());
      const std::size_t close = path.find(']', i);
      const std::string digits = close == std::string::npos ? "" : path.substr(i + 1, close - i - 1);
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 6) {
        throw InputError(where, path, "a list index must be written [n] with a whole number n >= 0");
      }
      steps.push_back(PathStep{"", std::stoi(digits)});
      i = close;
    } else {
      current += c;
    }
  }
  flush_key(steps.empty() || steps.back().index < 0);  // "faults[0]" ends on an index
  return steps;
}

std::string path_prefix(const std::vector<PathStep>& steps, std::size_t count) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) {
    if (steps[i].index >= 0) {
      out += "[" + std::to_string(steps[i].index) + "]";
    } else {
      if (!out.empty()) out += ".";
      out += steps[i].key;
    }
  }
  return out;
}

}  // namespace

MarkedNode parse_marked_yaml(const std::string& text, const std::string& file, bool from_command_line) {
  const YAML::Node document = load_one_yaml_document(text, file, from_command_line);
  Converter converter{file, from_command_line, 0};
  const SourceMark start = from_command_line ? SourceMark{file, 0, 0} : SourceMark{file, 1, 1};
  if (!document.IsDefined() || document.IsNull()) {
    MarkedNode empty;
    empty.mark = start;
    if (document.IsDefined()) empty.mark = converter.mark_of(document.Mark());
    if (empty.mark.line == 0 && !from_command_line) empty.mark = start;
    return empty;
  }
  return converter.convert(document, start, 0, "");
}

std::string override_key(const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  return trim(eq == std::string::npos ? assignment : assignment.substr(0, eq));
}

namespace {

// Puts `value` at `path` as a --set assignment does (a null value removes the key).
void set_at_path(MarkedNode& root, const std::string& path, MarkedNode value) {
  const SourceMark where{kCommandLine, 0, 0};
  const std::vector<PathStep> steps = split_path(path);
  const bool remove = value.is_null();

  MarkedNode* node = &root;
  if (node->is_null()) {
    node->type = MarkedNode::Type::kMap;
  }
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const PathStep& step = steps[i];
    const bool last = i + 1 == steps.size();
    if (step.index >= 0) {
      if (node->is_null()) node->type = MarkedNode::Type::kSequence;  // "faults[0].x=" on a file without faults
      if (node->type != MarkedNode::Type::kSequence) {
        throw InputError(where, path,
                         "'" + path_prefix(steps, i) + "' is " + node->type_name() + ", not a list: cannot index it");
      }
      const auto n = static_cast<int>(node->items.size());
      if (step.index > n || (step.index == n && remove)) {
        throw InputError(where, path,
                         "index " + std::to_string(step.index) + " is past the end of '" + path_prefix(steps, i) +
                             "' (" + std::to_string(n) + " items)");
      }
      if (last && remove) {
        node->items.erase(node->items.begin() + step.index);
        return;
      }
      if (step.index == n) {
        MarkedNode fresh;
        fresh.mark = where;
        node->items.push_back(fresh);
      }
      node = &node->items[static_cast<std::size_t>(step.index)];
    } else {
      if (node->is_null()) {
        node->type = MarkedNode::Type::kMap;
        node->mark = where;
      }
      if (!node->is_map()) {
        throw InputError(where, path,
                         "'" + path_prefix(steps, i) + "' is " + node->type_name() + ", not a map: cannot set '" +
                             step.key + "' in it");
      }
      if (last && remove) {
        auto& entries = node->entries;
        for (auto it = entries.begin(); it != entries.end(); ++it) {
          if (it->key == step.key) {
            entries.erase(it);
            break;
          }
        }
        return;
      }
      MarkedNode* child = node->find(step.key);
      if (child == nullptr) {
        MarkedNode fresh;
        fresh.mark = where;
        node->entries.push_back(MarkedEntry{step.key, where, fresh});
        child = &node->entries.back().value;
      } else {
        // The key now comes from the command line: errors about it must say so.
        for (auto& e : node->entries) {
          if (e.key == step.key && last) e.key_mark = where;
        }
      }
      node = child;
    }
  }
  *node = std::move(value);
}

}  // namespace

void apply_override(MarkedNode& root, const std::string& assignment) {
  const SourceMark where{kCommandLine, 0, 0};
  const std::size_t eq = assignment.find('=');
  const std::string path = override_key(assignment);
  if (eq == std::string::npos) {
    throw InputError(where, path,
                     "'" + assignment + "' is not an assignment; write --set key.path=value, e.g. "
                     "--set rack.span=\"1.2 m\"");
  }
  if (path.empty()) throw InputError(where, "", "'" + assignment + "': no key before '='");
  set_at_path(root, path, parse_marked_yaml(assignment.substr(eq + 1), kCommandLine, true));
}

void set_plain_scalar(MarkedNode& root, const std::string& key_path, std::string text) {
  MarkedNode value;
  value.type = MarkedNode::Type::kScalar;
  value.scalar = std::move(text);
  value.mark = SourceMark{kCommandLine, 0, 0};
  set_at_path(root, key_path, std::move(value));
}

void merge_over(MarkedNode& base, const MarkedNode& patch) {
  if (!base.is_map() || !patch.is_map()) {
    base = patch;
    return;
  }
  for (const auto& e : patch.entries) {
    MarkedNode* existing = base.find(e.key);
    if (existing == nullptr) {
      base.entries.push_back(e);
    } else {
      merge_over(*existing, e.value);
      for (auto& be : base.entries) {
        if (be.key == e.key) be.key_mark = e.key_mark;
      }
    }
  }
}

}  // namespace rackopt
