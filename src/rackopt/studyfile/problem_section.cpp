#include "rackopt/studyfile/study_sections.hpp"

#include <filesystem>

#include "rackopt/problem/random_input_keys.hpp"
#include "rackopt/studyfile/study_section_reader.hpp"

namespace rackopt::studyfile {

using namespace rackopt::study;
namespace {

namespace fs = std::filesystem;

// A MarkedNode written back as a YAML flow value, so that a `problem_set`
// entry can travel as a "key=value" override (StudySpec::problem_overrides).
std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default: out += c;
    }
  }
  return out + "\"";
}

std::string to_flow(const MarkedNode& n, bool top) {
  switch (n.type) {
    case MarkedNode::Type::kNull: return top ? "" : "~";
    case MarkedNode::Type::kScalar: return quote(n.scalar);
    case MarkedNode::Type::kMap: {
      std::string out = "{";
      for (std::size_t i = 0; i < n.entries.size(); ++i) {
        out += (i ? ", " : "") + quote(n.entries[i].key) + ": " + to_flow(n.entries[i].value, false);
      }
      return out + "}";
    }
    case MarkedNode::Type::kSequence: {
      std::string out = "[";
      for (std::size_t i = 0; i < n.items.size(); ++i) out += (i ? ", " : "") + to_flow(n.items[i], false);
      return out + "]";
    }
  }
  return "";
}

// Where each problem override came from, to send the problem loader's
// "<command line>" errors back to the study file line that wrote them.
struct OverrideOrigin {
  std::string key;
  SourceMark mark;  // the problem_set key; file "<command line>" for --set problem.*
  bool from_study_file = false;
};

bool path_within(const std::string& path, const std::string& key) {
  if (path.rfind(key, 0) != 0) return false;
  return path.size() == key.size() || path[key.size()] == '.' || path[key.size()] == '[';
}

[[noreturn]] void rethrow_problem_error(const InputError& e, const std::vector<OverrideOrigin>& origins) {
  if (e.mark().file == kCommandLine) {
    for (auto it = origins.rbegin(); it != origins.rend(); ++it) {
      if (!path_within(e.key_path(), it->key) && !path_within(it->key, e.key_path())) continue;
      if (it->from_study_file) throw InputError(it->mark, "problem_set." + e.key_path(), e.message());
      throw InputError(e.mark(), "problem." + e.key_path(), e.message());
    }
  }
  throw e;
}

}  // namespace

LoadedProblem read_problem_section(const SectionReader& top, const std::string& base_dir,
                                   const std::vector<std::string>& cli_problem_overrides,
                                   const InMemoryProblem* given, StudySpec& spec) {
  if (given) {
    // The program's problem wins over the file's `problem:`, which may be left out.
    spec.problem_path = given->name;
    spec.problem_root = std::make_shared<const MarkedNode>(parse_marked_yaml(given->yaml_text, given->name));
  } else if (const MarkedNode* inline_problem = top.get("problem"); inline_problem && inline_problem->is_map()) {
    // The problem written in the study file itself: its errors point there.
    spec.problem_path = spec.file + " (problem:)";
    spec.problem_root = std::make_shared<const MarkedNode>(*inline_problem);
  } else {
    const auto problem_text = top.scalar("problem", "the path of a problem file, or the problem itself as a map");
    if (!problem_text) top.missing("problem", "the path of a problem file, e.g. ../problems/rack_railway.yaml");
    const fs::path p(problem_text->first);
    spec.problem_path = (p.is_absolute() || base_dir.empty()) ? p.lexically_normal().string()
                                                              : (fs::path(base_dir) / p).lexically_normal().string();
    std::error_code ec;
    const fs::file_type type = fs::status(spec.problem_path, ec).type();
    if (type != fs::file_type::not_found && type != fs::file_type::regular && !ec) {
      // A FIFO would block the read for ever (docs/input_limits.md).
      const std::string kind = type == fs::file_type::directory ? "a directory"
                               : type == fs::file_type::fifo    ? "a FIFO (named pipe)"
                               : type == fs::file_type::character || type == fs::file_type::block ? "a device"
                                                                                                    : "a special file";
      throw InputError(problem_text->second, "problem",
                       "the problem file '" + spec.problem_path + "' is " + kind +
                           ", not a regular file: give the path of a .yaml file");
    }
    if (!fs::is_regular_file(spec.problem_path, ec)) {
      throw InputError(problem_text->second, "problem",
                       "cannot open the problem file '" + spec.problem_path + "'" +
                           (p.is_absolute() ? std::string()
                                            : " (a relative path is read from the study file's folder '" +
                                                  (base_dir.empty() ? std::string(".") : base_dir) + "')"));
    }
  }

  std::vector<OverrideOrigin> origins;
  if (given) {
    for (const auto& o : given->overrides) {
      spec.problem_overrides.push_back(o);
      origins.push_back(OverrideOrigin{override_key(o), SourceMark{kCommandLine, 0, 0}, false});
    }
  }
  if (const MarkedNode* ps = top.get("problem_set")) {
    if (!ps->is_map()) {
      throw InputError(ps->mark, "problem_set",
                       "expected a map of problem key -> value, e.g. {load.force: 60 kN}, found " + ps->type_name());
    }
    for (const auto& e : ps->entries) {
      spec.problem_overrides.push_back(e.key + "=" + to_flow(e.value, true));
      origins.push_back(OverrideOrigin{override_key(e.key + "="), e.key_mark, true});
    }
  }
  for (const auto& o : cli_problem_overrides) {
    spec.problem_overrides.push_back(o);
    origins.push_back(OverrideOrigin{override_key(o), SourceMark{kCommandLine, 0, 0}, false});
  }
  LoadedProblem problem;
  try {
    problem.tree = study_problem_tree(spec);
    problem.drive = drive_from_tree(problem.tree);
    check_overrides_against_absolute_inputs(problem.drive, spec.problem_overrides);
  } catch (const InputError& e) {
    rethrow_problem_error(e, origins);
  }
  return problem;
}

}  // namespace rackopt::studyfile
