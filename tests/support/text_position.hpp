// Where a piece of text sits in a test's own input (1-based line and
// column), so that the position an error must name comes from the text the
// test wrote, not from the loader under test.
#pragma once

#include <string>
#include <utility>

namespace rackopt::test_support {

// {line, column} of occurrence `occurrence` (0 = the first) of `needle` in
// `text`; {0, 0} when there is no such occurrence.
inline std::pair<int, int> line_column_of(const std::string& text, const std::string& needle,
                                          std::size_t occurrence = 0) {
  std::size_t at = text.find(needle);
  for (std::size_t k = 0; k < occurrence && at != std::string::npos; ++k) at = text.find(needle, at + 1);
  if (at == std::string::npos) return {0, 0};
  int line = 1, column = 1;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

// The same as "line:column", the form to_string(SourceMark) ends with.
inline std::string position_of(const std::string& text, const std::string& needle, std::size_t occurrence = 0) {
  const auto [line, column] = line_column_of(text, needle, occurrence);
  if (line == 0) return "<needle '" + needle + "' not in the text>";
  return std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace rackopt::test_support
