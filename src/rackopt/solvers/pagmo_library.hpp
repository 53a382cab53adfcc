// Opens librackopt_pagmo.so (pagmo_module.hpp) the first time a pagmo
// algorithm or a hypervolume is asked for. A run that does neither never
// loads pagmo.
//
// Where it looks, first match wins:
//  1. $RACKOPT_PAGMO_MODULE, when set (only there);
//  2. beside the program (/proc/self/exe) and beside the shared object that
//     holds this code (the Python module), then in ../lib and the install's
//     library folder relative to each: the build tree and an installed tree;
//  3. the library folder of the install prefix rackopt was configured with;
//  4. the dynamic linker's own search (LD_LIBRARY_PATH, the caller's RUNPATH).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "rackopt/solvers/pagmo_module.hpp"

namespace rackopt::solvers {

// The module could not be opened, or is of another rackopt build: the
// message names every place looked at and how to fix it.
class PagmoModuleNotFound : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The module's calls; opens it on the first call (thread-safe). Throws
// PagmoModuleNotFound, every time, when it cannot be opened.
const pagmo_module::Api& pagmo_api();

// The files the search above tries, in order (for messages and tests).
std::vector<std::string> pagmo_module_candidates();

}  // namespace rackopt::solvers
