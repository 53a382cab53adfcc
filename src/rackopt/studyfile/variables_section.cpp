#include "rackopt/studyfile/study_sections.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <span>

#include "rackopt/core/text.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/problem/random_input_keys.hpp"
#include "rackopt/studyfile/study_section_reader.hpp"

namespace rackopt::studyfile {

using namespace rackopt::study;
namespace {

// Numeric keys named in messages when a variable key is not one (filtered
// through problem_key_kind so that the list stays true to the schema).
std::vector<std::string> numeric_key_examples() {
  static const char* const kCandidates[] = {
      "pinion.teeth",        "pinion.module",     "pinion.pressure_angle",        "pinion.face_width",
      "pinion.profile_shift", "pinion.addendum",  "pinion.dedendum",              "pinion.tip_radius",
      "pinion.bore_radius",  "rack.addendum",     "rack.dedendum",                "rack.face_width",
      "rack.body_height",    "rack.body_width",   "rack.span",                    "rack.tooth_offset",
      "mounting.clearance",  "load.force",        "load.torque",                  "faults[0].depth",
      "faults[0].length",    "faults[0].width",   "faults[0].start",              "wear.coefficient",
      "wear.max_depth",      "wear.rack_hardness.case_depth", "wear.rack_hardness.surface",
      "wear.pinion_hardness.case_depth", "dynamics.moving_mass", "dynamics.drive_inertia",
      "dynamics.drive_stiffness", "dynamics.damping_ratio"};
  std::vector<std::string> out;
  for (const char* k : kCandidates) {
    if (problem_key_kind(k)) out.emplace_back(k);
  }
  return out;
}

// The unit a value was written in ("20 deg" -> "deg"; bare -> the kind's
// default unit), spelled as unit_names spells it.
std::string written_unit(const std::string& text, QuantityKind kind) {
  if (kind == QuantityKind::kCount || kind == QuantityKind::kDimensionless) return "";
  const std::string t = trim(text);
  char* end = nullptr;
  errno = 0;
  std::strtod(t.c_str(), &end);
  const std::string rest = trim(std::string_view(t).substr(static_cast<std::size_t>(end - t.c_str())));
  if (rest.empty()) return std::string(default_unit(kind));
  const std::vector<std::string> names = unit_names(kind);
  for (const auto& n : names) {
    if (n == rest) return n;
  }
  const double factor = unit_factor(rest, kind);
  for (const auto& n : names) {
    if (unit_factor(n, kind) == factor) return n;
  }
  return rest;
}

bool same_value(double a, double b) {
  return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

struct VariableSites {
  std::vector<ValueSite> bounds;  // lower, upper, values and start as written: checked against the problem
};

DesignVariable read_variable(const MarkedEntry& entry, VariableSites& sites) {
  DesignVariable v;
  v.key = entry.key;
  v.mark = entry.key_mark;
  const std::string path = "variables." + entry.key;
  const auto kind = problem_key_kind(entry.key);
  if (!kind) {
    std::string message =
        "'" + entry.key + "' is not a numeric problem key; a design variable is a number of the problem";
    const std::vector<std::string> examples = numeric_key_examples();
    if (const auto best = near_miss(entry.key, examples)) message += "; did you mean '" + *best + "'?";
    message += ". Numeric keys include: " + join(examples) + " (docs/yaml.md)";
    throw InputError(entry.key_mark, path, message);
  }
  v.kind = *kind;
  const MarkedNode& node = entry.value;
  const char* const forms =
      "{lower: 14 deg, upper: 25 deg[, start: 20 deg][, levels: 5]}, [lower, upper] or {values: [20 mm, 25 mm]}";

  std::optional<ValueSite> lower_site, upper_site, start_site;
  std::vector<ValueSite> values;
  if (node.type == MarkedNode::Type::kSequence) {
    if (node.items.size() != 2) {
      throw InputError(node.mark, path,
                       "a list gives [lower, upper] and needs exactly 2 values, found " +
                           std::to_string(node.items.size()) + "; for a discrete set write {values: [...]}");
    }
    lower_site = read_value(node.items[0], path + "[0]", v.kind);
    upper_site = read_value(node.items[1], path + "[1]", v.kind);
  } else if (node.is_map()) {
    const SectionReader s =
        study_section(&node, path, entry.key_mark, {"lower", "upper", "start", "levels", "values"}, forms);
    if (const MarkedNode* vals = s.get("values")) {
      if (s.has("lower") || s.has("upper")) {
        const std::string k = s.has("lower") ? "lower" : "upper";
        throw InputError(s.key_mark(k), s.child_path(k),
                         "give either values (a discrete set) or lower/upper (a continuous range), not both");
      }
      if (s.has("levels")) {
        throw InputError(s.key_mark("levels"), s.child_path("levels"),
                         "levels applies to continuous variables; every value of a discrete set is used");
      }
      if (vals->type != MarkedNode::Type::kSequence || vals->items.empty()) {
        throw InputError(vals->mark, s.child_path("values"),
                         "expected a non-empty list of values, e.g. [20 mm, 25 mm, 32 mm], found " + vals->type_name());
      }
      for (std::size_t i = 0; i < vals->items.size(); ++i) {
        values.push_back(read_value(vals->items[i], item_path(s.child_path("values"), i), v.kind));
      }
    } else {
      if (!s.has("lower")) s.missing("lower", std::string("the lower bound; a variable is ") + forms);
      if (!s.has("upper")) s.missing("upper", std::string("the upper bound; a variable is ") + forms);
      lower_site = read_value(*s.get("lower"), s.child_path("lower"), v.kind);
      upper_site = read_value(*s.get("upper"), s.child_path("upper"), v.kind);
      if (const auto levels = s.integer("levels", {2, 100000})) v.levels = static_cast<int>(*levels);
    }
    if (const MarkedNode* st = s.get("start")) start_site = read_value(*st, s.child_path("start"), v.kind);
  } else {
    throw InputError(node.is_null() ? entry.key_mark : node.mark, path,
                     std::string("expected ") + forms + ", found " + node.type_name());
  }

  if (!values.empty()) {
    v.unit = written_unit(values.front().text, v.kind);
    std::vector<ValueSite> sorted = values;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const ValueSite& a, const ValueSite& b) { return a.value < b.value; });
    for (std::size_t i = 1; i < sorted.size(); ++i) {
      if (same_value(sorted[i - 1].value, sorted[i].value)) {
        // Point at the later of the two as written.
        const ValueSite& later =
            (sorted[i].mark.line > sorted[i - 1].mark.line ||
             (sorted[i].mark.line == sorted[i - 1].mark.line && sorted[i].mark.column > sorted[i - 1].mark.column))
                ? sorted[i]
                : sorted[i - 1];
        throw InputError(later.mark, later.path,
                         format_in(later.value, v.kind, v.unit) + " is listed twice; the values must be distinct");
      }
    }
    for (const auto& s : sorted) v.values.push_back(s.value);
    v.lower = v.values.front();
    v.upper = v.values.back();
    if (start_site) {
      const auto it =
          std::find_if(v.values.begin(), v.values.end(), [&](double x) { return same_value(x, start_site->value); });
      if (it == v.values.end()) {
        std::vector<std::string> listed;
        for (double x : v.values) listed.push_back(format_in(x, v.kind, v.unit));
        throw InputError(start_site->mark, start_site->path,
                         format_in(start_site->value, v.kind, v.unit) + " is not one of the values (" + join(listed) +
                             "); the start of a discrete variable must be one of them");
      }
      v.start = *it;
    }
    sites.bounds.insert(sites.bounds.end(), values.begin(), values.end());
    return v;
  }

  if (v.kind == QuantityKind::kCount) {
    throw InputError(lower_site->mark, path,
                     entry.key + " is a whole number: give its candidates as a discrete set, e.g. {values: [" +
                         format_number(lower_site->value, 10) + ", " + format_number(upper_site->value, 10) + "]}");
  }
  v.unit = written_unit(lower_site->text, v.kind);
  v.lower = lower_site->value;
  v.upper = upper_site->value;
  if (!(v.lower < v.upper)) {
    throw InputError(upper_site->mark, upper_site->path,
                     "the lower bound " + format_in(v.lower, v.kind, v.unit) + " must be below the upper bound " +
                         format_in(v.upper, v.kind, v.unit) + " (for a fixed value use {values: [" + lower_site->text +
                         "]} or problem_set)");
  }
  if (start_site) {
    if (start_site->value < v.lower || start_site->value > v.upper) {
      throw InputError(start_site->mark, start_site->path,
                       format_in(start_site->value, v.kind, v.unit) + " is outside the bounds; allowed: " +
                           format_in(v.lower, v.kind, v.unit) + " <= start <= " + format_in(v.upper, v.kind, v.unit));
    }
    v.start = start_site->value;
  }
  sites.bounds.push_back(*lower_site);
  sites.bounds.push_back(*upper_site);
  return v;
}

}  // namespace

void read_variables(const SectionReader& top, const LoadedProblem& problem, StudySpec& spec) {
  std::vector<VariableSites> variable_sites;
  if (const MarkedNode* vars = top.get("variables")) {
    if (!vars->is_map()) {
      throw InputError(
          vars->mark, "variables",
          "expected a map of problem key -> bounds, e.g. {pinion.pressure_angle: [14 deg, 25 deg]}, found " +
              vars->type_name());
    }
    for (const auto& e : vars->entries) {
      VariableSites sites;
      spec.variables.push_back(read_variable(e, sites));
      variable_sites.push_back(std::move(sites));
      // A variable moves its random inputs' design values: an absolute one
      // would ignore it (problem/random_input_keys.hpp).
      check_absolute_random_inputs(problem.drive, e.key, e.key_mark, "variables." + e.key);
    }
  }
  // Every bound / value as the problem sees it (others at the problem's own
  // values), so that a value the schema refuses is reported where the study
  // wrote it, not at the first design the runner builds.
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    const DesignVariable& v = spec.variables[i];
    for (const ValueSite& site : variable_sites[i].bounds) {
      const std::pair<std::string, double> one{v.key, site.value};
      try {
        (void)drive_with_values(problem.tree, std::span<const std::pair<std::string, double>>(&one, 1));
      } catch (const InputError& e) {
        throw InputError(site.mark, site.path,
                         format_in(site.value, v.kind, v.unit) + " is refused by the problem: " +
                             (e.key_path().empty() ? "" : e.key_path() + ": ") + e.message());
      }
    }
  }
}

}  // namespace rackopt::studyfile
