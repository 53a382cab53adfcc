// What "verified" means for an output file before it gets its final name
// (docs/output.md, "Guarantees"): a file that passed is complete as far as
// its format can tell, so a truncated image or table is never published.
#pragma once

#include <string>

namespace rackopt {

// Checks the file at `path` as the format named by `format_name` (a file name:
// its extension decides; ".tmp" and ".tmp.<digits>" suffixes are ignored):
//  * every file: exists, size > 0 and, when expected_size >= 0, exactly that size;
//  * .png: the 8-byte PNG signature at the start and an IEND chunk (with its
//    CRC) as the last 12 bytes;
//  * .svg: "</svg>" in the last bytes; .html: "</html>" in the last bytes;
//  * .json: one complete JSON value (balanced objects/arrays/strings, nothing
//    but white space after it);
//  * .csv, .md, .gp: ends with a newline;
//  * any other extension: refused ("no completeness check for the format"),
//    so a new format cannot be published unverified by accident.
// Returns "" when the file passes, else what is wrong ("empty", "no IEND
// chunk at the end (truncated PNG)", ...).
std::string check_output_file(const std::string& path, const std::string& format_name, long long expected_size = -1);

// The JSON part of the check on text in memory: "" or what is wrong.
std::string check_json_complete(const std::string& text);

}  // namespace rackopt
