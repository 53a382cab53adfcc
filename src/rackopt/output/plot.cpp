#include "rackopt/output/plot.hpp"

#include <cstdlib>
#include <filesystem>

namespace rackopt {

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

std::string render_plot(const std::string& dir_name, const std::string& script, const std::string& png,
                        std::vector<std::string>& warnings) {
  namespace fs = std::filesystem;
  const fs::path dir(dir_name.empty() ? std::string(".") : dir_name);
  const char* env = std::getenv("RACKOPT_GNUPLOT");
  const std::string program = env != nullptr && *env != '\0' ? env : "gnuplot";
  const std::string probe = "command -v " + shell_quote(program) + " >/dev/null 2>&1";
  if (std::system(probe.c_str()) != 0) {
    warnings.push_back(program + " not found: wrote " + (dir / script).string() +
                       " but no plot (install gnuplot-nox)");
    return "";
  }
  std::error_code ec;
  fs::remove(dir / (png + ".tmp"), ec);  // a stale image from a killed run must not be taken for ours
  const std::string log = script + ".log";
  const std::string cmd = "cd " + shell_quote(dir.string()) + " && " + shell_quote(program) + " " +
                          shell_quote(script) + " >/dev/null 2>" + shell_quote(log);
  if (std::system(cmd.c_str()) != 0 || !fs::exists(dir / (png + ".tmp"))) {
    warnings.push_back("gnuplot failed on " + script + ": see " + (dir / log).string());
    fs::remove(dir / (png + ".tmp"), ec);
    return "";
  }
  fs::remove(dir / log, ec);
  ec.clear();
  fs::rename(dir / (png + ".tmp"), dir / png, ec);
  if (ec) {
    warnings.push_back("could not place the plot " + png + ": " + ec.message());
    return "";
  }
  return (dir / png).string();
}

}  // namespace rackopt
