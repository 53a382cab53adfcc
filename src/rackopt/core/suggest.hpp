// "Did you mean ..." for every name a user can mistype: problem keys, study
// keys, metric names, choices. One rule everywhere, so messages agree.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rackopt {

// Levenshtein distance (insert, delete, substitute; case-sensitive).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word` ignoring case (the first one on ties) when
// it is a near miss: distance <= max(2, a third of the word's length).
// nullopt when there is no candidate or none is near.
std::optional<std::string> closest_name(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace rackopt
