#include <string>
#include <vector>

#include "cli.hpp"
#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_comparison.hpp"

namespace rackopt::cli {
namespace {

long parse_whole(const std::string& flag, const std::string& text, long lo, long hi) {
  std::size_t used = 0;
  long v = 0;
  try {
    v = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || v < lo || v > hi) {
    throw UsageError(flag + " needs a whole number in " + std::to_string(lo) + ".." + std::to_string(hi) +
                     ", got '" + text + "'");
  }
  return v;
}

}  // namespace

Args parse_args(int argc, char** argv) {
  Args a;
  std::vector<std::string> rest(argv + 1, argv + argc);
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const std::string& s = rest[i];
    if (s.rfind("--", 0) == 0) a.given.push_back(s.substr(0, s.find('=')));  // for check_options_apply
    auto need_value = [&](const std::string& flag) -> std::string {
      if (i + 1 >= rest.size()) throw UsageError(flag + " needs a value");
      return rest[++i];
    };
    if (s == "--set") {
      a.overrides.push_back(need_value(s));
    } else if (s.rfind("--set=", 0) == 0) {
      a.overrides.push_back(s.substr(6));
    } else if (s == "--out") {
      a.out_dir = need_value(s);
    } else if (s.rfind("--out=", 0) == 0) {
      a.out_dir = s.substr(6);
    } else if (s == "--samples") {
      a.samples = parse_whole(s, need_value(s), 1, kMaxReliabilitySamples);  // as reliability.samples
    } else if (s == "--seed") {
      a.seed = parse_whole(s, need_value(s), 0, 2147483647L);
    } else if (s == "--threads") {
      a.threads = static_cast<int>(parse_whole(s, need_value(s), 1, 1024));
    } else if (s == "--positions") {
      a.positions = static_cast<int>(parse_whole(s, need_value(s), 1, fe::kMaxFePositions));
    } else if (s == "--level") {
      a.level = static_cast<int>(parse_whole(s, need_value(s), 0, 6));  // FeOptions::level
    } else if (s == "--extended-contact") {
      a.extended_contact = true;
    } else if (s == "--pictures") {
      a.pictures = true;
    } else if (s == "--rack-supports") {
      a.rack_supports = true;
    } else if (s == "--json") {
      a.json = true;
    } else if (s == "--resume") {
      a.resume = true;
    } else if (s == "--progress") {
      a.progress = true;
    } else if (s == "-h" || s == "--help") {
      a.command = "help";
    } else if (!s.empty() && s[0] == '-') {
      throw UsageError("unknown option " + s);
    } else if (a.command.empty()) {
      a.command = s;
    } else if (a.file.empty()) {
      a.file = s;
    } else {
      throw UsageError("unexpected argument " + s);
    }
  }
  return a;
}


}  // namespace rackopt::cli
