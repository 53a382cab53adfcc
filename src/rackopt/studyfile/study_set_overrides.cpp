#include "rackopt/studyfile/study_sections.hpp"

#include "rackopt/core/text.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"
#include "rackopt/studyfile/study_section_reader.hpp"

namespace rackopt::studyfile {
namespace {

// `--set` for the two study sections whose keys are dotted problem paths
// (variables, problem_set): "variables.rack.span.upper=3 m" addresses the
// field `upper` of the entry "rack.span" (the longest existing entry that
// fits); "variables.rack.span=[1 m, 3 m]" sets or adds the whole entry.
// apply_override would split the entry key at its dots. Returns false when
// the assignment is not for these sections.
bool apply_dotted_section_override(MarkedNode& root, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos) return false;
  const std::string key = override_key(assignment);
  const std::string value = assignment.substr(eq + 1);
  for (const char* section : {"variables", "problem_set"}) {
    const std::string prefix = std::string(section) + ".";
    if (key.rfind(prefix, 0) != 0 || key.size() == prefix.size()) continue;
    const std::string rest = key.substr(prefix.size());
    MarkedNode* map = root.is_map() ? root.find(section) : nullptr;
    if (map == nullptr || map->is_null()) {
      // Create the section through apply_override (marks "<command line>"),
      // then fall through to add the entry.
      apply_override(root, std::string(section) + "={}");
      map = root.find(section);
    }
    if (!map->is_map()) return false;  // the schema reports the wrong type
    MarkedEntry* best = nullptr;
    for (auto& e : map->entries) {
      if ((rest == e.key || rest.rfind(e.key + ".", 0) == 0) && (best == nullptr || e.key.size() > best->key.size())) {
        best = &e;
      }
    }
    // The entry as a one-key map so that apply_override can edit it.
    MarkedNode holder;
    holder.type = MarkedNode::Type::kMap;
    holder.mark = SourceMark{kCommandLine, 0, 0};
    const std::string entry_key = best != nullptr ? best->key : rest;
    const std::string field =
        best != nullptr && rest.size() > best->key.size() ? "." + rest.substr(best->key.size() + 1) : "";
    holder.entries.push_back(MarkedEntry{"entry", best != nullptr ? best->key_mark : SourceMark{kCommandLine, 0, 0},
                                         best != nullptr ? best->value : MarkedNode{}});
    MarkedNode& held = holder.entries.front().value;
    if (!field.empty() && std::string(section) == "variables" && held.type == MarkedNode::Type::kSequence &&
        held.items.size() == 2) {
      // [lower, upper] shorthand: spelled out so that one bound can change.
      MarkedNode spelled;
      spelled.type = MarkedNode::Type::kMap;
      spelled.mark = held.mark;
      spelled.entries.push_back(MarkedEntry{"lower", held.items[0].mark, held.items[0]});
      spelled.entries.push_back(MarkedEntry{"upper", held.items[1].mark, held.items[1]});
      held = spelled;
    }
    try {
      apply_override(holder, "entry" + field + "=" + value);
    } catch (const InputError& e) {
      std::string message = e.message();
      for (std::size_t at = message.find("'entry"); at != std::string::npos; at = message.find("'entry", at + 1)) {
        message.replace(at + 1, 5, prefix + entry_key);
      }
      throw InputError(e.mark(), key, message);
    }
    const MarkedEntry* updated = holder.find("entry") != nullptr ? &holder.entries.front() : nullptr;
    if (best != nullptr) {
      if (updated == nullptr) {
        map->entries.erase(map->entries.begin() + (best - map->entries.data()));
      } else {
        best->value = updated->value;
      }
    } else if (updated != nullptr) {
      map->entries.push_back(MarkedEntry{entry_key, SourceMark{kCommandLine, 0, 0}, updated->value});
    }
    return true;
  }
  return false;
}

bool is_problem_assignment(const std::string& assignment) {
  const std::string t = trim(assignment);
  return t.rfind("problem.", 0) == 0;
}

}  // namespace

std::vector<std::string> apply_study_overrides(MarkedNode& root, const std::vector<std::string>& overrides) {
  std::vector<std::string> cli_problem_overrides;
  for (const auto& o : overrides) {
    if (is_problem_assignment(o)) {
      cli_problem_overrides.push_back(trim(o).substr(8));
    } else if (!apply_dotted_section_override(root, o)) {
      apply_override(root, o);
    }
  }
  return cli_problem_overrides;
}

}  // namespace rackopt::studyfile
