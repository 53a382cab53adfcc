// The pieces of the Python module rackopt._rackopt (python_module.cpp puts
// them together); the Python package rackopt (python/rackopt/__init__.py)
// wraps them with dict and path handling and is the documented interface
// (docs/python.md).
#pragma once

#include <pybind11/pybind11.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"

namespace rackopt::python {

// A problem as the command line sees it: YAML text, the name its messages
// carry (the file's path, or "<string>", "<dict>") and `--set` assignments
// applied over it, with the drive built from them. Immutable: the with_*
// calls return new problems. Throws InputError like load_problem_text.
class Problem {
 public:
  Problem(std::string yaml_text, std::string name, std::vector<std::string> overrides);
  static Problem from_file(const std::string& path, const std::vector<std::string>& overrides);

  // The same problem with more assignments ("pinion.module=8 mm") after these.
  Problem with_overrides(const std::vector<std::string>& assignments) const;
  // The same problem with numeric keys set to SI values, bit for bit
  // (design variables from a Python optimizer). Throws InputError for a key
  // that is not numeric or a value that is not finite.
  Problem with_values(const std::map<std::string, double>& values) const;

  const std::string& yaml_text() const { return yaml_text_; }
  const std::string& name() const { return name_; }
  const std::vector<std::string>& overrides() const { return overrides_; }
  const Drive& drive() const { return *drive_; }

 private:
  std::string yaml_text_;
  std::string name_;
  std::vector<std::string> overrides_;
  std::shared_ptr<const Drive> drive_;
};

void bind_problem(pybind11::module_& m);
void bind_study(pybind11::module_& m);

}  // namespace rackopt::python
