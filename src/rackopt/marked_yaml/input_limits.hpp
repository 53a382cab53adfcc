// Limits that every YAML input (problem files, study files, `--set` values)
// is held to, so that any input, however hostile, is refused in bounded time
// and memory. docs/input_limits.md explains them; the shipped problems and
// studies are a few kB with a few hundred nodes, far inside every limit.
#pragma once

#include <cstddef>

namespace rackopt {

// A problem or study file (or any YAML text) larger than this is refused
// before it is parsed; files are read at most this many bytes (+1 to notice
// more). 1 MiB is hundreds of times the largest real problem file.
constexpr std::size_t kMaxInputBytes = 1024 * 1024;

// Nesting depth of the document (the problem schema needs 5 levels).
constexpr int kMaxTreeDepth = 32;

// Nodes (keys, values, list items) after alias expansion: an alias counts as
// a full copy of what it refers to ("billion laughs").
constexpr int kMaxTreeNodes = 20000;

// Bytes of text (keys and scalar values) after alias expansion: one anchor on
// a large scalar repeated by many aliases is refused even though it has few
// nodes. Twice the file limit: without aliases a document can never reach it.
constexpr std::size_t kMaxExpandedTextBytes = 2 * kMaxInputBytes;

}  // namespace rackopt
