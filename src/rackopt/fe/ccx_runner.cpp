#include "rackopt/fe/ccx_runner.hpp"

#include "rackopt/core/file_text.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <vector>

#include <unistd.h>

#include "rackopt/core/child_process.hpp"
#include "rackopt/fe/solve_folders.hpp"

namespace rackopt::fe {
namespace {

namespace fs = std::filesystem;

// A file ccx did not write reads as empty: the caller reports what is missing.
std::string read_text(const fs::path& p) { return read_file_text(p).value_or(""); }

// ccx's own complaint: its "*ERROR" lines with the line after each (ccx
// breaks its messages over two lines), at most 6 lines.
std::string solver_errors(const std::string& log) {
  std::istringstream in(log);
  std::string line, out;
  int taken = 0;
  bool follow = false;
  const auto trim = [](std::string s) {
    const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
  };
  while (std::getline(in, line) && taken < 6) {
    const std::string t = trim(line);
    if (t.rfind("*ERROR", 0) == 0) {
      out += (out.empty() ? "" : " / ") + t;
      follow = true;
      ++taken;
    } else if (follow && !t.empty()) {
      out += " " + t;
      follow = false;
    } else {
      follow = false;
    }
  }
  return out;
}

// Once per work parent and process, before its first solve: the folders of
// runs that were killed (solve_folders.hpp).
void clean_up_once(const fs::path& parent) {
  static std::mutex mutex;
  static std::set<std::string> done;
  const std::lock_guard<std::mutex> lock(mutex);
  if (done.insert(parent.string()).second) remove_abandoned_solve_folders(parent.string());
}

}  // namespace

std::string find_ccx(const CcxOptions& options) {
  std::string program = options.program;
  if (program.empty()) {
    const char* env = std::getenv("RACKOPT_CCX");
    program = env != nullptr && *env != '\0' ? env : "ccx";
  }
  const std::string exe = find_program(program);
  if (exe.empty()) {
    throw CcxNotFound("CalculiX solver '" + program +
                      "' not found (the FE reference needs it: install the Debian package calculix-ccx, "
                      "or set RACKOPT_CCX to the ccx program)");
  }
  return exe;
}

void run_ccx(const std::string& deck, const std::function<void(const std::string& dat_text)>& read,
             const CcxOptions& options) {
  const std::string exe = find_ccx(options);
  std::error_code ec;
  const fs::path parent = options.work_parent.empty() ? fs::temp_directory_path(ec) : fs::path(options.work_parent);
  clean_up_once(parent);
  std::string pattern = (parent / "rackopt-ccx-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error("cannot make a folder for the CalculiX solve under " + parent.string() + ": " +
                             std::strerror(errno));
  }
  const fs::path dir(pattern);
  try {
    mark_solve_folder_owner(dir.string());
  } catch (...) {
    fs::remove_all(dir, ec);
    throw;
  }
  const fs::path inp = dir / "job.inp", log = dir / "job.log", dat = dir / "job.dat";
  {
    std::ofstream out(inp, std::ios::binary);
    out << deck;
    out.flush();
    if (!out) {
      mark_solve_folder_kept(dir.string(), "the deck could not be written");
      throw CcxError("cannot write the CalculiX deck " + inp.string(), inp.string(), "");
    }
  }
  ChildCommand command;
  command.program = exe;
  command.arguments = {"-i", "job"};
  command.working_dir = dir.string();
  command.stdout_file = "job.log";
  command.stderr_file = "job.log";
  command.environment = {"OMP_NUM_THREADS=1", "CCX_NPROC_EQUATION_SOLVER=1", "CCX_NPROC_RESULTS=1"};
  command.time_limit_seconds = options.time_limit_seconds;
  const ChildOutcome outcome = run_child(command);

  const std::string log_text = read_text(log);
  const std::string errors = solver_errors(log_text);
  std::string failure;
  switch (outcome.kind) {
    case ChildOutcome::Kind::not_started:
      failure = outcome.message;
      break;
    case ChildOutcome::Kind::stopped:
      failure = "stopped by " + outcome.message;
      break;
    case ChildOutcome::Kind::timed_out: {
      std::ostringstream s;
      s << "did not finish within " << options.time_limit_seconds << " s and was killed";
      failure = s.str();
      break;
    }
    case ChildOutcome::Kind::signaled:
      failure = "crashed (" + outcome.message + ")";
      break;
    case ChildOutcome::Kind::exited:
      if (outcome.exit_code != 0) {
        failure = "exited with status " + std::to_string(outcome.exit_code);
      } else if (!errors.empty()) {
        failure = "reported an error";
      } else if (log_text.find("Job finished") == std::string::npos) {
        failure = "did not finish its job";
      } else if (!fs::exists(dat, ec)) {
        failure = "wrote no job.dat";
      }
      break;
  }
  if (failure.empty()) {
    try {
      read(read_text(dat));
    } catch (const std::exception& e) {
      failure = "output rejected: " + std::string(e.what());
    }
  }
  if (!failure.empty()) {
    mark_solve_folder_kept(dir.string(), "CalculiX " + failure);
    throw CcxError("CalculiX " + failure + (errors.empty() ? std::string() : ": " + errors) + " (deck kept: " +
                       inp.string() + ", solver log: " + log.string() + ")",
                   inp.string(), log.string());
  }
  fs::remove_all(dir, ec);
}

}  // namespace rackopt::fe
