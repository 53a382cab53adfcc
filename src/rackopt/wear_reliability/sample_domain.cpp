#include "rackopt/wear_reliability/sample_domain.hpp"

#include <cmath>

namespace rackopt {

bool input_must_be_positive(const std::string& key) {
  return key == "load" || key == "wear.coefficient" || key == "surface_hardness";
}

std::optional<std::string> outside_input_domain(const std::string& key, double value) {
  if (!std::isfinite(value)) return std::string("is not finite");
  if (input_must_be_positive(key) && !(value > 0)) return std::string("is not positive");
  return std::nullopt;
}

}  // namespace rackopt
