// rackopt._rackopt.run_study: a study end to end as `rackopt run` does it
// (load and check, take the output folder's lock, run with the evaluation
// store, write the report), returning summary.json as a dict. The GIL is
// released while the study runs; Ctrl-C stops it cleanly (the results so
// far are written, like the command line's first Ctrl-C; a second one does
// not end the interpreter) and then raises KeyboardInterrupt.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "python_bindings.hpp"
#include "rackopt/core/interrupt.hpp"
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

// True on the interpreter's main thread, the one that gets the signals.
bool on_main_thread() {
  const py::module_ threading = py::module_::import("threading");
  return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

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
  bool interrupted = false;
  {
    // While the study runs without the GIL the interpreter's own SIGINT
    // handler cannot run, and the models poll rackopt's stop request, not
    // Python's: rackopt's handler turns Ctrl-C (and SIGTERM) into that
    // request for the length of the call, on the main thread that gets the
    // signals; Python's handlers are back before anything is raised.
    std::optional<EmbeddedStopHandlers> handlers;
    if (on_main_thread()) {
      handlers.emplace(
          "\nrackopt: stopping after the current evaluation; the report is written, then KeyboardInterrupt\n");
    }
    py::gil_scoped_release free;
    try {
      const FolderLock lock(out);  // held until the report is written
      study::RunOptions opt;
      opt.out_dir = out;
      opt.resume = resume;
      opt.threads = static_cast<unsigned>(threads);
      opt.stop = [] { return stop_requested(); };
      try {
        const study::StudyResult result = study::run_study(spec, opt);
        summary = study_report::write_study_report(spec, result, out).summary_json;
      } catch (const Interrupted&) {
        // Work that gave up on the stop request outside the study's own
        // handling: nothing partial was published; KeyboardInterrupt all the same.
        if (!handlers) throw;
      }
    } catch (const record::OutputFolderConflict& e) {
      throw record::OutputFolderConflict(in_python_words(e.what()));
    } catch (const OutputFolderInUse& e) {
      throw OutputFolderInUse(in_python_words(e.what()));
    }
    interrupted = handlers && stop_requested();
  }
  if (interrupted) {
    // Ctrl-C: the report is written (a stopped study, or a finished one
    // when the signal came after the last evaluation); now raise.
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
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
