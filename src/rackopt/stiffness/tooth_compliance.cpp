#include "rackopt/stiffness/tooth_compliance.hpp"

#include <cstdio>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt {

bool spall_band_removes_material(const SpallBand& band) {
  if (!(band.width >= 0.0) || !(band.depth >= 0.0)) {
    throw InputError({}, "spall", "spall width and depth must be non-negative");
  }
  if (!(band.low <= band.high)) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "spall lower edge %.4g mm above its upper edge %.4g mm", band.low * 1e3,
                  band.high * 1e3);
    throw InputError({}, "spall", buf);
  }
  return band.width != 0.0 && band.depth != 0.0;
}

}  // namespace rackopt
