#include "rackopt/output/plot.hpp"

#include <cstdlib>
#include <deque>
#include <filesystem>
#include <sstream>

#include "rackopt/core/child_process.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/output/atomic_file.hpp"

namespace rackopt {
namespace {

namespace fs = std::filesystem;

std::string seconds_text(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

}  // namespace

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

std::string gnuplot_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      // A line break ends the statement and the rest of the line would run
      // as gnuplot commands (`system(...)`); no control character belongs
      // in a title, so each one becomes a space.
      out += ' ';
      continue;
    }
    if (c == '\'') out += '\'';
    out += c;
  }
  return out + "'";
}

std::string gnuplot_program() {
  const char* env = std::getenv("RACKOPT_GNUPLOT");
  return env != nullptr && *env != '\0' ? env : "gnuplot";
}

double plot_time_limit_seconds() {
  const char* env = std::getenv("RACKOPT_PLOT_TIMEOUT");
  if (env != nullptr && *env != '\0') {
    char* end = nullptr;
    const double v = std::strtod(env, &end);
    if (end != env && *end == '\0' && v > 0) return v;
  }
  return 60.0;
}

namespace {

// The images of one gnuplot run: each is drawn into `<image>`.tmp by the
// run and published on its own.
struct Image {
  std::string name;       // file name in the folder
  std::string published;  // its path once published, else ""
};

// One gnuplot process on `arguments` inside `dir` (the script's log is
// `script`.log), then each image published from `<image>`.tmp
// (publish_verified). A warning per image not drawn.
void render(const std::string& dir_name, const std::string& script, std::vector<Image>& images,
            const std::vector<std::string>& arguments, std::vector<std::string>& warnings) {
  const fs::path dir(dir_name.empty() ? std::string(".") : dir_name);
  const auto warn_all = [&](const std::string& why) {
    for (const Image& image : images) warnings.push_back("plot " + (dir / image.name).string() + " not drawn: " + why);
  };
  const std::string program = gnuplot_program();
  const std::string exe = find_program(program);
  if (exe.empty()) {
    warnings.push_back(program + " not found: wrote " + (dir / script).string() + " but no plot (install gnuplot-nox)");
    return;
  }
  if (stop_requested()) {
    warn_all("stopped by " + stop_reason());
    return;
  }
  std::error_code ec;
  std::deque<TemporaryFileGuard> guards;  // the guards neither move nor copy
  for (const Image& image : images) {
    const std::string tmp_path = (dir / image.name).string() + ".tmp";
    fs::remove(tmp_path, ec);  // a stale image from a killed run must not be taken for ours
    guards.emplace_back(tmp_path);
  }
  const std::string log = script + ".log";

  ChildCommand command;
  command.program = exe;
  command.arguments = arguments;
  command.working_dir = dir.string();
  command.stderr_file = log;
  command.time_limit_seconds = plot_time_limit_seconds();
  const ChildOutcome outcome = run_child(command);
  std::string failure;
  switch (outcome.kind) {
    case ChildOutcome::Kind::not_started:
      warn_all(outcome.message);
      return;
    case ChildOutcome::Kind::stopped:
      failure = "stopped by " + outcome.message;
      break;
    case ChildOutcome::Kind::timed_out:
      failure = "gnuplot did not finish within " + seconds_text(command.time_limit_seconds) +
                " s (RACKOPT_PLOT_TIMEOUT) and was killed";
      break;
    case ChildOutcome::Kind::exited:
    case ChildOutcome::Kind::signaled:
      break;
  }
  if (failure.empty() && !outcome.ok()) {
    failure = "gnuplot failed on " + script + ": see " + (dir / log).string();
  }
  bool all_drawn = failure.empty();
  for (Image& image : images) {
    const std::string image_path = (dir / image.name).string();
    const std::string tmp_path = image_path + ".tmp";
    std::string why = failure;
    if (why.empty()) {
      const std::string invalid = publish_verified(tmp_path, image_path);
      if (!invalid.empty()) why = "the image gnuplot wrote is not valid (" + invalid + ")";
    }
    if (!why.empty()) {
      fs::remove(tmp_path, ec);
      warnings.push_back("plot " + image_path + " not drawn: " + why);
      all_drawn = false;
      continue;
    }
    image.published = image_path;
  }
  if (all_drawn || (fs::exists(dir / log, ec) && fs::file_size(dir / log, ec) == 0))
    fs::remove(dir / log, ec);  // nothing to see
}

}  // namespace

std::string render_plot(const std::string& dir, const std::string& script, const std::string& png,
                        std::vector<std::string>& warnings) {
  return render_plot_images(dir, script, png, "", warnings).png;
}

RenderedImages render_plot_images(const std::string& dir, const std::string& script, const std::string& png,
                                  const std::string& svg, std::vector<std::string>& warnings) {
  std::vector<Image> images{{png, ""}};
  std::vector<std::string> arguments{script};
  if (!svg.empty()) {
    // The script a second time in the same process, as SVG: `reset` puts
    // every setting back to gnuplot's start (the terminal and output are
    // the script's own), so the second pass draws what a fresh process
    // would, without a second start of gnuplot and its fonts.
    images.push_back({svg, ""});
    arguments.insert(arguments.end(), {"-e", "reset; rackopt_svg=1", script});
  }
  render(dir, script, images, arguments, warnings);
  RenderedImages out;
  out.png = images[0].published;
  if (images.size() > 1) out.svg = images[1].published;
  return out;
}

std::string gnuplot_terminal(const std::string& png_tmp, int width, int height, int font_size) {
  const std::string suffix = ".png.tmp";
  const bool png_name = png_tmp.size() > suffix.size() &&
                        png_tmp.compare(png_tmp.size() - suffix.size(), suffix.size(), suffix) == 0;
  const std::string stem = png_name ? png_tmp.substr(0, png_tmp.size() - suffix.size()) : png_tmp;
  const std::string size = std::to_string(width) + "," + std::to_string(height);
  const std::string font = std::to_string(font_size);
  // noenhanced: labels are metric keys with underscores, not subscripts.
  return "if (exists('rackopt_svg')) {\n"
         "  set terminal svg size " + size + " standalone noenhanced font 'sans-serif," + font +
         "' background rgb 'white'\n"
         "  set output " + gnuplot_quote(stem + ".svg.tmp") + "\n"
         "} else {\n"
         "  set terminal pngcairo size " + size + " noenhanced font '," + font + "'\n"
         "  set output " + gnuplot_quote(png_tmp) + "\n"
         "}\n";
}

}  // namespace rackopt
