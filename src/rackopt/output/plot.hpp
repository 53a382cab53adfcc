// Turning a gnuplot script into a PNG without ever leaving a half-written
// image: the script writes `<png>.tmp`, which is renamed to `<png>` only when
// gnuplot succeeded. Plots are a convenience: a missing or failing gnuplot is
// a warning for the caller to show, never an error of the run.
#pragma once

#include <string>
#include <vector>

namespace rackopt {

// Runs gnuplot on `dir`/`script` inside `dir` (the script must write
// `png`.tmp, relative names), then renames `dir`/`png`.tmp to `dir`/`png`.
// Returns the path of the PNG, or "" with one warning appended to `warnings`
// when gnuplot is missing, fails (its stderr is kept in `dir`/`script`.log)
// or the image cannot be placed.
// The program is `gnuplot` from PATH, or the one named by the environment
// variable RACKOPT_GNUPLOT (tests set it to a missing program to check the
// no-gnuplot path).
std::string render_plot(const std::string& dir, const std::string& script, const std::string& png,
                        std::vector<std::string>& warnings);

// `text` quoted for /bin/sh as one word.
std::string shell_quote(const std::string& text);

}  // namespace rackopt
