// rackopt command line: parses it (command_line.cpp; `rackopt --help`,
// `rackopt COMMAND --help`, docs/cli.md), runs the command and maps its
// outcome to an exit code.
//
// Exit codes (docs/output.md, "Exit codes"): 0 ok, 1 run failed (also a
// result file that cannot be written), 2 bad input, a usage error or an
// output-folder conflict, 130 stopped by SIGINT (Ctrl-C) or SIGTERM. With
// --json exactly one JSON object goes to stdout (on every error too) and
// everything meant for people goes to stderr.
#include <csignal>
#include <iostream>
#include <memory>
#include <string>

#include <gsl/gsl_errno.h>

#include "cli.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/fe/ccx_runner.hpp"
#include "rackopt/fe/gmsh_library.hpp"
#include "rackopt/output/folder_lock.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/record/evaluation_store.hpp"
#ifdef RACKOPT_WITH_MPI
#include "rackopt/mpi/mpi_job.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/studyfile/study_loader.hpp"
#endif

namespace {

using namespace rackopt::cli;

// The one JSON error object of --json: {"ok": false, "error": kind, "message": msg}.
void print_json_error(const std::string& kind, const std::string& msg) {
  rackopt::JsonWriter j;
  j.begin_object().key("ok").value(false).key("error").value(kind).key("message").value(msg).end_object();
  std::cout << j.str() << "\n";
}

}  // namespace

#ifdef RACKOPT_WITH_MPI
// Ranks 1..N-1 of `mpirun -np N rackopt run STUDY ...`: load the same study
// and compute the designs rank 0 sends (mpi/mpi_job.hpp). Silent: rank 0
// alone prints, and reports a rank that could not start.
int mpi_worker(rackopt::mpi::MpiJob& job, int argc, char** argv) {
  std::string why_not;
  std::unique_ptr<rackopt::study::StudyProblem> problem;
  unsigned threads = 1;
  try {
    const Args args = parse_command_line(argc, argv).args;
    if (args.threads > 0) threads = static_cast<unsigned>(args.threads);
    if (args.command == "run" && !args.file.empty()) {
      const rackopt::study::StudySpec spec = rackopt::studyfile::load_study_file(args.file, args.overrides);
      problem = std::make_unique<rackopt::study::StudyProblem>(spec);
    } else {
      why_not = "only 'rackopt run' uses the MPI ranks";
    }
  } catch (const std::exception& e) {
    why_not = e.what();
  }
  return job.serve(problem.get(), why_not, threads);
}
#endif

int main(int argc, char** argv) {
  gsl_set_error_handler_off();  // GSL would abort() the process otherwise
#ifdef RACKOPT_WITH_MPI
  // Under mpirun: every rank joins the job before anything else; rank 0
  // goes on as the program (the job's destructor stops the workers on every
  // way out), the others serve.
  std::unique_ptr<rackopt::mpi::MpiJob> mpi_job;
  if (rackopt::mpi::MpiJob::launched()) {
    mpi_job = std::make_unique<rackopt::mpi::MpiJob>(&argc, &argv);
    if (mpi_job->rank() > 0) return mpi_worker(*mpi_job, argc, argv);
  }
#endif
  // Known before parsing, so that a usage error is a JSON object too.
  const bool json = json_requested(argc, argv);
  bool args_command_empty = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a(argv[i]);
    if (!a.empty() && a[0] != '-') args_command_empty = false;
  }
  CommandLine line;
  try {
    line = parse_command_line(argc, argv);
  } catch (const UsageError& e) {
    if (json) print_json_error("usage", e.what());
    std::cerr << "rackopt: " << e.what() << "\n";
    // The whole help only when there is no command to correct: otherwise the
    // one line that says what is wrong is not buried under thirty others.
    if (args_command_empty) {
      std::cerr << program_help();
    } else if (e.command.empty()) {
      std::cerr << "(rackopt --help lists the commands)\n";
    } else {
      std::cerr << "(rackopt " << e.command << " --help lists its options, with examples)\n";
    }
    return kBadInput;
  }
  if (!line.text.empty()) {
    std::cout << line.text;
    return kOk;
  }
  const Args& args = line.args;
  rackopt::install_interrupt_handlers(
      args.command == "run" ? "\nrackopt: stopping after the current evaluation (Ctrl-C again to quit at once)...\n"
                            : "\nrackopt: stopping (Ctrl-C again to quit at once)...\n");
#ifdef RACKOPT_WITH_MPI
  // Rank 0 under mpirun: SIGUSR1 is a stop too. mpirun forwards it to every
  // rank (the workers ignore it) and then ends with rank 0's status, 130;
  // a SIGINT or SIGTERM to mpirun aborts the job with OpenMPI's status 1.
  if (mpi_job) rackopt::also_stop_on(SIGUSR1);
#endif
  if (args.json) {
    // What an at-once end (second Ctrl-C) prints: the same error object.
    rackopt::JsonWriter j;
    j.begin_object().key("ok").value(false).key("error").value("interrupted");
    j.key("message").value("stopped at once by @").end_object();
    const std::string text = j.str() + "\n";
    const std::size_t at = text.find('@');
    rackopt::set_immediate_stop_output(text.substr(0, at), text.substr(at + 1));
  }
  auto fail = [&](int code, const std::string& kind, const std::string& msg) {
    rackopt::set_immediate_stop_output("");
    if (args.json) print_json_error(kind, msg);
    std::cerr << "rackopt: " << msg << "\n";
    return code;
  };
  try {
    int code;
    if (args.command == "check") {
      code = cmd_check(args);
    } else if (args.command == "stiffness") {
      code = cmd_stiffness(args);
    } else if (args.command == "dynamics") {
      code = cmd_dynamics(args);
    } else if (args.command == "run") {
      code = cmd_run(args);
    } else if (args.command == "fe") {
      code = cmd_fe(args);
    } else {
      code = cmd_wear(args);
    }
    // A stop that came after the last check point still ends the run as
    // interrupted (what was written is complete; stderr says so).
    if (rackopt::stop_requested() && code != rackopt::kInterruptedExit) {
      std::cerr << "rackopt: stopped by " << rackopt::stop_reason() << " (the files written are complete)\n";
      return rackopt::kInterruptedExit;
    }
    return code;
  } catch (const rackopt::Interrupted& e) {
    std::string msg = e.what();
    if (msg.find("stopped by") == std::string::npos) msg += " (" + rackopt::stop_reason() + ")";
    return fail(rackopt::kInterruptedExit, "interrupted", msg);
  } catch (const rackopt::InputError& e) {
    return fail(kBadInput, "input", e.what());
  } catch (const rackopt::DesignError& e) {
    return fail(kBadInput, "design:" + e.code(), std::string("impossible design (") + e.code() + "): " + e.what());
  } catch (const rackopt::record::OutputFolderConflict& e) {
    return fail(kBadInput, "output_folder", e.what());
  } catch (const rackopt::OutputFolderInUse& e) {
    return fail(kBadInput, "output_folder", e.what());
  } catch (const MpiUnavailable& e) {
    return fail(kBadInput, "mpi_unavailable", e.what());
  } catch (const rackopt::fe::CcxNotFound& e) {
    return fail(kRunFailed, "ccx_not_found", e.what());
  } catch (const rackopt::fe::GmshNotFound& e) {
    return fail(kRunFailed, "gmsh_not_found", e.what());
  } catch (const rackopt::fe::CcxError& e) {
    std::string msg = std::string("FE solve failed: ") + e.what();
    if (!e.deck().empty() && msg.find(e.deck()) == std::string::npos) msg += " (input deck kept: " + e.deck() + ")";
    return fail(kRunFailed, "fe_solver", msg);
  } catch (const std::exception& e) {
    return fail(kRunFailed, "run", std::string("run failed: ") + e.what());
  }
}
