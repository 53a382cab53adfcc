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

// `s` with every control character (below 0x20, and DEL: line breaks, tab,
// CR, escape) as a space: user text shown on one line of a terminal or a
// file stays on that line and cannot send terminal escape sequences.
std::string one_line(std::string_view s);

// The items joined by `separator` ("a, b, c" by default; "" for none).
std::string join(const std::vector<std::string>& items, std::string_view separator = ", ");

// One CSV field by RFC 4180: quoted when it holds a comma, a quote or a line
// break, a quote inside doubled; line breaks are kept inside the quotes.
// A text cell that a spreadsheet would run as a formula (it starts with
// = + - @, a tab or a carriage return and is not a number) gets a leading
// apostrophe and quotes: "'=1+1" shows as the text =1+1. Numbers such as
// -1.5e-3, -inf and nan are written as they are.
std::string csv_field(std::string_view s);

}  // namespace rackopt
