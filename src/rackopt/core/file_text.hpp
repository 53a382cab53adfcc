// Reading a whole file the program wrote itself (a solver's log and
// results). User inputs go through read_input_file (marked_yaml/input_file.hpp)
// instead, which bounds what it reads.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace rackopt {

// The bytes of the file at `path`; nullopt when it cannot be opened.
std::optional<std::string> read_file_text(const std::filesystem::path& path);

}  // namespace rackopt
