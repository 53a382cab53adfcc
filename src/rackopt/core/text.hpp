// Small text helpers every layer uses: one definition each, so a rule (what
// counts as blank, how a CSV field is quoted) cannot drift between callers.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rackopt {

// `s` without leading and trailing white space (std::isspace).
std::string trim(std::string_view s);

// `s` in ASCII lower case (other bytes unchanged).
std::string lower(std::string_view s);

// The items joined by `separator` ("a, b, c" by default; "" for none).
std::string join(const std::vector<std::string>& items, std::string_view separator = ", ");

// One CSV field by RFC 4180: quoted when it holds a comma, a quote or a line
// break, a quote inside doubled; line breaks are kept inside the quotes.
std::string csv_field(std::string_view s);

}  // namespace rackopt
