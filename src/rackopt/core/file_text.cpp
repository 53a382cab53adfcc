#include "rackopt/core/file_text.hpp"

#include <fstream>
#include <sstream>

namespace rackopt {

std::optional<std::string> read_file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace rackopt
