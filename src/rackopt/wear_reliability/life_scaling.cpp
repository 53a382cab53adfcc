#include "rackopt/wear_reliability/life_scaling.hpp"

namespace rackopt {

bool input_scales_life(const std::string& key) { return key == "wear.coefficient" || key == "surface_hardness"; }

double life_scale(const WearSample& sample) {
  return sample.surface_hardness_scale / sample.wear_coefficient_scale;
}

}  // namespace rackopt
