#include "rackopt/study_report/study_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/plot_batch.hpp"
#include "rackopt/output/stiffness_files.hpp"
#include "rackopt/output/wear_files.hpp"
#include "rackopt/study_report/design_tables.hpp"
#include "rackopt/study_report/fe_verification_report.hpp"
#include "rackopt/study_report/front_quality_report.hpp"
#include "rackopt/study_report/markdown_text.hpp"
#include "rackopt/study_report/report_html.hpp"
#include "rackopt/study_report/report_markdown.hpp"
#include "rackopt/study_report/study_plots.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;

std::string ReportFiles::get(const std::string& role) const {
  for (const auto& [r, p] : entries) {
    if (r == role) return p;
  }
  return "";
}

StudyReport write_study_report(const StudySpec& spec, const StudyResult& result, const std::string& out_dir_text) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path dir(out_dir_text.empty() ? std::string(".") : out_dir_text);
  fs::create_directories(dir);
  StudyReport rep;
  rep.warnings = result.warnings;
  // Plots and the stiffness curve warn after the run's warnings, whatever
  // order the files are written in.
  std::vector<std::string> plot_warnings;
  // report.html shows each plot as SVG, drawn with its PNG by the same
  // gnuplot run from the same script; the SVG stays next to the PNG for
  // documents that want vector figures.
  const PlotImages images = !spec.output.plots   ? PlotImages::kNone
                            : spec.output.report ? PlotImages::kPngAndSvg
                                                 : PlotImages::kPng;

  // Every plot of the folder is queued and drawn by one gnuplot process
  // (PlotBatch) once all scripts are written; the PNGs are listed where
  // their scripts are written, and those not drawn are dropped after.
  PlotBatch batch(dir.string());

  auto write = [&](const std::string& name, const std::string& content) {
    const std::string path = (dir / name).string();
    write_file_atomic(path, content);
    rep.written.push_back(path);
    return path;
  };
  auto plot = [&](const std::string& role, const std::string& script_name, const std::string& script,
                  const std::string& png) {
    if (!spec.output.plots) return;
    write(script_name, script);
    const std::string svg =
        images == PlotImages::kPngAndSvg ? fs::path(png).replace_extension(".svg").string() : std::string();
    const RenderedImages drawn = draw_or_queue(&batch, dir.string(), script_name, png, svg, plot_warnings);
    if (!drawn.png.empty()) {
      rep.files.add(role, drawn.png);
      rep.written.push_back(drawn.png);
    }
    if (!drawn.svg.empty()) rep.written.push_back(drawn.svg);
  };
  auto take = [&](const WrittenFiles& files) {
    for (const auto& [role, path] : files.listed) rep.files.add(role, path);
    rep.written.insert(rep.written.end(), files.written.begin(), files.written.end());
    plot_warnings.insert(plot_warnings.end(), files.warnings.begin(), files.warnings.end());
  };

  const std::vector<std::string> labels = metric_labels(spec, result);
  const std::string title = spec.name.empty() ? std::string("study") : spec.name;

  if (const auto best = best_table(spec, labels, result)) rep.files.add("best_csv", write("best.csv", best->text));
  const std::optional<DesignTable> front = front_table(spec, labels, result);
  if (front) rep.files.add("front_csv", write("front.csv", front->text));
  const std::optional<DesignTable> sweep = sweep_table(spec, labels, result);
  if (sweep) rep.files.add("sweep_csv", write("sweep.csv", sweep->text));
  if (const auto history = history_table(spec, result)) rep.files.add("history_csv", write("history.csv", *history));
  const std::optional<std::string> hypervolume = hypervolume_table(result);
  if (hypervolume) rep.files.add("hypervolume_csv", write("hypervolume.csv", *hypervolume));

  if (spec.output.stiffness_curve) {
    if (result.best_curve) {
      const std::string which = spec.kind == StudyKind::kPareto ? "chosen design" : "best design";
      take(write_stiffness_files(*result.best_curve, dir.string(), title + ": stiffness of the " + which,
                                 images, &batch));
    } else if (!result.best_curve_error.empty()) {
      plot_warnings.push_back(result.best_curve_error);
    }
  }

  // reliability: the files of `rackopt wear` for the study's design.
  if (result.reliability && result.best_drive) {
    take(write_wear_files(*result.best_drive, *result.reliability, dir.string(), title, images, &batch));
  }

  write_fe_verification_files(spec, result, rep.files, write, plot);

  const std::size_t n_obj = spec.objectives.size();
  if (front && n_obj >= 2 && n_obj <= 4) {
    plot("pareto_png", "pareto.gp", pareto_gnuplot(spec, *front, result.evaluations_csv_path), "pareto.png");
  }
  bool any_history = false;
  for (double h : result.best_history) any_history = any_history || std::isfinite(h);
  if (hypervolume) {
    // A front's convergence is its hypervolume, not its first objective.
    plot("history_png", "history.gp", hypervolume_gnuplot(spec, result.best_history.size()), "history.png");
  } else if (any_history && !spec.objectives.empty()) {
    plot("history_png", "history.gp", history_gnuplot(spec, spec.objectives[0].label, result.best_history.size()),
         "history.png");
  }
  if (sweep && !spec.variables.empty() && !labels.empty()) {
    plot("sweep_png", "sweep.gp", sweep_gnuplot(spec, *sweep, labels), "sweep.png");
  }
  {
    const std::vector<std::string> missing = batch.render(plot_warnings);
    const auto drawn = [&](const std::string& path) {
      return std::find(missing.begin(), missing.end(), path) == missing.end();
    };
    std::erase_if(rep.written, [&](const std::string& path) { return !drawn(path); });
    std::erase_if(rep.files.entries, [&](const auto& entry) { return !drawn(entry.second); });
  }
  if (!result.evaluations_csv_path.empty() && fs::exists(result.evaluations_csv_path)) {
    rep.files.add("evaluations_csv", result.evaluations_csv_path);
  }
  if (!result.database_path.empty() && fs::exists(result.database_path)) {
    rep.files.add("database", result.database_path);
  }
  // The SVG each listed PNG's gnuplot run drew beside it, inlined in report.html.
  std::map<std::string, std::string> svg_by_target;
  if (spec.output.report) {
    std::size_t plots = 0;
    for (const auto& entry : rep.files.entries) {
      const fs::path png(entry.second);
      if (png.extension() != ".png") continue;
      const std::string svg = fs::path(png).replace_extension(".svg").string();
      if (std::find(rep.written.begin(), rep.written.end(), svg) == rep.written.end()) continue;
      std::ifstream in(svg, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      svg_by_target[markdown_link_destination(link_target(dir, entry.second))] = inline_svg(text.str(), "plot" + std::to_string(++plots) + "-");
    }
  }
  for (const auto& w : plot_warnings) rep.warnings.push_back(w);

  const std::string summary_path = (dir / "summary.json").string();
  if (spec.output.report) {
    std::string md = report_markdown(spec, result, rep.files, rep.warnings, dir);
    // summary.json does not exist yet: link it by hand (it will, below).
    md += "Summary for programs: [summary.json](summary.json)\n";
    rep.files.add("report_md", write("report.md", md));
    rep.files.add("report_html", write("report.html", report_html(md, "Study: " + spec.name, svg_by_target)));
  }
  rep.files.add("summary_json", summary_path);
  ReportTimings timings;
  timings.run_seconds = result.seconds;
  timings.report_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rep.summary_json = study_summary_json(spec, result, rep.files, timings, rep.warnings);
  write("summary.json", rep.summary_json + "\n");
  return rep;
}

}  // namespace rackopt::study_report
