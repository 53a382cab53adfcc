// Turning a gnuplot script into a PNG without ever publishing a half-written
// image and without ever hanging: the script writes `<png>.tmp`; gnuplot runs
// in its own process group with a time limit; the image gets its final name
// only when gnuplot succeeded and the file passes check_output_file (PNG
// signature, IEND chunk at the end). Plots are a convenience: a missing,
// failing, hung or interrupted gnuplot is a warning naming the file for the
// caller to show, never an error of the run. Every script can also draw
// its plot as SVG (gnuplot_terminal): report.html inlines those.
#pragma once

#include <string>
#include <vector>

namespace rackopt {

// Runs gnuplot on `dir`/`script` inside `dir` (the script must write
// `png`.tmp, relative names), stdin from /dev/null, stdout discarded, stderr
// to `dir`/`script`.log; then publishes `dir`/`png`.tmp as `dir`/`png`
// (publish_verified). Returns the path of the PNG, or "" with one warning
// naming the PNG appended to `warnings` when gnuplot is missing, fails, runs
// past the time limit (its process group is killed), the stop request is set
// (Ctrl-C: the group is killed at once), or the image fails its check
// (truncated by a full disk: gnuplot itself exits 0 then).
// The program is `gnuplot` from PATH, or the one named by the environment
// variable RACKOPT_GNUPLOT (tests set it to a missing program or to a
// wrapper). The time limit is plot_time_limit_seconds().
std::string render_plot(const std::string& dir, const std::string& script, const std::string& png,
                        std::vector<std::string>& warnings);

// Which images a file set draws from each plot script it writes.
enum class PlotImages {
  kNone,       // the tables only: no script, no image
  kPng,        // the script and its PNG
  kPngAndSvg,  // the script, its PNG and its SVG, both from one gnuplot run (render_plot_images)
};

// The paths render_plot_images published; "" for an image not drawn.
struct RenderedImages {
  std::string png, svg;
};

// render_plot, and when `svg` is not empty the same plot as SVG from the
// same gnuplot process: the script runs twice (the second time after
// `reset`, with rackopt_svg defined), so a report pays for one gnuplot start
// per plot. Each image is verified and published on its own (a PNG drawn
// while the SVG failed is kept); one warning per image not drawn. One time
// limit for the whole run.
RenderedImages render_plot_images(const std::string& dir, const std::string& script, const std::string& png,
                                  const std::string& svg, std::vector<std::string>& warnings);

// The terminal and output lines every plot script starts with: a PNG of
// `width` x `height` pixels, text `font_size` pixels high, into `png_tmp` (the name render_plot expects,
// "<name>.png.tmp"); when gnuplot runs with rackopt_svg defined
// (render_plot_images' second pass), the same plot as a standalone SVG of the same size into
// "<name>.svg.tmp". One script for both: the PNG and the SVG cannot drift
// apart, and the script stays runnable by hand (`gnuplot x.gp`).
std::string gnuplot_terminal(const std::string& png_tmp, int width, int height, int font_size = 11);

// The gnuplot program to run: the environment variable RACKOPT_GNUPLOT when
// set and not empty, else "gnuplot" (found on PATH by find_program).
std::string gnuplot_program();

// Seconds one gnuplot run may take: RACKOPT_PLOT_TIMEOUT (a positive number)
// when set, else 60.
double plot_time_limit_seconds();

// `text` quoted for /bin/sh as one word.
std::string shell_quote(const std::string& text);

// `text` as one gnuplot single-quoted string, the only way user text (study
// and problem names, labels, file names) enters a plot script: a quote
// inside is doubled, and every control character (line breaks, tab, CR,
// escape, DEL) becomes a space, so the string stays on its statement's line
// and no text can start a command of its own. Inside single quotes gnuplot
// (5.4, checked by tests/output/plot_scripts_test.cpp with the real program)
// does no backquote command substitution, no `@` macro expansion and no
// backslash escapes: those characters are kept as they are and shown.
std::string gnuplot_quote(const std::string& text);

}  // namespace rackopt
