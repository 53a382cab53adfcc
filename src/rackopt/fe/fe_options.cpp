#include "rackopt/fe/fe_options.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rackopt::fe {

void check_fe_options(const FeOptions& options) {
  if (options.level < 0 || options.level > 6)
    throw std::invalid_argument("FE level " + std::to_string(options.level) + " is out of range; allowed: 0..6");
  if (!std::isfinite(options.rack_body_depth))
    throw std::invalid_argument("FE rack body depth must be finite");
}

}  // namespace rackopt::fe
