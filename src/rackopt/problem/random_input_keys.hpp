// Which problem keys change the design value of which wear-reliability
// random input (core/drive.hpp, RandomInput), in one place for every caller
// that changes keys: `--set` on the command line (load_problem), a study's
// problem_set and `--set problem.<key>`, and a study's design variables.
//
// A random input given around the design follows any such change. An
// ABSOLUTE one (absolute: true) does not, so a change of a key that moves
// its design value would be silently ignored by the life at R: that is
// refused here instead (docs/yaml.md, reliability.random).
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/core/error.hpp"

namespace rackopt {

// The random inputs (RandomInput::key values) whose design value
// `problem_key` changes: "mounting.clearance" -> {"contact_ratio"}. A key
// changes an input when it is, lies under, or contains one of the keys below
// ("pinion" and "wear.hardness.coefficients[0]" count; list indices and
// spaces around the key are ignored):
//  * contact_ratio: pinion.teeth, module, pressure_angle, profile_shift,
//    addendum, dedendum, tip_radius; rack.addendum, rack.dedendum;
//    mounting.clearance; effects.interference_limit (it caps the contact
//    ratio's path);
//  * wear.coefficient: wear.coefficient;
//  * load: load.force, load.torque and, when the load is given as a torque
//    (F = T / r_b), pinion.teeth, module and pressure_angle;
//  * surface_hardness: the surface, coefficients, values, kind and
//    hardness_unit of wear.hardness, wear.pinion_hardness and
//    wear.rack_hardness.
// Unrelated keys (materials, face widths, rack body, load factors, duty,
// reliability.*) change none: an empty list.
std::vector<std::string> random_inputs_changed_by(const std::string& problem_key, const Drive& drive);

// Throws InputError at `mark` with key path `key_path` (what the user wrote,
// e.g. "variables.mounting.clearance" or "mounting.clearance") when
// `problem_key` changes the design value of a random input that `drive`
// gives as an absolute distribution; the message names that input's key
// (reliability.random[i]) and says how to fix it.
void check_absolute_random_inputs(const Drive& drive, const std::string& problem_key, const SourceMark& mark,
                                  const std::string& key_path);

// check_absolute_random_inputs for each `--set` assignment "key=value" of
// `overrides` (mark "<command line>", key path the override's key).
void check_overrides_against_absolute_inputs(const Drive& drive, const std::vector<std::string>& overrides);

}  // namespace rackopt
