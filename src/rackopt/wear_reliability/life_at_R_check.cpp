#include "rackopt/wear_reliability/life_at_R_check.hpp"

#include <cstdio>

namespace rackopt {

std::optional<std::string> life_at_R_above_nominal(double R, double life_years, double nominal_years,
                                                   const std::string& how) {
  if (!(R >= 0.5) || !(nominal_years > 0) || !(life_years > nominal_years * (1 + 1e-6))) return std::nullopt;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "life at R = %g (%.4g y, %s) is above the nominal wear life (%.4g y): the random inputs describe a "
                "better drive than the design (an absolute distribution that does not follow it, or a favourable "
                "shift)",
                R, life_years, how.c_str(), nominal_years);
  return std::string(buf);
}

}  // namespace rackopt
