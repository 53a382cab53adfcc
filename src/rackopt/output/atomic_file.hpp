// Files appear whole or not at all: content goes to a temporary file
// `<path>.tmp.<pid>` in the same directory, is written, fsynced and verified
// (check_output_file: size and format, docs/output.md "Guarantees"), then
// renamed over the target (atomic on POSIX within one file system) and the
// directory fsynced. A crash, a kill -9 or a full disk never leaves a
// truncated CSV that looks complete; at worst a temporary file, which the
// next run holding the folder lock removes (remove_stale_temporaries).
#pragma once

#include <string>
#include <vector>

namespace rackopt {

// Writes `content` (not empty) to `path` atomically; creates missing parent
// directories. Throws std::runtime_error naming the path and the OS error
// (or what the verification found) on failure; the temporary file is
// removed and `path` is left as it was.
void write_file_atomic(const std::string& path, const std::string& content);

// Renames the finished temporary file `tmp` (written by another program,
// e.g. gnuplot) to `path` after verifying it as `path`'s format and fsyncing
// it and the directory. Returns "" on success, else why not (then `tmp` is
// removed and `path` untouched).
std::string publish_verified(const std::string& tmp, const std::string& path);

// True for the names of temporary files rackopt's writers create in an
// output folder: "<name>.tmp.<digits>" (write_file_atomic), "<name>.png.tmp"
// (plots: the gnuplot scripts write there) and ".<name>.tmp" + 6 characters
// (the evaluations.csv export, mkstemp).
bool is_rackopt_temporary(const std::string& file_name);

// Removes every file of `dir` (not its subfolders) that is_rackopt_temporary
// names and returns their names. Call only while holding the folder's lock
// (FolderLock): every rackopt writer holds it while it writes there, so
// whatever temporary file is present then was left by a process that died
// (kill -9, power cut), whatever its pid says (a pid may since have been
// reused by an unrelated process).
std::vector<std::string> remove_stale_temporaries(const std::string& dir);

}  // namespace rackopt
