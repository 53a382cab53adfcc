// rackopt._rackopt: the compiled half of the Python package rackopt.
#include <pybind11/pybind11.h>

#include "python_bindings.hpp"
#include "python_errors.hpp"
#include "rackopt/version.hpp"

PYBIND11_MODULE(_rackopt, m) {
  m.doc() = "rackopt's models and studies (use the package rackopt, docs/python.md)";
  m.attr("__version__") = RACKOPT_VERSION_STRING;
  rackopt::python::register_errors(m);
  rackopt::python::bind_problem(m);
  rackopt::python::bind_study(m);
}
