#include "rackopt/studyfile/study_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <utility>

#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/marked_yaml/input_file.hpp"
#include "rackopt/core/suggest.hpp"
#include "rackopt/marked_yaml/marked_map.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/problem/random_input_keys.hpp"
#include "rackopt/study/study_kind_rules.hpp"
#include "rackopt/studyfile/verify_section.hpp"
#include "rackopt/units/units.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt::studyfile {

// The loaders fill the study layer's types throughout.
using namespace rackopt::study;
namespace {

namespace fs = std::filesystem;

constexpr const char* kCommandLine = "<command line>";

// ---------------------------------------------------------------- text helpers


// The candidate closest to `word` when it is a near miss (closest_name, the
// rule of every loader), or else one it abbreviates.
std::optional<std::string> near_miss(std::string_view word, const std::vector<std::string>& candidates) {
  if (auto best = closest_name(word, candidates)) return best;
  // An abbreviation ("max_evals" for "max_evaluations"): a long common start.
  const std::string* longest = nullptr;
  std::size_t longest_prefix = 0;
  for (const auto& c : candidates) {
    std::size_t k = 0;
    while (k < word.size() && k < c.size() && std::tolower(static_cast<unsigned char>(word[k])) ==
                                                   std::tolower(static_cast<unsigned char>(c[k]))) {
      ++k;
    }
    if (k > longest_prefix) {
      longest = &c;
      longest_prefix = k;
    }
  }
  if (longest != nullptr && longest_prefix >= std::max<std::size_t>(4, (2 * word.size() + 2) / 3)) return *longest;
  return std::nullopt;
}

std::string item_path(const std::string& list, std::size_t i) { return list + "[" + std::to_string(i) + "]"; }

std::string format_in(double si, QuantityKind kind, std::string_view unit = {}) {
  if (kind == QuantityKind::kCount || kind == QuantityKind::kDimensionless) return format_number(si, 10);
  return format_quantity(si, kind, unit, 10);
}

// ------------------------------------------------------------------ sections

// One map of the study file. Rejects unknown keys on construction (with
// "did you mean"), reads typed values, and reports missing keys at the map's
// own mark. Same behaviour as the problem loader's sections.
class Section : public MarkedMap {
 public:
  Section(const MarkedNode* node, std::string path, const SourceMark& fallback, std::vector<std::string> allowed,
          const std::string& example = {})
      : MarkedMap(node, std::move(path), fallback, std::move(allowed), example, near_miss) {}

  // One of `options` (compared without case); nullopt when absent.
  std::optional<std::string> choice(const std::string& key, const std::vector<std::string>& options) const {
    const auto t = scalar(key, "one of " + join(options, " | "));
    if (!t) return std::nullopt;
    for (const auto& o : options) {
      if (lower(t->first) == lower(o)) return o;
    }
    std::string message = "'" + t->first + "' is not allowed; allowed: " + join(options, " | ");
    if (const auto best = near_miss(t->first, options)) message += " (did you mean '" + *best + "'?)";
    throw InputError(t->second, child_path(key), message);
  }

  // A whole number in [lo, hi].
  long long integer(const std::string& key, long long fallback, long long lo, long long hi) const {
    const auto t = scalar(key, "a whole number");
    if (!t) return fallback;
    // Compared as a double first: 1e30 is "out of range", not an overflow.
    const double v = parse_whole_number(t->first, t->second, child_path(key));
    if (v < static_cast<double>(lo) || v > static_cast<double>(hi)) {
      throw InputError(t->second, child_path(key),
                       format_number(v, 17) + " is out of range; allowed: " + std::to_string(lo) + " <= " + key +
                           (hi < std::numeric_limits<int>::max() ? " <= " + std::to_string(hi) : std::string()));
    }
    return static_cast<long long>(v);
  }

  // A plain number; `lo_open`: must be > lo (else >= lo); hi: <= hi.
  double number(const std::string& key, double fallback, double lo, bool lo_open,
                double hi = std::numeric_limits<double>::infinity()) const {
    const auto t = scalar(key, "a plain number");
    if (!t) return fallback;
    const double v = parse_quantity(t->first, QuantityKind::kDimensionless, t->second, child_path(key));
    check_range(key, t->second, v, QuantityKind::kDimensionless, lo, lo_open, hi);
    return v;
  }

  double quantity(const std::string& key, QuantityKind kind, double fallback, double lo, bool lo_open,
                  std::string_view bare_unit = {}) const {
    const auto t = scalar(key, std::string("a ") + std::string(rackopt::kind_name(kind)));
    if (!t) return fallback;
    const double v = parse_quantity(t->first, kind, t->second, child_path(key), bare_unit);
    check_range(key, t->second, v, kind, lo, lo_open, std::numeric_limits<double>::infinity());
    return v;
  }

 private:
  void check_range(const std::string& key, const SourceMark& where, double v, QuantityKind kind, double lo,
                   bool lo_open, double hi) const {
    const bool bad = (lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi);
    if (!bad) return;
    std::string allowed = format_in(lo, kind) + (lo_open ? " < " : " <= ") + key;
    if (std::isfinite(hi)) allowed += " <= " + format_in(hi, kind);
    throw InputError(where, child_path(key), format_in(v, kind) + " is out of range; allowed: " + allowed);
  }
};

// ------------------------------------------------------------------- metrics

const char* const kMetricExamples = "a metric such as contact_ratio, min_stiffness_ks(200) or wear_life_at_R(0.9)";

metrics::MetricRequest read_metric(const MarkedNode& node, const std::string& path) {
  if (node.type != MarkedNode::Type::kScalar) {
    throw InputError(node.mark, path, std::string("expected ") + kMetricExamples + ", found " + node.type_name());
  }
  try {
    return metrics::resolve_request(metrics::parse_metric_request(node.scalar));
  } catch (const InputError& e) {
    throw InputError(node.mark, path, e.message());
  }
}

// A bound written in the metric's unit: its QuantityKind when it has one
// (bare number = the kind's default unit), else a bare number in the
// metric's SI unit, optionally followed by that unit ("0.8 1/m").
double read_metric_quantity(const MarkedNode& node, const std::string& path, const metrics::MetricDefinition& def) {
  const std::string unit(def.unit);
  if (node.type != MarkedNode::Type::kScalar) {
    throw InputError(node.mark, path,
                     "expected a value of " + std::string(def.name) + " (unit " + unit + "), found " + node.type_name());
  }
  if (def.kind) return parse_quantity(node.scalar, *def.kind, node.mark, path);
  std::string text = trim(node.scalar);
  if (unit != "-" && text.size() > unit.size() && text.compare(text.size() - unit.size(), unit.size(), unit) == 0) {
    text = trim(std::string_view(text).substr(0, text.size() - unit.size()));
  }
  try {
    return parse_quantity(text, QuantityKind::kDimensionless, node.mark, path);
  } catch (const InputError&) {
    throw InputError(node.mark, path,
                     "'" + node.scalar + "' is not a value of " + std::string(def.name) + "; expected a number in " +
                         unit + " (e.g. 0.8 or 0.8 " + unit + ")");
  }
}

std::string metric_value_text(double v, const metrics::MetricDefinition& def) {
  if (def.kind) return format_in(v, *def.kind, def.display_unit);
  return format_number(v, 10) + (def.unit == "-" ? "" : " " + std::string(def.unit));
}

// Where a metric was written, for re-throwing its set-up errors there.
struct MetricSite {
  metrics::MetricRequest request;
  SourceMark mark;
  std::string path;
};

// ----------------------------------------------------------------- variables

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
      "wear.pinion_hardness.case_depth"};
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

bool same_value(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }

struct ValueSite {
  double value;
  std::string text;
  SourceMark mark;
  std::string path;
};

ValueSite read_value(const MarkedNode& node, const std::string& path, QuantityKind kind) {
  if (node.type != MarkedNode::Type::kScalar) {
    throw InputError(node.mark, path, "expected a single value, found " + node.type_name());
  }
  return ValueSite{parse_quantity(node.scalar, kind, node.mark, path), node.scalar, node.mark, path};
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
    std::string message = "'" + entry.key + "' is not a numeric problem key; a design variable is a number of the problem";
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
    const Section s(&node, path, entry.key_mark, {"lower", "upper", "start", "levels", "values"}, forms);
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
      v.levels = static_cast<int>(s.integer("levels", 0, 2, 100000));
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
      const auto it = std::find_if(v.values.begin(), v.values.end(),
                                   [&](double x) { return same_value(x, start_site->value); });
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

// --------------------------------------------------------------- problem_set

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

// ------------------------------------------------------------------- solver

std::uint64_t read_seed(const Section& s, const std::string& key, std::uint64_t fallback) {
  const auto t = s.scalar(key, "a whole number >= 0");
  if (!t) return fallback;
  const std::string text = trim(t->first);
  std::uint64_t v = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (!text.empty() && text[0] == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (text.empty() || ec != std::errc() || ptr != last) {
    throw InputError(t->second, s.child_path(key),
                     "'" + t->first + "' is not a seed; expected a whole number >= 0 (at most 18446744073709551615)");
  }
  return v;
}

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
    const std::string field = best != nullptr && rest.size() > best->key.size() ? "." + rest.substr(best->key.size() + 1) : "";
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

StudySpec load_study_text(const std::string& yaml_text, const std::string& name_for_messages,
                          const std::string& base_dir, const std::vector<std::string>& overrides) {
  MarkedNode root = parse_marked_yaml(yaml_text, name_for_messages);
  if (root.is_null()) {
    root.type = MarkedNode::Type::kMap;
    root.mark = SourceMark{name_for_messages, 1, 1};
  }
  if (!root.is_map()) {
    throw InputError(root.mark, "",
                     "a study file is a map of sections (study, problem, variables, objectives, ...), found " +
                         root.type_name());
  }
  std::vector<std::string> cli_problem_overrides;
  for (const auto& o : overrides) {
    if (is_problem_assignment(o)) {
      cli_problem_overrides.push_back(trim(o).substr(8));
    } else if (!apply_dotted_section_override(root, o)) {
      apply_override(root, o);
    }
  }

  StudySpec spec;
  spec.file = name_for_messages;
  const Section top(&root, "", root.mark,
                    {"study", "problem", "problem_set", "variables", "objectives", "constraints", "report",
                     "metric_options", "solver", "pareto", "sweep", "output", "limits", "verify"});

  // --- study -----------------------------------------------------------------
  const std::vector<std::string> kinds = {"evaluate", "sweep", "optimize", "pareto", "reliability"};
  if (!top.has("study")) top.missing("study", "a map {name: ..., kind: " + join(kinds, " | ") + ", seed: 1}");
  const Section study(top.get("study"), "study", top.key_mark("study"), {"name", "kind", "seed", "description"},
                      "{kind: optimize, seed: 1}");
  spec.name = study.text("name", fs::path(name_for_messages).stem().string());
  spec.description = study.text("description", "");
  const auto kind_text = study.choice("kind", kinds);
  if (!kind_text) study.missing("kind", "one of " + join(kinds, " | "));
  const std::size_t kind_index =
      static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), *kind_text) - kinds.begin());
  const StudyKind kind_values[] = {StudyKind::kEvaluate, StudyKind::kSweep, StudyKind::kOptimize, StudyKind::kPareto,
                                   StudyKind::kReliability};
  spec.kind = kind_values[kind_index];
  spec.seed = read_seed(study, "seed", 1);
  const SourceMark kind_mark = study.value_mark("kind");

  // --- problem -----------------------------------------------------------------
  const auto problem_text = top.scalar("problem", "the path of a problem file");
  if (!problem_text) top.missing("problem", "the path of a problem file, e.g. ../problems/rack_railway.yaml");
  {
    const fs::path p(problem_text->first);
    spec.problem_path = (p.is_absolute() || base_dir.empty()) ? p.lexically_normal().string()
                                                              : (fs::path(base_dir) / p).lexically_normal().string();
    std::error_code ec;
    if (!fs::is_regular_file(spec.problem_path, ec)) {
      throw InputError(problem_text->second, "problem",
                       "cannot open the problem file '" + spec.problem_path + "'" +
                           (p.is_absolute() ? std::string()
                                            : " (a relative path is read from the study file's folder '" +
                                                  (base_dir.empty() ? std::string(".") : base_dir) + "')"));
    }
  }

  std::vector<OverrideOrigin> origins;
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
  ProblemTree tree;
  Drive drive;
  try {
    tree = load_problem_tree_file(spec.problem_path, spec.problem_overrides);
    drive = drive_from_tree(tree);
    check_overrides_against_absolute_inputs(drive, spec.problem_overrides);
  } catch (const InputError& e) {
    rethrow_problem_error(e, origins);
  }

  // --- variables -------------------------------------------------------------
  std::vector<VariableSites> variable_sites;
  const SourceMark variables_mark = top.key_mark("variables");
  if (const MarkedNode* vars = top.get("variables")) {
    if (!vars->is_map()) {
      throw InputError(vars->mark, "variables",
                       "expected a map of problem key -> bounds, e.g. {pinion.pressure_angle: [14 deg, 25 deg]}, found " +
                           vars->type_name());
    }
    for (const auto& e : vars->entries) {
      VariableSites sites;
      spec.variables.push_back(read_variable(e, sites));
      variable_sites.push_back(std::move(sites));
      // A variable moves its random inputs' design values: an absolute one
      // would ignore it (problem/random_input_keys.hpp).
      check_absolute_random_inputs(drive, e.key, e.key_mark, "variables." + e.key);
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
        (void)drive_with_values(tree, std::span<const std::pair<std::string, double>>(&one, 1));
      } catch (const InputError& e) {
        throw InputError(site.mark, site.path,
                         format_in(site.value, v.kind, v.unit) + " is refused by the problem: " +
                             (e.key_path().empty() ? "" : e.key_path() + ": ") + e.message());
      }
    }
  }

  // --- objectives ------------------------------------------------------------
  std::vector<MetricSite> metric_sites;
  const SourceMark objectives_mark = top.key_mark("objectives");
  if (const MarkedNode* objs = top.get("objectives")) {
    if (objs->type != MarkedNode::Type::kSequence) {
      throw InputError(objs->mark, "objectives",
                       "expected a list of objectives, e.g. [stiffness_fluctuation] or [{metric: wear_life, sense: "
                       "maximize}], found " + objs->type_name());
    }
    std::set<std::string> labels;
    for (std::size_t i = 0; i < objs->items.size(); ++i) {
      const MarkedNode& item = objs->items[i];
      const std::string path = item_path("objectives", i);
      ObjectiveSpec o;
      o.mark = item.mark;
      SourceMark metric_mark = item.mark;
      std::string metric_path = path;
      if (item.is_map()) {
        const Section s(&item, path, item.mark, {"metric", "sense", "scale"},
                        "{metric: wear_life, sense: maximize, scale: 1}");
        const MarkedNode* m = s.get("metric");
        if (m == nullptr) s.missing("metric", kMetricExamples);
        metric_mark = m->mark;
        metric_path = s.child_path("metric");
        o.metric = read_metric(*m, metric_path);
        o.maximize = s.choice("sense", {"minimize", "maximize"}).value_or("minimize") == "maximize";
        o.scale = s.number("scale", 0, 0, true);
      } else {
        o.metric = read_metric(item, path);
      }
      o.label = metrics::to_string(o.metric);
      if (!labels.insert(o.label).second) {
        throw InputError(metric_mark, metric_path, "objective '" + o.label + "' is listed twice");
      }
      metric_sites.push_back(MetricSite{o.metric, metric_mark, metric_path});
      spec.objectives.push_back(std::move(o));
    }
  }

  // --- constraints -----------------------------------------------------------
  if (const MarkedNode* cons = top.get("constraints")) {
    if (cons->type != MarkedNode::Type::kSequence) {
      throw InputError(cons->mark, "constraints",
                       "expected a list of bounds, e.g. [{metric: contact_ratio, min: 1.3}], found " + cons->type_name());
    }
    for (std::size_t i = 0; i < cons->items.size(); ++i) {
      const MarkedNode& item = cons->items[i];
      const std::string path = item_path("constraints", i);
      const Section s(&item, path, item.mark, {"metric", "min", "max", "equals", "scale"},
                      "{metric: contact_ratio, min: 1.3}");
      ConstraintSpec c;
      c.mark = item.mark;
      const MarkedNode* m = s.get("metric");
      if (m == nullptr) s.missing("metric", kMetricExamples);
      c.metric = read_metric(*m, s.child_path("metric"));
      c.label = metrics::to_string(c.metric);
      const metrics::MetricDefinition& def = metrics::find_metric(c.metric.name);
      auto bound = [&](const std::string& key) -> std::optional<double> {
        const MarkedNode* b = s.get(key);
        if (b == nullptr) return std::nullopt;
        return read_metric_quantity(*b, s.child_path(key), def);
      };
      c.min = bound("min");
      c.max = bound("max");
      c.equals = bound("equals");
      if (!c.min && !c.max && !c.equals) {
        throw InputError(item.mark, path,
                         "a constraint needs at least one bound: min, max or equals (e.g. {metric: " + c.label +
                             ", min: ...})");
      }
      if (c.equals && (c.min || c.max)) {
        const std::string k = c.min ? "min" : "max";
        throw InputError(s.key_mark(k), s.child_path(k),
                         "equals excludes min and max; give either equals or min/max");
      }
      if (c.min && c.max && !(*c.min < *c.max)) {
        throw InputError(s.value_mark("max"), s.child_path("max"),
                         "min " + metric_value_text(*c.min, def) + " must be below max " +
                             metric_value_text(*c.max, def) + " (for a target value use equals)");
      }
      if (const MarkedNode* sc = s.get("scale")) {
        const double v = read_metric_quantity(*sc, s.child_path("scale"), def);
        if (!(v > 0)) {
          throw InputError(sc->mark, s.child_path("scale"),
                           metric_value_text(v, def) + " is out of range; allowed: scale > 0 (default: |the bound|)");
        }
        c.scale = v;
      }
      metric_sites.push_back(MetricSite{c.metric, m->mark, s.child_path("metric")});
      spec.constraints.push_back(std::move(c));
    }
  }

  // --- report ------------------------------------------------------------------
  if (const MarkedNode* rep = top.get("report")) {
    if (rep->type != MarkedNode::Type::kSequence) {
      throw InputError(rep->mark, "report",
                       "expected a list of metrics, e.g. [mean_stiffness, supports_per_metre], found " +
                           rep->type_name());
    }
    for (std::size_t i = 0; i < rep->items.size(); ++i) {
      const std::string path = item_path("report", i);
      spec.report_metrics.push_back(read_metric(rep->items[i], path));
      metric_sites.push_back(MetricSite{spec.report_metrics.back(), rep->items[i].mark, path});
    }
  }

  // --- metric_options ----------------------------------------------------------
  const Section mo(top.get("metric_options"), "metric_options", top.key_mark("metric_options"),
                   {"exact_quantile", "reliability_samples", "reliability_seed", "bootstrap_replicates", "cost"},
                   "{exact_quantile: on, reliability_samples: 1000}");
  spec.metric_options.exact_quantile = mo.flag("exact_quantile", spec.metric_options.exact_quantile);
  spec.metric_options.reliability_samples = static_cast<long>(mo.integer("reliability_samples", -1, 1, kMaxReliabilitySamples));
  // The study seed drives every random choice, the Monte Carlo included,
  // unless the study pins the Monte Carlo seed itself.
  spec.metric_options.reliability_seed =
      mo.has("reliability_seed") ? static_cast<long>(mo.integer("reliability_seed", 0, 0, 2000000000))
                                 : static_cast<long>(spec.seed % 2000000001ULL);
  spec.metric_options.bootstrap_replicates =
      static_cast<int>(mo.integer("bootstrap_replicates", spec.metric_options.bootstrap_replicates, 20, 100000));
  {
    const Section cost(mo.get("cost"), "metric_options.cost", mo.key_mark("cost"),
                       {"rack_per_kg", "pinion_per_kg", "per_support", "rack_length"},
                       "{rack_per_kg: 1, pinion_per_kg: 3, per_support: 400, rack_length: 30 m}");
    metrics::CostWeights& w = spec.metric_options.cost;
    w.rack_per_kg = cost.number("rack_per_kg", w.rack_per_kg, 0, false);
    w.pinion_per_kg = cost.number("pinion_per_kg", w.pinion_per_kg, 0, false);
    w.per_support = cost.number("per_support", w.per_support, 0, false);
    w.rack_length = cost.quantity("rack_length", QuantityKind::kLength, w.rack_length, 0, false, "m");
  }

  // --- solver --------------------------------------------------------------------
  const Section sv(top.get("solver"), "solver", top.key_mark("solver"),
                   {"library", "algorithm", "local_algorithm", "max_evaluations", "max_time", "starts", "xtol_rel",
                    "xtol_abs", "ftol_rel", "ftol_abs", "constraint_tolerance", "gradients", "gradient_step",
                    "ipopt_tol", "ipopt_max_iterations"},
                   "{library: nlopt, algorithm: LN_COBYLA, max_evaluations: 400}");
  solvers::SolverSettings& so = spec.solver;
  so.library = sv.choice("library", {"nlopt", "ipopt"}).value_or("nlopt");
  so.algorithm = sv.text("algorithm", so.algorithm);
  so.local_algorithm = sv.text("local_algorithm", "");
  so.max_evaluations = static_cast<std::size_t>(sv.integer("max_evaluations", 1000, 1, 100000000));
  so.max_seconds = sv.quantity("max_time", QuantityKind::kTime, 0, 0, false, "s");
  so.starts = static_cast<int>(sv.integer("starts", 1, 1, 10000));
  so.xtol_rel = sv.number("xtol_rel", 1e-6, 0, false);
  so.xtol_abs = sv.number("xtol_abs", so.xtol_abs, 0, false);
  so.ftol_rel = sv.number("ftol_rel", so.ftol_rel, 0, false);
  so.ftol_abs = sv.number("ftol_abs", so.ftol_abs, 0, false);
  so.constraint_tolerance = sv.number("constraint_tolerance", so.constraint_tolerance, 0, false);
  const auto gradients = sv.choice("gradients", {"forward", "central"});
  so.central_differences = gradients ? *gradients == "central" : so.library == "ipopt";
  so.gradient_step = sv.number("gradient_step", so.gradient_step, 0, true, 0.25);
  so.ipopt_tol = sv.number("ipopt_tol", so.ipopt_tol, 0, true);
  so.ipopt_max_iterations = static_cast<int>(sv.integer("ipopt_max_iterations", so.ipopt_max_iterations, 1, 100000000));
  so.seed = spec.seed;

  // --- pareto ----------------------------------------------------------------------
  const Section pa(top.get("pareto"), "pareto", top.key_mark("pareto"),
                   {"method", "points", "primary", "duplicate_tolerance", "choose_weights"},
                   "{method: eps_constraint, points: 20}");
  spec.pareto.method = pa.choice("method", {"eps_constraint", "weighted_sum"}).value_or("eps_constraint") ==
                               "weighted_sum"
                           ? solvers::Scalarization::kWeightedSum
                           : solvers::Scalarization::kEpsilonConstraint;
  spec.pareto.points = static_cast<std::size_t>(pa.integer("points", 20, 2, 10000));
  spec.pareto.duplicate_tolerance = pa.number("duplicate_tolerance", spec.pareto.duplicate_tolerance, 0, false, 1);
  if (const auto primary = pa.scalar("primary", "an objective's metric or its index (0, 1, 2)")) {
    const std::string t = trim(primary->first);
    std::vector<std::string> labels;
    for (const auto& o : spec.objectives) labels.push_back(o.label);
    const bool is_index = !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    std::optional<std::size_t> found;
    if (is_index) {
      const std::size_t i = t.size() > 6 ? labels.size() : static_cast<std::size_t>(std::stoul(t));
      if (i < labels.size()) found = i;
    } else {
      std::string wanted = t;
      try {
        wanted = metrics::to_string(metrics::resolve_request(metrics::parse_metric_request(t)));
      } catch (const InputError&) {
        // not a metric text: compared as written below
      }
      for (std::size_t i = 0; i < labels.size(); ++i) {
        if (labels[i] == wanted || labels[i] == t) found = i;
      }
    }
    if (!found) {
      std::vector<std::string> choices;
      for (std::size_t i = 0; i < labels.size(); ++i) choices.push_back(std::to_string(i) + " = " + labels[i]);
      throw InputError(primary->second, "pareto.primary",
                       "'" + primary->first + "' is not one of the objectives; allowed: " +
                           (choices.empty() ? std::string("(the study has no objectives)") : join(choices)));
    }
    spec.pareto.primary = *found;
  }
  if (const MarkedNode* cw = pa.get("choose_weights")) {
    if (cw->type != MarkedNode::Type::kSequence) {
      throw InputError(cw->mark, "pareto.choose_weights",
                       "expected a list of weights, one per objective, e.g. [1, 1], found " + cw->type_name());
    }
    bool any_positive = false;
    for (std::size_t i = 0; i < cw->items.size(); ++i) {
      const std::string path = item_path("pareto.choose_weights", i);
      const ValueSite w = read_value(cw->items[i], path, QuantityKind::kDimensionless);
      if (w.value < 0) {
        throw InputError(w.mark, path, format_number(w.value, 10) + " is out of range; allowed: weight >= 0");
      }
      any_positive = any_positive || w.value > 0;
      spec.choose_weights.push_back(w.value);
    }
    if (spec.kind == StudyKind::kPareto && spec.choose_weights.size() != spec.objectives.size()) {
      throw InputError(cw->mark, "pareto.choose_weights",
                       "gives " + std::to_string(spec.choose_weights.size()) + " weights for " +
                           std::to_string(spec.objectives.size()) + " objectives; give one per objective, in order");
    }
    if (!any_positive) {
      throw InputError(cw->mark, "pareto.choose_weights", "every weight is 0; at least one must be > 0");
    }
  }

  // --- sweep -------------------------------------------------------------------------
  const Section sw(top.get("sweep"), "sweep", top.key_mark("sweep"), {"method", "levels", "points", "max_points"},
                   "{method: grid, levels: 5}");
  const std::string sweep_method = sw.choice("method", {"grid", "lhs", "sobol"}).value_or("grid");
  spec.sweep.method = sweep_method == "lhs"     ? SweepSpec::Method::kLatinHypercube
                      : sweep_method == "sobol" ? SweepSpec::Method::kSobol
                                                : SweepSpec::Method::kGrid;
  spec.sweep.levels = static_cast<int>(sw.integer("levels", spec.sweep.levels, 2, 100000));
  spec.sweep.points = static_cast<std::size_t>(sw.integer("points", 64, 1, 100000000));
  spec.sweep.max_points = static_cast<std::size_t>(sw.integer("max_points", 100000, 1, 100000000));

  // --- output, limits ------------------------------------------------------------------
  const Section out(top.get("output"), "output", top.key_mark("output"), {"plots", "report", "stiffness_curve"},
                    "{plots: on, report: on}");
  spec.output.plots = out.flag("plots", true);
  spec.output.report = out.flag("report", true);
  spec.output.stiffness_curve = out.flag("stiffness_curve", true);
  const Section lim(top.get("limits"), "limits", top.key_mark("limits"), {"max_discrete_combinations"},
                    "{max_discrete_combinations: 256}");
  spec.max_discrete_combinations = static_cast<std::size_t>(lim.integer("max_discrete_combinations", 256, 1, 100000000));
  spec.verify_fe = read_verify_section(top);

  // --- what each kind needs ------------------------------------------------------------
  // Where a broken kind rule points: the key to change, or study.kind when
  // the section the kind needs is missing altogether.
  auto rule_site = [&](const StudyRuleViolation& v) -> std::pair<SourceMark, std::string> {
    auto value_or_section = [](const Section& sec, const char* key, const std::string& path) {
      return std::pair<SourceMark, std::string>{sec.has(key) ? sec.value_mark(key) : sec.mark(), path};
    };
    switch (v.part) {
      case StudyRulePart::kObjectives:
        if (top.has("objectives")) return {objectives_mark, "objectives"};
        return {kind_mark, "study.kind"};
      case StudyRulePart::kVariables:
        if (top.has("variables")) return {variables_mark, "variables"};
        return {kind_mark, "study.kind"};
      case StudyRulePart::kVariable:
        return {spec.variables[v.variable].mark, "variables." + spec.variables[v.variable].key};
      case StudyRulePart::kSweepGrid:
        if (sw.has("levels")) return {sw.value_mark("levels"), "sweep.levels"};
        return {sw.present() ? sw.mark() : variables_mark, "sweep"};
      case StudyRulePart::kSweepPoints: return {sw.value_mark("points"), "sweep.points"};
      case StudyRulePart::kSolverLibrary: return value_or_section(sv, "library", "solver.library");
      case StudyRulePart::kSolverLocalAlgorithm:
        if (sv.has("local_algorithm")) return {sv.value_mark("local_algorithm"), "solver.local_algorithm"};
        return value_or_section(sv, "algorithm", "solver.algorithm");
      case StudyRulePart::kSolverAlgorithm: return value_or_section(sv, "algorithm", "solver.algorithm");
      case StudyRulePart::kParetoMethod:
        if (pa.has("method")) return {pa.value_mark("method"), "pareto.method"};
        if (sv.has("algorithm")) return {sv.value_mark("algorithm"), "solver.algorithm"};
        return {kind_mark, "solver.algorithm"};
    }
    return {kind_mark, "study.kind"};
  };
  // One design for evaluate/reliability: a single listed value is its start.
  if (spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability) {
    for (auto& v : spec.variables)
      if (!v.start && v.values.size() == 1) v.start = v.values.front();
  }
  if (const auto broken = check_study_kind_rules(spec)) {
    const auto [where, key] = rule_site(*broken);
    throw InputError(where, key, broken->message);
  }
  if ((spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability) && !spec.variables.empty()) {
    std::vector<std::pair<std::string, double>> design;
    for (const auto& v : spec.variables) design.emplace_back(v.key, *v.start);
    try {
      (void)drive_with_values(tree, design);
    } catch (const InputError& e) {
      throw InputError(variables_mark, "variables",
                       "the design of the starts is refused by the problem: " +
                           (e.key_path().empty() ? "" : e.key_path() + ": ") + e.message());
    }
  }
  if (spec.kind == StudyKind::kReliability) {
    if (!(drive.wear.coefficient > 0)) {
      throw InputError(kind_mark, "study.kind",
                       "a reliability study needs the problem's wear section (wear.coefficient, hardness); '" +
                           spec.problem_path + "' has none (docs/yaml.md, wear)");
    }
    if (drive.reliability.inputs.empty()) {
      throw InputError(kind_mark, "study.kind",
                       "a reliability study needs random inputs in the problem's reliability section "
                       "(reliability.random, e.g. - {input: contact_ratio, distribution: normal, shift: -0.096, sd: "
                       "0.038}); '" + spec.problem_path + "' has none");
    }
  }

  // --- metrics against the problem ---------------------------------------------------
  for (const MetricSite& site : metric_sites) {
    try {
      metrics::check_metric_requests(drive, std::span<const metrics::MetricRequest>(&site.request, 1),
                                     spec.metric_options);
    } catch (const InputError& e) {
      throw InputError(site.mark, site.path,
                       metrics::to_string(site.request) + " cannot be computed for the problem '" + spec.problem_path +
                           "': " + (e.key_path().empty() ? "" : e.key_path() + ": ") + e.message());
    }
  }
  {
    const std::vector<metrics::MetricRequest> all = spec.all_metrics();
    try {
      metrics::check_metric_requests(drive, all, spec.metric_options);
    } catch (const InputError& e) {
      throw InputError(mo.mark(), "metric_options" + (e.key_path().empty() ? "" : "." + e.key_path()), e.message());
    }
  }

  spec.pareto.solver = spec.solver;
  return spec;
}

StudySpec load_study_file(const std::string& path, const std::vector<std::string>& overrides) {
  const std::string text = read_input_file(path, "study file");
  return load_study_text(text, path, fs::path(path).parent_path().string(), overrides);
}

}  // namespace rackopt::studyfile
