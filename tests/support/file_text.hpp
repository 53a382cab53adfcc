// A file's bytes as a string, for comparing what a program wrote.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace rackopt::test_support {

// "" when the file is missing or empty: the tests that care check existence.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace rackopt::test_support
