// The output folder's files: written with the one atomic writer
// (core/atomic_file.hpp) and verified by their format before they get their
// names (check_output_file: size and format, docs/output.md "Guarantees");
// plots published the same way; the temporary files a crash can leave, and
// their removal by the next run that holds the folder's lock.
#pragma once

#include "rackopt/core/atomic_file.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace rackopt {

// Writes `content` (not empty) to `path` with write_file_atomically, the
// temporary file checked by check_output_file as `path`'s format. Throws
// std::runtime_error naming the path and the OS error (or what the check
// found); `path` is then left as it was.
void write_file_atomic(const std::string& path, const std::string& content);

// The same with the content produced in pieces (write_file_atomically_from):
// a table of a hundred thousand rows is written as it is formatted.
void write_file_atomic_from(const std::string& path, const ContentProducer& produce);

// Renames the finished temporary file `tmp` (written by another program,
// e.g. gnuplot) to `path` after verifying it as `path`'s format and fsyncing
// it and the directory. Returns "" on success, else why not (then `tmp` is
// removed and `path` untouched).
std::string publish_verified(const std::string& tmp, const std::string& path);

// True for the names of temporary files rackopt's writers create in an
// output folder: ".<name>.tmp" + 6 characters (write_file_atomically),
// "<name>.png.tmp" and "<name>.svg.tmp" (plots: the gnuplot scripts write there) and
// "<name>.tmp.<digits>" (the pid-suffixed names that folders written by
// earlier rackopt builds may hold).
bool is_rackopt_temporary(const std::string& file_name);

// Removes every file of `dir` (not its subfolders) that is_rackopt_temporary
// names and returns their names. Call only while holding the folder's lock
// (FolderLock): every rackopt writer holds it while it writes there, so
// whatever temporary file is present then was left by a process that died
// (kill -9, power cut), whatever its pid says (a pid may since have been
// reused by an unrelated process).
std::vector<std::string> remove_stale_temporaries(const std::string& dir);

}  // namespace rackopt
