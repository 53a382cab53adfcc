#include "rackopt/problem/problem_loader.hpp"

#include <optional>
#include <utility>

#include "rackopt/core/text.hpp"
#include "rackopt/marked_yaml/input_file.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"
#include "rackopt/problem/drive_sections.hpp"
#include "rackopt/problem/random_input_keys.hpp"

namespace rackopt {
namespace {

bool is_variant_assignment(const std::string& assignment) {
  const std::string key = override_key(assignment);
  return key == "variant" || key.rfind("variants.", 0) == 0 || key == "variants";
}

// The file's tree with overrides applied, split into base / variants.
struct ParsedProblem {
  MarkedNode base;  // without `variant` / `variants`
  std::vector<MarkedEntry> variants;
  std::optional<std::pair<std::string, SourceMark>> selected;
  SourceMark variants_mark;
};

ParsedProblem parse_problem(MarkedNode root, const std::string& file, const std::vector<std::string>& overrides) {
  ParsedProblem out;
  out.base = std::move(root);
  if (out.base.is_null()) {
    out.base.type = MarkedNode::Type::kMap;
    out.base.mark = SourceMark{file, 1, 1};
  }
  if (!out.base.is_map()) {
    throw InputError(out.base.mark, "",
                     "a problem file is a map of sections (pinion, rack, load, ...), found " + out.base.type_name());
  }
  // Only the assignments that pick or edit variants go in now; the others are
  // applied after the variant is merged, so that they win over it.
  for (const auto& o : overrides) {
    if (is_variant_assignment(o)) apply_override(out.base, o);
  }

  auto& entries = out.base.entries;
  for (auto it = entries.begin(); it != entries.end();) {
    if (it->key == "variants") {
      out.variants_mark = it->key_mark;
      if (!it->value.is_null()) {
        if (!it->value.is_map()) {
          throw InputError(it->value.mark, "variants",
                           "expected a map of variant name -> partial problem, found " + it->value.type_name());
        }
        out.variants = it->value.entries;
      }
      it = entries.erase(it);
    } else if (it->key == "variant") {
      if (!it->value.is_null()) {
        if (it->value.type != MarkedNode::Type::kScalar) {
          throw InputError(it->value.mark, "variant", "expected a variant name, found " + it->value.type_name());
        }
        out.selected = std::make_pair(it->value.scalar, it->value.mark);
      }
      it = entries.erase(it);
    } else {
      ++it;
    }
  }
  for (const auto& v : out.variants) {
    if (!v.value.is_null() && !v.value.is_map()) {
      throw InputError(v.value.mark, "variants." + v.key,
                       "expected a partial problem (a map such as {faults: [...]}), found " + v.value.type_name());
    }
    for (const auto& inner : v.value.entries) {
      if (inner.key == "variant" || inner.key == "variants") {
        throw InputError(inner.key_mark, "variants." + v.key + "." + inner.key, "variants cannot be nested");
      }
    }
  }
  return out;
}

std::string read_file(const std::string& path) {
  return read_input_file(path, "problem file");
}

}  // namespace

ProblemTree load_problem_tree(const std::string& yaml_text, const std::string& name_for_messages,
                              const std::vector<std::string>& overrides) {
  return load_problem_tree_node(parse_marked_yaml(yaml_text, name_for_messages), name_for_messages, overrides);
}

ProblemTree load_problem_tree_node(MarkedNode root, const std::string& name_for_messages,
                                   const std::vector<std::string>& overrides) {
  ParsedProblem parsed = parse_problem(std::move(root), name_for_messages, overrides);

  // Every variant must be valid, selected or not: a broken variant is a
  // broken file. They are checked with the file's values only.
  for (const auto& v : parsed.variants) {
    MarkedNode merged = parsed.base;
    merge_over(merged, v.value);
    build_drive(merged, name_for_messages);
  }
  auto apply_value_overrides = [&](MarkedNode& tree) {
    for (const auto& o : overrides) {
      if (!is_variant_assignment(o)) apply_override(tree, o);
    }
  };
  ProblemTree out;
  out.file = name_for_messages;
  if (!parsed.selected) {
    apply_value_overrides(parsed.base);
    out.root = std::move(parsed.base);
    return out;
  }

  const auto& [wanted, where] = *parsed.selected;
  for (const auto& v : parsed.variants) {
    if (v.key != wanted) continue;
    out.root = parsed.base;
    merge_over(out.root, v.value);
    apply_value_overrides(out.root);  // ordinary overrides win over the variant's values
    out.variant = wanted;
    return out;
  }
  std::vector<std::string> names;
  for (const auto& v : parsed.variants) names.push_back(v.key);
  throw InputError(where, "variant",
                   "unknown variant '" + wanted + "'; " +
                       (names.empty() ? std::string("this problem defines no variants") : "defined: " + join(names)));
}

Drive drive_from_tree(const ProblemTree& tree) {
  Drive drive = build_drive(tree.root, tree.file);
  if (!tree.variant.empty()) drive.name += " [" + tree.variant + "]";
  return drive;
}

Drive load_problem_text(const std::string& yaml_text, const std::string& name_for_messages,
                        const std::vector<std::string>& overrides) {
  Drive drive = drive_from_tree(load_problem_tree(yaml_text, name_for_messages, overrides));
  check_overrides_against_absolute_inputs(drive, overrides);
  return drive;
}

ProblemTree load_problem_tree_file(const std::string& path, const std::vector<std::string>& overrides) {
  return load_problem_tree(read_file(path), path, overrides);
}

Drive load_problem(const std::string& path, const std::vector<std::string>& overrides) {
  return load_problem_text(read_file(path), path, overrides);
}

std::vector<std::string> problem_variants(const std::string& path) {
  const ParsedProblem parsed = parse_problem(parse_marked_yaml(read_file(path), path), path, {});
  std::vector<std::string> names;
  for (const auto& v : parsed.variants) names.push_back(v.key);
  return names;
}

}  // namespace rackopt
