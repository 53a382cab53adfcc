// rackopt command line.
//
//   rackopt check FILE [--set key=value]...
//   rackopt stiffness FILE [--set key=value]... [--out DIR] [--json]
//   rackopt wear FILE [--set key=value]... [--out DIR] [--json] [--samples N]
//                [--seed S] [--threads N]
//   rackopt run STUDY [--set key=value]... [--out DIR] [--threads N] [--resume]
//               [--json] [--progress]
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
#include "rackopt/record/evaluation_store.hpp"

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
    "  rackopt run STUDY [--set key=value]... [--out DIR] [--threads N] [--resume]\n"
    "              [--json] [--progress]\n"
    "      run a study file (studies/*.yaml: evaluate, sweep, optimize, pareto,\n"
    "      reliability); every evaluation goes to DIR/evaluations.sqlite as it\n"
    "      happens, then DIR/summary.json, CSVs, plots and DIR/report.md\n"
    "      (default DIR: out/<study name>). Ctrl-C stops cleanly and writes the\n"
    "      results so far; --resume continues without redoing recorded evaluations.\n"
    "      --set problem.<key>=value changes the problem, any other key the study\n"
    "      (e.g. --set solver.max_evaluations=50); --progress shows the progress\n"
    "      bar even when stderr is not a terminal\n"
    "\n"
    "  --set key=value   override any key of the problem, e.g. --set rack.span=\"1.2 m\"\n"
    "exit codes: 0 ok (also a study with no feasible design), 1 run failed (also a\n"
    "study whose every evaluation failed), 2 bad input, 130 study stopped by Ctrl-C\n";

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
  if (args.command != "check" && args.command != "stiffness" && args.command != "wear" && args.command != "run") {
    std::cerr << "rackopt: unknown command '" << args.command << "'\n" << kUsage;
    return kBadInput;
  }
  if (args.file.empty()) {
    std::cerr << "rackopt: " << args.command << " needs a " << (args.command == "run" ? "study" : "problem")
              << " FILE\n" << kUsage;
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
    if (args.command == "run") return cmd_run(args);
    return cmd_wear(args);
  } catch (const rackopt::InputError& e) {
    return fail(kBadInput, "input", e.what());
  } catch (const rackopt::DesignError& e) {
    return fail(kBadInput, "design:" + e.code(), std::string("impossible design (") + e.code() + "): " + e.what());
  } catch (const rackopt::record::OutputFolderConflict& e) {
    return fail(kBadInput, "output_folder", e.what());
  } catch (const std::exception& e) {
    return fail(kRunFailed, "run", std::string("run failed: ") + e.what());
  }
}
