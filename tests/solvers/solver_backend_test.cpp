// The table of solver libraries and the settings each one owns.
#include "rackopt/solvers/solver_backend.hpp"

#include <gtest/gtest.h>

#include "test_problems.hpp"

namespace rs = rackopt::solvers;
using namespace rackopt::solvers::testing;

namespace {

TEST(SolverBackends, TableNamesEveryLibraryOnceAndFindsThemInAnyCase) {
  EXPECT_EQ(rs::solver_library_names(), (std::vector<std::string>{"nlopt", "ipopt", "pagmo"}));
  for (const std::string& name : rs::solver_library_names()) {
    const rs::SolverBackend* b = rs::find_solver_backend(name);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->library(), name);
  }
  EXPECT_EQ(rs::find_solver_backend("PaGMO"), rs::find_solver_backend("pagmo"));
  EXPECT_EQ(rs::find_solver_backend("scipy"), nullptr);
}

TEST(SolverBackends, EveryDefaultAlgorithmIsOneOfItsOwnAndEveryOptionDefaultIsInRange) {
  for (const rs::SolverBackend* b : rs::solver_backends()) {
    if (!b->algorithms().empty()) {
      EXPECT_TRUE(b->find_algorithm(b->default_algorithm())) << b->library();
    }
    for (const rs::BackendOption& o : b->options()) {
      EXPECT_TRUE(o.lo_open ? o.default_value > o.lo : o.default_value >= o.lo)
          << b->library() << " " << o.key;
      EXPECT_LE(o.default_value, o.hi) << o.key;
      rs::SolverSettings s;
      s.library = std::string(b->library());
      EXPECT_EQ(b->option(s, o.key), o.default_value);
      s.options[o.key] = o.hi;
      EXPECT_EQ(b->option(s, o.key), o.hi);
    }
  }
  EXPECT_THROW(rs::find_solver_backend("nlopt")->option(rs::SolverSettings{}, "population"), std::logic_error);
}

TEST(SolverBackends, OnlyPagmosPopulationMethodsFindFronts) {
  rs::SolverSettings s;
  for (const auto& [library, algorithm, fronts] :
       std::vector<std::tuple<std::string, std::string, bool>>{{"pagmo", "NSGA2", true},
                                                               {"pagmo", "moead", true},
                                                               {"pagmo", "cmaes", false},
                                                               {"nlopt", "LN_COBYLA", false},
                                                               {"ipopt", "", false}}) {
    s.library = library;
    s.algorithm = algorithm;
    EXPECT_EQ(rs::algorithm_finds_fronts(s), fronts) << library << " " << algorithm;
  }
}

TEST(SolverBackends, OptionsAreCheckedByTheirLibrary) {
  const LambdaProblem p = rosenbrock();
  rs::SolverSettings s = nlopt_settings("LN_COBYLA");
  s.options["population"] = 40;
  const std::string other = rs::check_solver_settings(s, p);
  EXPECT_NE(other.find("'population' is not a setting of nlopt"), std::string::npos) << other;

  s = ipopt_settings();
  s.options["ipopt_tol"] = 0;  // must be > 0
  const std::string range = rs::check_solver_settings(s, p);
  EXPECT_NE(range.find("ipopt_tol"), std::string::npos) << range;
  s.options["ipopt_tol"] = 1e-9;
  s.options["ipopt_max_iterations"] = 2.5;  // whole numbers only
  EXPECT_NE(rs::check_solver_settings(s, p).find("whole numbers"), std::string::npos);
  s.options["ipopt_max_iterations"] = 20;
  EXPECT_EQ(rs::check_solver_settings(s, p), "");

  const auto refusal = rs::check_solver_settings(s, rs::ProblemShape{2, 1, 0, 0});
  EXPECT_FALSE(refusal);
  s.options["ipopt_tol"] = -1;
  const auto bad = rs::check_solver_settings(s, rs::ProblemShape{2, 1, 0, 0});
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->setting, rs::SolverSetting::kOption);
  EXPECT_EQ(bad->option, "ipopt_tol");
}

TEST(SolverBackends, UnknownLibraryListsTheTable) {
  rs::SolverSettings s;
  s.library = "scipy";
  const std::string msg = rs::check_solver_settings(s, rosenbrock());
  EXPECT_NE(msg.find("\"nlopt\", \"ipopt\", \"pagmo\""), std::string::npos) << msg;
}

}  // namespace
