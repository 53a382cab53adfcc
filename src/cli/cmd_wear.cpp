// rackopt wear: Archard wear, deterministic wear life and life at
// reliability R by Monte Carlo.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/output/folder_lock.hpp"
#include "rackopt/output/plot_batch.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/progress_bar.hpp"
#include "rackopt/output/wear_files.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt::cli {

int cmd_wear(const Args& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const Drive drive = load_problem(a.file, a.overrides);
  namespace fs = std::filesystem;
  const fs::path dir = a.out_dir.empty() ? fs::path("out") / (fs::path(a.file).stem().string() + "_wear")
                                         : fs::path(a.out_dir);
  const FolderLock lock(dir.string());  // before the long part: a folder in use is refused at once
  report_stale_temporaries(lock);
  WearReliabilityOptions opt = wear_reliability_options(drive);
  opt.samples = a.samples;
  opt.seed = a.seed;
  opt.threads = a.threads > 0 ? static_cast<unsigned>(a.threads) : 0u;
  const long n = a.samples.value_or(drive.reliability.samples);
  std::unique_ptr<ProgressBar> bar;
  if (!drive.reliability.inputs.empty()) {
    bar = std::make_unique<ProgressBar>(n, "samples");
    opt.progress = bar.get();
  }
  opt.stop = [] { return stop_requested(); };
  // Nothing is written before the analysis ends: Ctrl-C ends it at once,
  // also in the parts that do not poll (the fit and its bootstrap).
  std::optional<ImmediateStopScope> immediate(std::in_place);
  const WearReliabilityResult r = run_wear_reliability(drive, opt);  // throws Interrupted on Ctrl-C
  immediate.reset();
  if (bar) bar->finish(true);  // finish the progress line before printing
  throw_if_stop_requested("wear");

  const std::string title = drive.name.empty() ? fs::path(a.file).stem().string() : drive.name;
  // The three plots from one gnuplot process (PlotBatch).
  PlotBatch batch(dir.string());
  WrittenFiles written = write_wear_files(drive, r, dir.string(), title, PlotImages::kPng, &batch);
  written.drop(batch.render(written.warnings));
  const WearFiles files = wear_files_by_role(written.listed);
  const std::vector<std::string>& warnings = written.warnings;
  throw_if_stop_requested("wear");  // the CSVs are complete; the plots were not drawn
  const double total_ms = ms_since(t0);

  std::string text = (drive.name.empty() ? std::string("rack drive") : drive.name) + "\n" + wear_summary(drive, r);
  text += "  wrote " + dir.string() + "/ (wear_profile.csv" +
          (r.lives.empty() ? std::string("") : ", life_samples.csv, reliability.csv, life_histogram.csv") +
          " and plots)\n";
  for (const std::string& w : warnings) text += "  warning: " + w + "\n";
  set_immediate_stop_output("");  // our own output follows
  if (a.json) {
    std::cerr << text;
    std::cout << wear_json(drive, r, files, total_ms) << "\n";
  } else {
    std::cout << text;
  }
  return kOk;
}

}  // namespace rackopt::cli
