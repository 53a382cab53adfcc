// rackopt._rackopt.run_study: a study end to end as `rackopt run` does it
// (load and check, take the output folder's lock, run with the evaluation
// store, write the report), returning summary.json as a dict. The GIL is
// released while the study runs; Ctrl-C stops it cleanly (the results so
// far are written, like the command line's first Ctrl-C) and then raises
// KeyboardInterrupt.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "python_bindings.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/marked_yaml/input_file.hpp"
#include "rackopt/output/folder_lock.hpp"
#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/study_report/study_report.hpp"
#include "rackopt/studyfile/study_loader.hpp"

namespace py = pybind11;

namespace rackopt::python {
namespace {

// Polled by the runner between evaluations, also from worker threads. Only
// the interpreter's main thread can run Python's signal handlers: it does,
// under the GIL, and records a KeyboardInterrupt (left pending in its thread
// state, raised when the study returns); the others read the flag.
class PythonStop {
 public:
  bool operator()() {
    if (stopped_.load()) return true;
    if (std::this_thread::get_id() != main_) return false;
    py::gil_scoped_acquire hold;
    if (PyErr_CheckSignals() != 0) stopped_.store(true);
    return stopped_.load();
  }

 private:
  std::thread::id main_ = std::this_thread::get_id();
  std::atomic<bool> stopped_{false};
};

// `text` with every `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// The store and the folder lock advise in the command line's words
// (--resume, --out); a Python caller passes resume=True and out= instead.
std::string in_python_words(const std::string& message) {
  return replaced(replaced(replaced(message, "--resume", "resume=True"), "another --out folder",
                           "another output folder (out=...)"),
                  "--out", "out=");
}

py::dict run(const std::string& study_text, const std::string& study_name, const std::string& base_dir,
             const std::vector<std::string>& overrides, const std::optional<Problem>& problem,
             const std::string& out_dir, long threads, bool resume) {
  check_count(threads, kThreadsLimit, "threads");  // before the library's unsigned takes it
  std::optional<studyfile::InMemoryProblem> given;
  if (problem) given = studyfile::InMemoryProblem{problem->yaml_text(), problem->name(), problem->overrides()};
  const study::StudySpec spec =
      studyfile::load_study_text(study_text, study_name, base_dir, overrides, given ? &*given : nullptr);
  const std::string out = out_dir.empty() ? study::default_out_dir(spec) : out_dir;

  std::string summary;
  auto stop = std::make_shared<PythonStop>();
  {
    py::gil_scoped_release free;
    try {
      const FolderLock lock(out);  // held until the report is written
      study::RunOptions opt;
      opt.out_dir = out;
      opt.resume = resume;
      opt.threads = static_cast<unsigned>(threads);
      opt.stop = [stop] { return (*stop)(); };
      const study::StudyResult result = study::run_study(spec, opt);
      summary = study_report::write_study_report(spec, result, out).summary_json;
    } catch (const record::OutputFolderConflict& e) {
      throw record::OutputFolderConflict(in_python_words(e.what()));
    } catch (const OutputFolderInUse& e) {
      throw OutputFolderInUse(in_python_words(e.what()));
    }
  }
  if (PyErr_Occurred()) throw py::error_already_set();  // Ctrl-C: the report is written, now raise
  py::dict d = py::module_::import("json").attr("loads")(summary);
  d["out_dir"] = out;
  return d;
}

}  // namespace

void bind_study(py::module_& m) {
  m.def("run_study_text", &run, py::arg("study_text"), py::arg("study_name"), py::arg("base_dir"),
        py::arg("overrides"), py::arg("problem"), py::arg("out_dir"), py::arg("threads"), py::arg("resume"));
  m.def(
      "read_input_file", [](const std::string& path) { return read_input_file(path, "study file"); },
      py::arg("path"));
}

}  // namespace rackopt::python
