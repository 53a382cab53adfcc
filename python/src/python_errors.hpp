// rackopt's errors as Python exceptions: InputError and DesignError keep
// what the C++ ones carry (file, line, column, key path; the design's code),
// so a Python caller can point at the key the same way the command line does.
#pragma once

#include <pybind11/pybind11.h>

namespace rackopt::python {

// Creates rackopt._rackopt.InputError and DesignError (both ValueError) in
// `m` and translates the C++ exceptions to them. Anything else escaping a
// call keeps pybind11's translation (std::runtime_error -> RuntimeError).
void register_errors(pybind11::module_& m);

}  // namespace rackopt::python
