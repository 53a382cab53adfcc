#include "rackopt/problem/design_point.hpp"

#include <cmath>

namespace rackopt {

void set_problem_value(ProblemTree& tree, const std::string& key_path, double value_si) {
  const auto kind = problem_key_kind(key_path);
  const SourceMark where{"<design variable>", 0, 0};
  if (!kind) {
    throw InputError(where, key_path,
                     "is not a numeric key of the problem; a design variable must be a number such as "
                     "pinion.module, rack.span or mounting.clearance (docs/yaml.md)");
  }
  if (!std::isfinite(value_si)) throw InputError(where, key_path, "design value is not finite");
  std::string text;
  if (*kind == QuantityKind::kCount) {
    if (value_si != std::round(value_si)) {
      throw InputError(where, key_path, format_number(value_si, 17) + " is not a whole number");
    }
    text = format_number(value_si, 17);
  } else if (*kind == QuantityKind::kDimensionless) {
    text = format_number(value_si, 17);
  } else {
    text = format_number(value_si, 17) + " " + std::string(si_unit(*kind));
  }
  // A number (sign, digits, '.', 'e') and a unit name: YAML reads it as itself.
  set_plain_scalar(tree.root, key_path, std::move(text));
}

Drive drive_with_values(const ProblemTree& tree, std::span<const std::pair<std::string, double>> values) {
  ProblemTree copy = tree;
  for (const auto& [key, value] : values) set_problem_value(copy, key, value);
  return drive_from_tree(copy);
}

}  // namespace rackopt
