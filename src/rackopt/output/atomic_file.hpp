// Files appear whole or not at all: content goes to a temporary file in the
// same directory, is flushed, then renamed over the target (rename is atomic
// on POSIX within one file system). A crash or a full disk never leaves a
// truncated CSV that looks complete.
#pragma once

#include <string>

namespace rackopt {

// Writes `content` to `path` atomically; creates missing parent directories.
// Throws std::runtime_error naming the path and the OS error on failure.
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace rackopt
