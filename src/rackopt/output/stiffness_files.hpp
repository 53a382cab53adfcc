// The stiffness file set of a drive, the same for `rackopt stiffness` and a
// study's best design: stiffness.csv (columns in docs/output.md), and with
// plots stiffness.gp and stiffness.png.
#pragma once

#include <string>

#include "rackopt/output/plot_batch.hpp"
#include "rackopt/output/written_files.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt {

// Writes stiffness.csv (role "stiffness_csv") into `out_dir` ("" is the
// current folder; it must exist), and unless `plots` is kNone the script
// stiffness.gp and the image stiffness.png (role "stiffness_png", listed only
// when gnuplot drew it; with kPngAndSvg also stiffness.svg, in `written`) with `title` on top. Every file atomically
// (write_file_atomic, render_plot). A plot gnuplot cannot draw is a warning
// in the result; throws only when a file cannot be written. With `batch`
// (for `out_dir`) the plot is queued there and listed as drawn
// (draw_or_queue): the caller drops what batch->render() did not draw.
WrittenFiles write_stiffness_files(const StiffnessCurve& curve, const std::string& out_dir, const std::string& title,
                                   PlotImages plots = PlotImages::kPng, PlotBatch* batch = nullptr);

}  // namespace rackopt
