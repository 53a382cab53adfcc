// The wear file set of a drive's wear reliability analysis, the same for
// `rackopt wear` and a reliability study: wear_profile.csv, and with Monte
// Carlo lives life_samples.csv, reliability.csv and life_histogram.csv; with
// plots a gnuplot script and a PNG beside each of wear_profile,
// life_histogram and reliability (columns in docs/output.md).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/output/plot_batch.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/output/written_files.hpp"

namespace rackopt {

// Writes the wear file set of `r` (the analysis of `drive`) into `out_dir`
// ("" is the current folder; it must exist). Roles, in the order written:
// "wear_profile_csv", "wear_profile_png", and when r.lives is not empty
// "life_samples_csv", "reliability_csv", "life_histogram_csv",
// "life_histogram_png", "reliability_png"; the PNGs (and their *.gp
// scripts) unless `plots` is kNone, each listed only when gnuplot drew it;
// with kPngAndSvg each plot's SVG too (in `written`, not listed). `title`
// heads every plot. Every file atomically; a plot gnuplot cannot draw is a
// warning in the result; throws only when a file cannot be written. With
// `batch` (for `out_dir`) the plots are queued there and listed as drawn
// (draw_or_queue): the caller drops what batch->render() did not draw.
WrittenFiles write_wear_files(const Drive& drive, const WearReliabilityResult& r, const std::string& out_dir,
                              const std::string& title, PlotImages plots = PlotImages::kPng,
                              PlotBatch* batch = nullptr);

// The paths wear_json names, looked up by the roles above in `listed`
// ((role, path) pairs; "" for a role not there).
WearFiles wear_files_by_role(const std::vector<std::pair<std::string, std::string>>& listed);

}  // namespace rackopt
