// The distribution of a wear-reliability random input around the design
// (core/drive.hpp, RandomInput; docs/models/reliability.md "Scatter that
// follows the design"): the design's own value of the input, and the
// distribution of the input that the Monte Carlo samples and the exact
// quantile path invert.
#pragma once

#include <string>

#include "rackopt/core/drive.hpp"
#include "rackopt/statistics/distribution.hpp"

namespace rackopt {

// The design's own value v0 of random input `key` (RandomInput::key), SI:
// contact_ratio: `nominal_contact_ratio` (the wear model's, i.e. of the
// drive's geometry and clearance); wear.coefficient: wear.coefficient; load:
// load.force; surface_hardness: the rack's surface hardness, else the
// pinion's. Throws InputError (key "reliability.random") for an unknown key
// or a surface_hardness input without a surface hardness.
double design_value(const Drive& drive, const std::string& key, double nominal_contact_ratio);

// The distribution of the input itself: `input`'s as given when absolute,
// else built around `design_value` as documented on RandomInput. Throws
// DesignError "random_input_not_positive" when a scatter around the design
// leaves a load, coefficient or hardness with a non-positive mean (a shift
// larger than the design's value: this design cannot carry that scatter),
// InputError for parameters no distribution accepts.
statistics::Distribution input_distribution(const RandomInput& input, double design_value);

}  // namespace rackopt
