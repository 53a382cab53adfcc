// One fuzzer input fed to every way rackopt reads YAML: the body of the
// libFuzzer target (input_fuzzer.cpp, built with -DRACKOPT_FUZZ=ON) and of
// the regression test that replays the inputs it found (regressions/), so
// both run exactly the same code. docs/input_limits.md, "Fuzzing".
#pragma once

#include <string>
#include <string_view>

namespace rackopt::fuzz {

// Feeds `data` to:
//  * the problem loader (load_problem_text), with every line of the input
//    that starts with "#set " applied as a --set assignment (at most 8);
//    a drive that loads is then built into its mesh geometry (contact ratio,
//    pair counts, contact positions), which must come out finite;
//  * the first line of the input as one --set assignment over a small valid
//    problem, then the same geometry;
//  * the study loader (load_study_text), relative problem paths resolved
//    against `studies_dir` (the repository's studies/, so the shipped
//    studies used as seeds find their problems), with the same "#set " lines.
// Returns when each of them either succeeds or throws InputError or
// DesignError: refusing bad input is correct behaviour. Any other exception
// (std::bad_alloc, std::logic_error, yaml-cpp's own, ...) propagates, and a
// non-finite geometry result throws std::logic_error: both are bugs.
void run_input_fuzz_case(std::string_view data, const std::string& studies_dir);

}  // namespace rackopt::fuzz
