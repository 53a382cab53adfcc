// Which options each command accepts: the one table the usage text, the
// applicability check and docs/output.md agree with.
#include <algorithm>
#include <string>
#include <vector>

#include "cli.hpp"

namespace rackopt::cli {
namespace {

struct CommandOptions {
  const char* command;
  std::vector<std::string> options;
};

const std::vector<CommandOptions>& option_table() {
  static const std::vector<CommandOptions> table = {
      {"check", {"--set", "--json"}},
      {"stiffness", {"--set", "--out", "--json"}},
      {"wear", {"--set", "--out", "--json", "--samples", "--seed", "--threads"}},
      {"run", {"--set", "--out", "--json", "--threads", "--resume", "--progress"}},
      {"fe", {"--set", "--out", "--json", "--positions", "--level", "--extended-contact", "--pictures", "--rack-supports", "--threads"}},
  };
  return table;
}

const CommandOptions* find_command(const std::string& command) {
  for (const auto& c : option_table()) {
    if (command == c.command) return &c;
  }
  return nullptr;
}

}  // namespace

std::string accepted_options(const std::string& command) {
  const CommandOptions* c = find_command(command);
  std::string out;
  if (c == nullptr) return out;
  for (const auto& o : c->options) out += (out.empty() ? "" : ", ") + o;
  return out;
}

void check_options_apply(const Args& a) {
  const CommandOptions* c = find_command(a.command);
  if (c == nullptr) return;  // help, or an unknown command (reported on its own)
  for (const std::string& given : a.given) {
    if (given == "--help") continue;
    if (std::find(c->options.begin(), c->options.end(), given) == c->options.end()) {
      throw UsageError("option " + given + " does not apply to '" + a.command + "' (" + a.command + " accepts " +
                       accepted_options(a.command) + ")");
    }
  }
}

}  // namespace rackopt::cli
