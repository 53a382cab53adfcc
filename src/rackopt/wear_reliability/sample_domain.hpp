// Which sampled values of a wear-reliability random input describe a drive at
// all (docs/models/reliability.md, "Failed samples"). One rule for every
// input:
//  * a value that is not finite (a distribution whose quantile overflowed, e.g.
//    a Weibull of tiny shape) is outside the domain;
//  * load, wear.coefficient and surface_hardness are positive quantities: a
//    sampled value <= 0 is outside the domain (a normal or uniform scatter
//    that reaches below 0);
//  * every finite contact ratio is inside: a contact ratio outside
//    [max(1, [eps]), eps_max] is a drive that fails at once (life 0, counted
//    in R(t)), which is physics, not an invalid sample.
// A sample with any value outside its domain is not evaluated: it is a failed
// evaluation (excluded from R(t) and the life at R, which are then conditional
// on a valid sample, counted, and warned about once per input with the count).
#pragma once

#include <optional>
#include <string>

namespace rackopt {

// True for the inputs whose values must be > 0 (load, wear.coefficient,
// surface_hardness; RandomInput::key).
bool input_must_be_positive(const std::string& key);

// Why `value` of input `key` is outside the input's domain ("is not finite",
// "is not positive"), nullopt when it is inside.
std::optional<std::string> outside_input_domain(const std::string& key, double value);

}  // namespace rackopt
