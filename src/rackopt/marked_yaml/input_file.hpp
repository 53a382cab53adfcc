// Reading a problem or study file from disk, bounded: the text is what the
// YAML loaders then parse (marked_yaml/bounded_yaml.hpp).
#pragma once

#include <string>

namespace rackopt {

// The whole text of the file at `path`; `what` names the file in messages
// ("problem file", "study file"). Reads at most kMaxInputBytes + 1 bytes,
// whatever the file is (a regular file, a pipe, /dev/zero), so a huge or
// endless input costs no more than that.
// Throws InputError at SourceMark{path, 0, 0} when the path cannot be opened
// (with the system's reason), is a directory, or holds more than
// kMaxInputBytes bytes (docs/input_limits.md), or when it holds a NUL byte
// (check_path_text, core/run_limits.hpp).
std::string read_input_file(const std::string& path, const std::string& what);

}  // namespace rackopt
