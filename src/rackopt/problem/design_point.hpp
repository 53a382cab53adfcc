// Design variables written into a problem: a study keeps one ProblemTree and
// instantiates a Drive per design point by setting numeric keys on a copy,
// so that every check and derived default of the loader (bore radius from
// r_f, rack section from body_height, range limits, whole tooth counts)
// applies to the design exactly as if the user had written the file.
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/problem/problem_loader.hpp"

namespace rackopt {

// Writes `value_si` at `key_path` of `tree` (created if absent, like --set).
// The value is written in the key's SI unit with 17 significant digits, so
// the drive receives it bit-exactly. Count keys (pinion.teeth) need a whole
// number. Throws InputError naming the key for a key that is not numeric or
// not known (problem_key_kind), or a count that is not whole. Range checks
// happen when the drive is built (drive_from_tree).
void set_problem_value(ProblemTree& tree, const std::string& key_path, double value_si);

// A copy of `tree` with every (key, SI value) set, turned into a Drive.
// Throws what set_problem_value and drive_from_tree throw.
Drive drive_with_values(const ProblemTree& tree, std::span<const std::pair<std::string, double>> values);

}  // namespace rackopt
