// rackopt command line.
//
//   rackopt check FILE [--set key=value]...
//   rackopt stiffness FILE [--set key=value]... [--out DIR] [--json]
//   rackopt wear FILE [--set key=value]... [--out DIR] [--json] [--samples N]
//                [--seed S] [--threads N]
//
// Exit codes: 0 ok, 1 run failed, 2 bad input (file, key, value or an
// impossible design). With --json exactly one JSON object goes to stdout and
// everything meant for people goes to stderr.
#include <iostream>
#include <string>

#include <gsl/gsl_errno.h>

#include "cli.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/output/json_writer.hpp"

namespace {

using namespace rackopt::cli;

const char* kUsage =
    "usage:\n"
    "  rackopt check FILE [--set key=value]...\n"
    "      validate a problem file and print the contact geometry\n"
    "  rackopt stiffness FILE [--set key=value]... [--out DIR] [--json]\n"
    "      mesh stiffness over one rack span: DIR/stiffness.csv, DIR/stiffness.png\n"
    "      (default DIR: out/<problem name>); --json prints one JSON object on stdout\n"
    "  rackopt wear FILE [--set key=value]... [--out DIR] [--json]\n"
    "               [--samples N] [--seed S] [--threads N]\n"
    "      Archard wear along both flanks, wear life, and life at reliability R by\n"
    "      Monte Carlo (problem keys wear, duty, reliability; docs/yaml.md)\n"
    "\n"
    "  --set key=value   override any key of the problem, e.g. --set rack.span=\"1.2 m\"\n"
    "exit codes: 0 ok, 1 run failed, 2 bad input\n";

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();  // GSL would abort() the process otherwise
  Args args;
  try {
    args = parse_args(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << "rackopt: " << e.what() << "\n" << kUsage;
    return kBadInput;
  }
  if (args.command.empty() || args.command == "help") {
    std::cerr << kUsage;
    return args.command == "help" ? kOk : kBadInput;
  }
  if (args.command != "check" && args.command != "stiffness" && args.command != "wear") {
    std::cerr << "rackopt: unknown command '" << args.command << "'\n" << kUsage;
    return kBadInput;
  }
  if (args.file.empty()) {
    std::cerr << "rackopt: " << args.command << " needs a problem FILE\n" << kUsage;
    return kBadInput;
  }
  auto fail = [&](int code, const std::string& kind, const std::string& msg) {
    if (args.json) {
      rackopt::JsonWriter j;
      j.begin_object().key("ok").value(false).key("error").value(kind).key("message").value(msg).end_object();
      std::cout << j.str() << "\n";
    }
    std::cerr << "rackopt: " << msg << "\n";
    return code;
  };
  try {
    if (args.command == "check") return cmd_check(args);
    if (args.command == "stiffness") return cmd_stiffness(args);
    return cmd_wear(args);
  } catch (const rackopt::InputError& e) {
    return fail(kBadInput, "input", e.what());
  } catch (const rackopt::DesignError& e) {
    return fail(kBadInput, "design:" + e.code(), std::string("impossible design (") + e.code() + "): " + e.what());
  } catch (const std::exception& e) {
    return fail(kRunFailed, "run", std::string("run failed: ") + e.what());
  }
}
