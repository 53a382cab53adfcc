#include "rackopt/marked_yaml/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "rackopt/core/error.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/marked_yaml/input_limits.hpp"

namespace rackopt {

std::string read_input_file(const std::string& path, const std::string& what) {
  check_path_text(path, what);
  const SourceMark where{path, 0, 0};
  std::error_code ec;
  // An ifstream opens a directory without complaint on Linux and reads it as
  // empty: the loader would then report the first missing key.
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(where, "", "is a directory, not a " + what + " (give the path of a .yaml file)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(where, "", "cannot open the " + what + ": " + std::strerror(errno));
  }
  std::string text(kMaxInputBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) {
    throw InputError(where, "", "cannot read the " + what + ": " + std::strerror(errno));
  }
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxInputBytes) {
    throw InputError(where, "",
                     "the " + what + " is larger than " + std::to_string(kMaxInputBytes) +
                         " bytes (1 MiB), the limit for an input file; a " + what +
                         " is a few kB (docs/input_limits.md)");
  }
  return text;
}

}  // namespace rackopt
