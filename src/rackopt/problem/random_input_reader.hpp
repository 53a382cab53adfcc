// One item of a problem's reliability.random list -> RandomInput
// (core/drive.hpp; docs/yaml.md, reliability.random).
//
// Around the design (the default):
//   {input: contact_ratio, distribution: normal, shift: -0.096, sd: 0.038}
//   {input: load, distribution: normal, cv: 0.1}
//   {input: wear_coefficient, distribution: lognormal, sigma: 0.3}      (factor, median 1)
//   {input: surface_hardness, distribution: uniform, half_width: 20 HB}
// normal: sd (the input's unit) or cv (plain number), optional shift (the
// input's unit, default 0); lognormal: sigma of ln (0 < sigma < 5), optional
// median_factor (> 0, default 1); uniform: half_width (> 0), optional shift.
// Absolute (explicit opt-in, `absolute: true`): normal mean, sd; lognormal
// median, sigma; uniform lower, upper; weibull scale, shape; values positive.
#pragma once

#include <string>

#include "rackopt/core/drive.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"

namespace rackopt {

// Reads `item` (written at reliability.random[n], `path`). Throws InputError
// at the offending key or value for: not a map, missing or unknown input or
// distribution, a parameter the form does not take (an absolute one such as
// `mean` without `absolute: true` says so), a missing parameter, sd together
// with cv, a value out of range, and weibull without `absolute: true`.
RandomInput read_random_input(const MarkedNode& item, const std::string& path);

}  // namespace rackopt
