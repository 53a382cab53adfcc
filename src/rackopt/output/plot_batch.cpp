#include "rackopt/output/plot_batch.hpp"

#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <utility>

#include "rackopt/core/child_process.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/output/atomic_file.hpp"

namespace rackopt {
namespace {

namespace fs = std::filesystem;

// 16 random hex digits: the markers carry it, so no text a script prints
// (its titles come from the user) can pass for a marker of this run.
std::string random_token() {
  std::random_device device;
  std::mt19937_64 engine((static_cast<std::uint64_t>(device()) << 32) ^ device());
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(engine()));
  return text;
}

std::string seconds_text(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

}  // namespace

PlotBatch::PlotBatch(std::string dir) : dir_(std::move(dir)) {}

void PlotBatch::add(const std::string& script, const std::string& png, const std::string& svg) {
  jobs_.push_back({script, png, svg});
}

std::vector<std::string> PlotBatch::render(std::vector<std::string>& warnings) {
  std::vector<Job> jobs;
  jobs.swap(jobs_);
  const fs::path dir(dir_.empty() ? std::string(".") : dir_);
  std::vector<std::string> missing;
  // One plot alone, exactly as an unbatched caller draws it.
  const auto alone = [&](const Job& job) {
    const RenderedImages drawn = render_plot_images(dir_, job.script, job.png, job.svg, warnings);
    if (drawn.png.empty()) missing.push_back((dir / job.png).string());
    if (!job.svg.empty() && drawn.svg.empty()) missing.push_back((dir / job.svg).string());
  };
  const std::string exe = find_program(gnuplot_program());
  if (jobs.size() < 2 || exe.empty() || stop_requested()) {
    // Nothing to share, or nothing to start: each plot warns on its own.
    for (const Job& job : jobs) alone(job);
    return missing;
  }

  std::error_code ec;
  std::deque<TemporaryFileGuard> guards;  // the guards neither move nor copy
  for (const Job& job : jobs) {
    for (const std::string* image : {&job.png, &job.svg}) {
      if (image->empty()) continue;
      const std::string tmp_path = (dir / *image).string() + ".tmp";
      fs::remove(tmp_path, ec);  // a stale image from a killed run must not be taken for ours
      guards.emplace_back(tmp_path);
    }
  }
  const std::string token = random_token();
  const std::string log = ".plots.log.tmp" + token.substr(0, 6);
  guards.emplace_back((dir / log).string());

  // Per plot: its script (the PNG), `unset output` to close the image
  // before its marker; with an SVG, `reset` and the script again with
  // rackopt_svg defined, as render_plot_images does. Then `reset session`
  // so the next plot starts from gnuplot's defaults with no variable,
  // datablock or function of this one, and the marker on stderr (`set print`
  // with no file), which goes to the log.
  std::vector<std::string> arguments;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Job& job = jobs[i];
    arguments.insert(arguments.end(), {job.script, "-e", "unset output"});
    if (!job.svg.empty()) {
      arguments.insert(arguments.end(), {"-e", "reset", "-e", "rackopt_svg=1", job.script, "-e", "unset output"});
    }
    arguments.insert(arguments.end(),
                     {"-e", "reset session", "-e", "set print", "-e", "print '" + token + " " + std::to_string(i) + "'"});
  }
  ChildCommand command;
  command.program = exe;
  command.arguments = std::move(arguments);
  command.working_dir = dir.string();
  command.stderr_file = log;
  const double per_plot = plot_time_limit_seconds();
  command.time_limit_seconds = per_plot * static_cast<double>(jobs.size());
  const ChildOutcome outcome = run_child(command);

  std::set<std::size_t> marked;
  {
    std::ifstream in(dir / log);
    const std::string prefix = token + " ";
    for (std::string line; std::getline(in, line);) {
      if (line.compare(0, prefix.size(), prefix) != 0) continue;
      try {
        marked.insert(std::stoul(line.substr(prefix.size())));
      } catch (const std::exception&) {
        // not a marker: ignore
      }
    }
  }
  // A plot that fails is drawn again alone, with a log of its own: the
  // batch's log, all plots' stderr together, has nothing more to show.
  fs::remove(dir / log, ec);
  bool first_unmarked = true;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Job& job = jobs[i];
    if (marked.count(i) != 0) {
      // gnuplot got past this plot: its images are closed; each one is
      // verified and published on its own.
      for (const std::string* image : {&job.png, &job.svg}) {
        if (image->empty()) continue;
        const std::string image_path = (dir / *image).string();
        const std::string invalid = publish_verified(image_path + ".tmp", image_path);
        if (invalid.empty()) continue;
        fs::remove(image_path + ".tmp", ec);
        warnings.push_back("plot " + image_path + " not drawn: the image gnuplot wrote is not valid (" + invalid +
                           ")");
        missing.push_back(image_path);
      }
      continue;
    }
    std::string why;
    if (outcome.kind == ChildOutcome::Kind::stopped) {
      why = "stopped by " + outcome.message;
    } else if (outcome.kind == ChildOutcome::Kind::timed_out && first_unmarked) {
      why = "gnuplot did not finish within " + seconds_text(per_plot) + " s (RACKOPT_PLOT_TIMEOUT) and was killed";
    }
    first_unmarked = false;
    if (why.empty()) {
      // gnuplot ended at or before this plot: drawn alone, it either works
      // (a plot after the failing one) or fails with its own warning and log.
      alone(job);
      continue;
    }
    for (const std::string* image : {&job.png, &job.svg}) {
      if (image->empty()) continue;
      const std::string image_path = (dir / *image).string();
      fs::remove(image_path + ".tmp", ec);
      warnings.push_back("plot " + image_path + " not drawn: " + why);
      missing.push_back(image_path);
    }
  }
  return missing;
}

RenderedImages draw_or_queue(PlotBatch* batch, const std::string& dir, const std::string& script,
                             const std::string& png, const std::string& svg, std::vector<std::string>& warnings) {
  if (batch == nullptr) return render_plot_images(dir, script, png, svg, warnings);
  batch->add(script, png, svg);
  const fs::path folder(dir.empty() ? std::string(".") : dir);
  RenderedImages listed;
  listed.png = (folder / png).string();
  if (!svg.empty()) listed.svg = (folder / svg).string();
  return listed;
}

}  // namespace rackopt
