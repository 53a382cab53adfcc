// Built with rackopt as a subdirectory: parses quantities with units and
// prints them in SI; a bad unit is an InputError naming what is allowed.
#include <rackopt/units/units.hpp>
#include <rackopt/core/error.hpp>
#include <rackopt/version.hpp>

#include <cstdio>

int main() {
  const double module = rackopt::parse_quantity("36 mm", rackopt::QuantityKind::kLength);
  const double angle = rackopt::parse_quantity("20 deg", rackopt::QuantityKind::kAngle);
  std::printf("rackopt %s\nmodule %.9g\nangle %.9g\n", RACKOPT_VERSION_STRING, module, angle);
  try {
    rackopt::parse_quantity("36 furlongs", rackopt::QuantityKind::kLength);
  } catch (const rackopt::InputError& e) {
    std::printf("refused: %s\n", e.what());
    return 0;
  }
  return 1;
}
