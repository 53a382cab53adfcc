#include "rackopt/problem/random_input_keys.hpp"

#include <algorithm>

#include "rackopt/marked_yaml/marked_tree.hpp"

namespace rackopt {
namespace {

// "wear.hardness.coefficients[0]" -> "wear.hardness.coefficients", trimmed.
std::string normalized(const std::string& key) {
  std::string out;
  int depth = 0;
  for (char c : key) {
    if (c == '[') ++depth;
    if (depth == 0 && c != ' ' && c != '\t') out += c;
    if (c == ']' && depth > 0) --depth;
  }
  return out;
}

// a is b, or lies under it ("pinion.module" under "pinion").
bool within(const std::string& a, const std::string& b) {
  if (a.rfind(b, 0) != 0) return false;
  return a.size() == b.size() || a[b.size()] == '.';
}

bool touches(const std::string& key, const std::string& affecting) {
  return within(key, affecting) || within(affecting, key);
}

// The problem keys that move each input's design value.
std::vector<std::string> affecting_keys(const std::string& input, const Drive& drive) {
  if (input == "contact_ratio") {
    return {"pinion.teeth",     "pinion.module",   "pinion.pressure_angle", "pinion.profile_shift",
            "pinion.addendum",  "pinion.dedendum", "pinion.tip_radius",     "rack.addendum",
            "rack.dedendum",    "mounting.clearance", "effects.interference_limit"};
  }
  if (input == "wear.coefficient") return {"wear.coefficient"};
  if (input == "load") {
    std::vector<std::string> k = {"load.force", "load.torque"};
    if (drive.load.torque > 0) {  // F = T / r_b, r_b = m z cos(a0) / 2
      k.insert(k.end(), {"pinion.teeth", "pinion.module", "pinion.pressure_angle"});
    }
    return k;
  }
  if (input == "surface_hardness") {
    std::vector<std::string> k;
    for (const char* section : {"wear.hardness", "wear.pinion_hardness", "wear.rack_hardness"}) {
      for (const char* field : {"surface", "coefficients", "values", "kind", "hardness_unit"})
        k.push_back(std::string(section) + "." + field);
    }
    return k;
  }
  return {};
}

// How the file names the input (reliability.random[i].input).
std::string written_name(const std::string& key) { return key == "wear.coefficient" ? "wear_coefficient" : key; }

}  // namespace

std::vector<std::string> random_inputs_changed_by(const std::string& problem_key, const Drive& drive) {
  const std::string key = normalized(problem_key);
  std::vector<std::string> out;
  if (key.empty()) return out;
  for (const char* input : {"contact_ratio", "wear.coefficient", "load", "surface_hardness"}) {
    const std::vector<std::string> keys = affecting_keys(input, drive);
    if (std::any_of(keys.begin(), keys.end(), [&](const std::string& a) { return touches(key, a); }))
      out.emplace_back(input);
  }
  return out;
}

void check_absolute_random_inputs(const Drive& drive, const std::string& problem_key, const SourceMark& mark,
                                  const std::string& key_path) {
  const std::vector<std::string> changed = random_inputs_changed_by(problem_key, drive);
  const std::vector<RandomInput>& inputs = drive.reliability.inputs;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (!inputs[i].absolute) continue;
    if (std::find(changed.begin(), changed.end(), inputs[i].key) == changed.end()) continue;
    const std::string random = "reliability.random[" + std::to_string(i) + "]";
    throw InputError(mark, key_path,
                     "changes the design's " + written_name(inputs[i].key) + ", which " + random +
                         " gives as an absolute distribution (absolute: true): the life at R would ignore the "
                         "change. Describe " + random + " around the design instead (drop absolute: true; "
                         "docs/yaml.md, reliability.random) or do not change " + normalized(problem_key));
  }
}

void check_overrides_against_absolute_inputs(const Drive& drive, const std::vector<std::string>& overrides) {
  for (const std::string& o : overrides) {
    const std::string key = override_key(o);
    check_absolute_random_inputs(drive, key, SourceMark{"<command line>", 0, 0}, key);
  }
}

}  // namespace rackopt
