// The one atomic file writer: a file appears whole or not at all. The content
// goes to a temporary file made by mkostemp in the target's directory (the
// same file system, so the rename is atomic), named ".<name>.tmp" and six
// characters; it is written (retrying interrupted writes), made readable
// like any other output (0644), flushed to disk and checked, then renamed
// over the target, and the directory is flushed so the rename itself
// survives a power cut. A crash, a kill -9 or a full disk never leaves a
// truncated file that looks complete: at worst the temporary file, which
// the next run holding the folder's lock removes (output/atomic_file.hpp).
// A second Ctrl-C while it writes unlinks the temporary file
// (TemporaryFileGuard).
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace rackopt {

// Looks at the written temporary file (its path) before it gets its name:
// "" to publish it, otherwise why not.
using WrittenFileCheck = std::function<std::string(const std::string& temporary_path)>;

// Writes `content` (not empty) to `path` atomically; creates missing parent
// directories. The size on disk is always checked against the content;
// `check`, when given, is asked too. Throws std::runtime_error naming the
// path and the OS error or the failed check; the temporary file is removed
// and `path` is left as it was.
void write_file_atomically(const std::string& path, std::string_view content, const WrittenFileCheck& check = {});

// Content produced in pieces: `produce(write)` calls write(piece) for each
// piece, in order (a large table written as it is formatted, never held whole).
using ContentProducer = std::function<void(const std::function<void(std::string_view piece)>& write)>;

// write_file_atomically with the content from `produce`; the same guarantees
// (the size on disk checked against the sum of the pieces, an empty content
// refused). An exception from `produce` removes the temporary file and
// propagates.
void write_file_atomically_from(const std::string& path, const ContentProducer& produce,
                                const WrittenFileCheck& check = {});

// Flushes the directory that holds `path`, so that a rename into it survives
// a power cut (best effort: some file systems refuse).
void fsync_directory_of(const std::string& path);

}  // namespace rackopt
