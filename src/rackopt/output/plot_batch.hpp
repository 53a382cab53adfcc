// Several plots of one output folder drawn by one gnuplot process: gnuplot's
// start (its shared objects and pngcairo's fonts, about 27 ms of CPU) is paid
// once per folder instead of once per plot (docs/performance.md, "Plots of a
// small study"). Each plot is still drawn exactly as render_plot_images draws
// it alone: between plots gnuplot runs `reset session`, which puts every
// setting back to its start and deletes the scripts' variables, datablocks
// and functions, and every script sets its terminal's size and font itself.
// The guarantees of render_plot_images hold per plot: each image is verified
// and published on its own from `<image>`.tmp, and a plot that fails is a
// warning naming its image, whichever plot of the batch it is.
#pragma once

#include <string>
#include <vector>

#include "rackopt/output/plot.hpp"

namespace rackopt {

class PlotBatch {
 public:
  // A batch for the plots of folder `dir` ("" is the current folder).
  explicit PlotBatch(std::string dir);

  // Queues `script` (a file of the folder, written before render()) to draw
  // `png` and, when `svg` is not empty, `svg`, as render_plot_images would.
  // Nothing runs until render().
  void add(const std::string& script, const std::string& png, const std::string& svg);

  // Draws every queued plot and empties the queue. Returns the paths of the
  // images not drawn, as draw_or_queue returned them, and appends one
  // warning per image not drawn, as render_plot_images would:
  // - no gnuplot, or a stop request before the start: each plot alone
  //   (render_plot_images), which warns for each without starting a process;
  // - otherwise one gnuplot process runs every script in turn, printing a
  //   marker of this run (a random token and the plot's index) to its log
  //   after each plot's images are closed; a plot with its marker is
  //   published (verified); the time limit is plot_time_limit_seconds() per
  //   plot queued, for the whole process;
  // - a plot without its marker: gnuplot stopped at or before it. When
  //   gnuplot failed (an error in a script ends it), every such plot is drawn
  //   again alone by render_plot_images, so the failing plot gets its own
  //   warning and log (`<script>.log`) and the plots after it are drawn. When
  //   the time limit killed it, the first such plot is the one that hung and
  //   is reported as timed out; the rest are drawn alone. When stopped
  //   (Ctrl-C), each such plot warns "stopped by ...".
  // The batch's log (`.plots.log.tmp<6 characters>` in the folder, a name
  // is_rackopt_temporary knows) is removed.
  std::vector<std::string> render(std::vector<std::string>& warnings);

 private:
  struct Job {
    std::string script, png, svg;
  };
  std::string dir_;
  std::vector<Job> jobs_;
};

// With `batch` null: render_plot_images(dir, script, png, svg, warnings),
// the plot drawn now. Otherwise the plot is queued in `batch` (which must be
// for `dir`) and the paths it will have once drawn are returned: the caller
// lists them at once and drops those batch->render() did not draw
// (the paths render() returns), so the order of listed files is the order of the calls.
RenderedImages draw_or_queue(PlotBatch* batch, const std::string& dir, const std::string& script,
                             const std::string& png, const std::string& svg, std::vector<std::string>& warnings);

}  // namespace rackopt
