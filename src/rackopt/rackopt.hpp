// rackopt's public API in one include. Each header below states its own
// contract; docs/library.md shows how to build against the installed package
// (find_package(rackopt) -> rackopt::rackopt) and a first program.
//
// Example:
//   #include <rackopt/rackopt.hpp>
//   rackopt::Drive drive = rackopt::load_problem("problems/rack_railway.yaml");
//   rackopt::StiffnessCurve curve = rackopt::MeshStiffnessModel(drive).curve();
//   std::cout << curve.k_min << " N/m, rackopt " RACKOPT_VERSION_STRING "\n";
#pragma once

#include "rackopt/version.hpp"

// Errors: InputError (file, line, column, key) and DesignError (an
// impossible design, with a code).
#include "rackopt/core/error.hpp"
// The drive: every problem key as SI values.
#include "rackopt/core/drive.hpp"
// Problem files, YAML text and overrides -> Drive; design values on a tree.
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/problem/design_point.hpp"
// Units of YAML numbers ("60 mm", "14 deg").
#include "rackopt/units/units.hpp"

// Models.
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/wear/wear_life.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/fe/fe_comparison.hpp"

// Metrics by name, computing only the models they need.
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/metrics/evaluate_metrics.hpp"

// Optimization: a problem concept and the solver backends.
#include "rackopt/solvers/problem.hpp"
#include "rackopt/solvers/solver.hpp"

// Studies: spec, problem view, runner, study files, the record.
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/studyfile/study_loader.hpp"
#include "rackopt/record/evaluation_store.hpp"
