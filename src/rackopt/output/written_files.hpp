// What one file-set writer (stiffness_files.hpp, wear_files.hpp) put into an
// output folder, in the shape both of its callers need: `rackopt stiffness`
// and `rackopt wear` name the files in their text and JSON, the study report
// lists them by role in summary.json and report.md (docs/output.md).
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace rackopt {

struct WrittenFiles {
  // The files a reader is pointed at, as (role, path) in the order written:
  // every table, and each plot gnuplot drew. Scripts are not listed.
  std::vector<std::pair<std::string, std::string>> listed;
  // Every path written, gnuplot scripts included, in the order written.
  std::vector<std::string> written;
  // One line per plot gnuplot could not draw (render_plot's warnings), in order.
  std::vector<std::string> warnings;

  // The path listed under `role`, "" when none is.
  std::string path_of(const std::string& role) const {
    for (const auto& [r, p] : listed) {
      if (r == role) return p;
    }
    return "";
  }

  // Removes `paths` from `listed` and `written`: the images a PlotBatch did
  // not draw (PlotBatch::render), listed when their plots were queued.
  void drop(const std::vector<std::string>& paths) {
    const auto gone = [&](const std::string& p) { return std::find(paths.begin(), paths.end(), p) != paths.end(); };
    std::erase_if(listed, [&](const auto& entry) { return gone(entry.second); });
    std::erase_if(written, gone);
  }
};

}  // namespace rackopt
