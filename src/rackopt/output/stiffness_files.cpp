#include "rackopt/output/stiffness_files.hpp"

#include <filesystem>

#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/stiffness_report.hpp"

namespace rackopt {

WrittenFiles write_stiffness_files(const StiffnessCurve& curve, const std::string& out_dir, const std::string& title,
                                   PlotImages plots, PlotBatch* batch) {
  namespace fs = std::filesystem;
  const fs::path dir(out_dir.empty() ? std::string(".") : out_dir);
  WrittenFiles files;
  const std::string csv = (dir / "stiffness.csv").string();
  write_file_atomic_from(csv, [&](const std::function<void(std::string_view)>& write) {
    write_stiffness_csv(curve, write);
  });
  files.written.push_back(csv);
  files.listed.emplace_back("stiffness_csv", csv);
  if (plots == PlotImages::kNone) return files;
  const std::string script = (dir / "stiffness.gp").string();
  write_file_atomic(script, stiffness_gnuplot(curve, title, "stiffness.csv", "stiffness.png.tmp"));
  files.written.push_back(script);
  const RenderedImages images = draw_or_queue(batch, dir.string(), "stiffness.gp", "stiffness.png",
                                              plots == PlotImages::kPngAndSvg ? "stiffness.svg" : "", files.warnings);
  if (!images.png.empty()) {
    files.written.push_back(images.png);
    files.listed.emplace_back("stiffness_png", images.png);
  }
  if (!images.svg.empty()) files.written.push_back(images.svg);
  return files;
}

}  // namespace rackopt
