// Random inputs that scale the wear life exactly (docs/models/reliability.md,
// "Several random inputs: the scaling inputs factor out").
//
// The wear coefficient and the hardness enter the wear model only through the
// rate of the hardness integral per pass, K q / H (wear/wear_life.hpp: the
// sample's K = k K0 and H = sigma H0(h)). Scaling that rate by k / sigma
// scales every pass count (the passes to failure, each block's passes, the
// contact-ratio root of a block) by sigma / k and leaves the wear state after
// each block, the loads and the failure criterion as they are. So, in exact
// arithmetic,
//   life(eps, F, k K0, sigma H0) = life(eps, F, K0, H0) * sigma / k,
// and a Monte Carlo over several inputs of which at most one shapes the life
// (the contact ratio or the load) needs lives along that one input only. In
// floating point the two sides differ by rounding (measured 1.0e-15
// relative at most, tests/wear_reliability/life_scaling_test.cpp, over both
// ends of a life: h_max and the contact-ratio root).
//
// Example:
//   WearSample s = wear_sample_for(drive, inputs, x);
//   double years = life_years_without_scaling(s) * life_scale(s);
#pragma once

#include <string>

#include "rackopt/wear/wear_life.hpp"

namespace rackopt {

// True for wear.coefficient and surface_hardness (RandomInput::key).
bool input_scales_life(const std::string& key);

// sigma / k of a sample: its life over the life of the same sample with the
// wear coefficient and the hardness at the design's values.
double life_scale(const WearSample& sample);

}  // namespace rackopt
