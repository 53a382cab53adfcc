// The study file's `verify` key (docs/studies.md, `verify`):
//   verify: fe                                   # 4 positions, level 0
//   verify: {method: fe, positions: 8, level: 1, extended_contact: off, rack_supports: off}
#pragma once

#include <optional>

#include "rackopt/marked_yaml/marked_map.hpp"
#include "rackopt/study/fe_verify_spec.hpp"

namespace rackopt::studyfile {

// nullopt when `top` has no verify key. Throws InputError at the value's
// file:line:column naming the key ("verify.positions") for: a word other
// than fe, a list, an unknown key (with "did you mean"), a method other
// than fe, positions outside 1..64, a level outside 0..6, a switch that is
// not on/off.
std::optional<study::FeVerifySpec> read_verify_section(const MarkedMap& top);

}  // namespace rackopt::studyfile
