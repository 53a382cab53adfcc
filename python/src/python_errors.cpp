#include "python_errors.hpp"

#include "rackopt/core/error.hpp"

namespace py = pybind11;

namespace rackopt::python {
namespace {

// The exception types live as long as the interpreter: module attributes
// hold them, these pointers only find them again in the translator.
PyObject* input_error_type = nullptr;
PyObject* design_error_type = nullptr;

// Raises `type(what)` with `attributes` set on the instance.
void raise_with(PyObject* type, const char* what, const py::dict& attributes) {
  py::object instance = py::reinterpret_borrow<py::object>(type)(what);
  for (auto item : attributes) py::setattr(instance, item.first, item.second);
  PyErr_SetObject(type, instance.ptr());
}

}  // namespace

void register_errors(py::module_& m) {
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<DesignError> design_error(m, "DesignError", PyExc_ValueError);
  input_error_type = input_error.ptr();
  design_error_type = design_error.ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::dict a;
      a["file"] = e.mark().file;
      a["line"] = e.mark().line > 0 ? py::cast(e.mark().line) : py::none();
      a["column"] = e.mark().column > 0 ? py::cast(e.mark().column) : py::none();
      a["key_path"] = e.key_path();
      a["message"] = e.message();
      raise_with(input_error_type, e.what(), a);
    } catch (const DesignError& e) {
      py::dict a;
      a["code"] = e.code();
      a["message"] = std::string(e.what());
      raise_with(design_error_type, e.what(), a);
    }
  });
}

}  // namespace rackopt::python
