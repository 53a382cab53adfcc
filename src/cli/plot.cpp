#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli.hpp"

namespace rackopt::cli {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string render_plot(const std::string& dir_name, const std::string& script, const std::string& png,
                        std::vector<std::string>& warnings) {
  namespace fs = std::filesystem;
  const fs::path dir(dir_name);
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    warnings.push_back("gnuplot not found: wrote " + script + " but no plot (install gnuplot-nox)");
    return "";
  }
  const std::string log = script + ".log";
  const std::string cmd = "cd '" + dir.string() + "' && gnuplot '" + script + "' >/dev/null 2>'" + log + "'";
  if (std::system(cmd.c_str()) != 0) {
    warnings.push_back("gnuplot failed on " + script + ": see " + (dir / log).string());
    return "";
  }
  std::error_code ec;
  fs::remove(dir / log, ec);
  fs::rename(dir / (png + ".tmp"), dir / png, ec);
  if (ec) {
    warnings.push_back("could not place the plot " + png + ": " + ec.message());
    return "";
  }
  return (dir / png).string();
}

}  // namespace rackopt::cli
