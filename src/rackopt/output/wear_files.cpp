#include "rackopt/output/wear_files.hpp"

#include <filesystem>

#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/plot_batch.hpp"

namespace rackopt {

WrittenFiles write_wear_files(const Drive& drive, const WearReliabilityResult& r, const std::string& out_dir,
                              const std::string& title, PlotImages plots, PlotBatch* batch) {
  namespace fs = std::filesystem;
  const fs::path dir(out_dir.empty() ? std::string(".") : out_dir);
  WrittenFiles files;
  auto table = [&](const std::string& role, const std::string& name, const std::string& content) {
    const std::string path = (dir / name).string();
    write_file_atomic(path, content);
    files.written.push_back(path);
    files.listed.emplace_back(role, path);
  };
  auto plot = [&](const std::string& role, const std::string& script_name, const std::string& script,
                  const std::string& png_name) {
    if (plots == PlotImages::kNone) return;
    const std::string script_path = (dir / script_name).string();
    write_file_atomic(script_path, script);
    files.written.push_back(script_path);
    const std::string svg_name =
        plots == PlotImages::kPngAndSvg ? fs::path(png_name).replace_extension(".svg").string() : std::string();
    const RenderedImages images = draw_or_queue(batch, dir.string(), script_name, png_name, svg_name, files.warnings);
    if (!images.png.empty()) {
      files.written.push_back(images.png);
      files.listed.emplace_back(role, images.png);
    }
    if (!images.svg.empty()) files.written.push_back(images.svg);
  };
  table("wear_profile_csv", "wear_profile.csv", wear_profile_csv(r.nominal));
  plot("wear_profile_png", "wear_profile.gp", wear_profile_gnuplot(title, r.nominal), "wear_profile.png");
  // Without random inputs there are no sampled lives, only the nominal profile.
  if (!r.lives.empty()) {
    table("life_samples_csv", "life_samples.csv", life_samples_csv(r));
    table("reliability_csv", "reliability.csv", reliability_csv(drive, r));
    table("life_histogram_csv", "life_histogram.csv", life_histogram_csv(r));
    plot("life_histogram_png", "life_histogram.gp", life_histogram_gnuplot(title), "life_histogram.png");
    plot("reliability_png", "reliability.gp", reliability_gnuplot(title), "reliability.png");
  }
  return files;
}

WearFiles wear_files_by_role(const std::vector<std::pair<std::string, std::string>>& listed) {
  auto path_of = [&](const std::string& role) {
    for (const auto& [r, p] : listed) {
      if (r == role) return p;
    }
    return std::string();
  };
  WearFiles f;
  f.wear_profile_csv = path_of("wear_profile_csv");
  f.life_samples_csv = path_of("life_samples_csv");
  f.reliability_csv = path_of("reliability_csv");
  f.histogram_csv = path_of("life_histogram_csv");
  f.wear_profile_png = path_of("wear_profile_png");
  f.histogram_png = path_of("life_histogram_png");
  f.reliability_png = path_of("reliability_png");
  return f;
}

}  // namespace rackopt
