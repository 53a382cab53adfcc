// Reading a problem or study file from disk, bounded: the text is what the
// YAML loaders then parse (marked_yaml/bounded_yaml.hpp).
#pragma once

#include <string>

namespace rackopt {

// The whole text of the file at `path`; `what` names the file in messages
// ("problem file", "study file"). Only a regular file is read: a FIFO, a
// device or a socket is refused without waiting on it (a FIFO without a
// writer would block open() for ever), and at most kMaxInputBytes + 1 bytes
// are read, so a huge input costs no more than that.
// Throws InputError at SourceMark{path, 0, 0} when the path cannot be opened
// (with the system's reason), is a directory or not a regular file (naming
// its kind), or holds more than kMaxInputBytes bytes (docs/input_limits.md),
// or when it holds a NUL byte (check_path_text, core/run_limits.hpp).
std::string read_input_file(const std::string& path, const std::string& what);

}  // namespace rackopt
