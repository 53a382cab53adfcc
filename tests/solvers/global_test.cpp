// Global algorithms, determinism, multistart and the settings check.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>

#include <nlopt.hpp>

#include "test_problems.hpp"

namespace rs = rackopt::solvers;
using namespace rackopt::solvers::testing;

namespace {

// Shifted 2D Rastrigin-like function on [-4, 4]^2:
//   f = sum_i z_i^2 + 0.5 (1 - cos(2 pi z_i)),   z = x - a,  a = (1.3, -0.7).
// Each term is >= 0 and zero only at z_i = 0, so the global minimum is f = 0
// at x = a. Other stationary points solve 2 z + pi sin(2 pi z) = 0; the
// nearest local minima are at |z| ~ 0.90 with a term value ~ 0.91, so any
// f < 0.5 is in the global basin. The box center is not a minimum.
const std::vector<double> kShift{1.3, -0.7};
LambdaProblem multimodal() {
  return LambdaProblem({-4, -4}, {4, 4}, [](std::span<const double> x) {
    double f = 0;
    for (int i = 0; i < 2; ++i) {
      const double z = x[i] - kShift[i];
      f += z * z + 0.5 * (1 - std::cos(2 * std::numbers::pi * z));
    }
    return ok(f);
  });
}

// Double well f = (x^2 - 1)^2 + 0.3 x on [-2, 2]. f'(x) = 4x(x^2-1) + 0.3 has
// three roots; the outer ones are minima near -1 (global: the 0.3 x term is
// negative there) and near +1 (local). Roots found here by bisection.
LambdaProblem double_well() {
  return LambdaProblem({-2}, {2}, [](std::span<const double> x) {
    return ok((x[0] * x[0] - 1) * (x[0] * x[0] - 1) + 0.3 * x[0]);
  });
}
double bisect_derivative_root(double a, double b) {
  auto d = [](double x) { return 4 * x * (x * x - 1) + 0.3; };
  for (int k = 0; k < 200; ++k) {
    const double m = 0.5 * (a + b);
    ((d(a) < 0) == (d(m) < 0) ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace

TEST(Global, FindsGlobalBasin) {
  const auto p = multimodal();
  // AGS's own bookkeeping grows steeply with the evaluation count (1000
  // evaluations: ms, 3000: seconds), hence its smaller budget.
  for (rs::SolverSettings s : {nlopt_settings("GN_DIRECT_L", 1000), nlopt_settings("GN_ISRES", 3000),
                               nlopt_settings("GN_CRS2_LM", 1000), nlopt_settings("GN_AGS", 1000)}) {
    SCOPED_TRACE(s.algorithm);
    const rs::SolverResult r = rs::minimize(p, std::vector<double>{0.0, 0.0}, s);
    ASSERT_TRUE(r.feasible);
    // Near a and below every local minimum (~0.91).
    EXPECT_NEAR(r.x[0], kShift[0], 0.1);
    EXPECT_NEAR(r.x[1], kShift[1], 0.1);
    EXPECT_LT(r.evaluation.objectives[0], 0.1);
  }
}

TEST(Global, SameSeedSameResultInAnyThread) {
  const auto p = multimodal();
  for (const char* alg : {"GN_ISRES", "GN_CRS2_LM"}) {
    SCOPED_TRACE(alg);
    rs::SolverSettings s = nlopt_settings(alg, 600);
    s.seed = 42;
    const rs::SolverResult a = rs::minimize(p, std::vector<double>{0.0, 0.0}, s);
    // Disturb NLopt's thread-local generator in this thread, then run again,
    // and once more in a fresh thread: all three must agree bit for bit.
    nlopt::srand(12345);
    const rs::SolverResult b = rs::minimize(p, std::vector<double>{0.0, 0.0}, s);
    rs::SolverResult c;
    std::thread([&] { c = rs::minimize(p, std::vector<double>{0.0, 0.0}, s); }).join();
    for (const rs::SolverResult* other : std::vector<const rs::SolverResult*>{&b, &c}) {
      EXPECT_EQ(a.x, other->x);
      EXPECT_EQ(a.evaluations, other->evaluations);
      EXPECT_EQ(a.best_history, other->best_history);
    }
    s.seed = 43;  // a different seed takes a different path
    const rs::SolverResult d = rs::minimize(p, std::vector<double>{0.0, 0.0}, s);
    EXPECT_NE(a.best_history, d.best_history);
  }
}

TEST(Global, MultistartEscapesLocalMinimum) {
  const double x_global = bisect_derivative_root(-2.0, -0.5);
  const double x_local = bisect_derivative_root(0.5, 2.0);
  ASSERT_LT(x_global, -0.9);
  ASSERT_GT(x_local, 0.9);
  const auto p = double_well();
  rs::SolverSettings bobyqa = nlopt_settings("LN_BOBYQA");
  rs::SolverSettings ipopt = ipopt_settings();
  ipopt.central_differences = true;
  for (rs::SolverSettings s : {bobyqa, ipopt}) {
    SCOPED_TRACE(s.library);
    // From x0 = 0.9 alone the local minimum is found ...
    const rs::SolverResult one = rs::minimize(p, std::vector<double>{0.9}, s);
    EXPECT_NEAR(one.x[0], x_local, 1e-4);
    // ... five starts (x0 + 4 Latin hypercube points) find the global one.
    s.starts = 5;
    const rs::SolverResult five = rs::minimize(p, std::vector<double>{0.9}, s);
    EXPECT_NEAR(five.x[0], x_global, 1e-4);
    EXPECT_EQ(to_string(five.status), "converged");
    EXPECT_NE(five.solver_message.find("start 4:"), std::string::npos) << five.solver_message;
  }
}

TEST(Settings, MessagesSayWhatIsWrongAndWhatToUse) {
  const auto two_ineq = LambdaProblem({0, 0}, {1, 1}, [](std::span<const double>) { return ok(0, {0, 0}); }, 2);
  const std::string bobyqa = rs::check_solver_settings(nlopt_settings("LN_BOBYQA"), two_ineq);
  EXPECT_NE(bobyqa.find("LN_BOBYQA cannot handle the 2 inequality constraints"), std::string::npos) << bobyqa;
  EXPECT_NE(bobyqa.find("LN_COBYLA"), std::string::npos);
  EXPECT_NE(bobyqa.find("LD_SLSQP"), std::string::npos);
  EXPECT_NE(bobyqa.find("AUGLAG with local_algorithm LN_BOBYQA"), std::string::npos);

  const auto p = disk_on_line();
  const std::string mma = rs::check_solver_settings(nlopt_settings("ld_mma"), p);
  EXPECT_NE(mma.find("LD_MMA cannot handle the 1 equality constraint"), std::string::npos) << mma;
  EXPECT_NE(mma.find("LD_SLSQP"), std::string::npos);
  EXPECT_EQ(mma.find("LD_CCSAQ"), std::string::npos);  // cannot do equalities either

  // A bad sub-solver is refused with the list of good ones (an empty one
  // means LN_COBYLA, see SubSolverDefaultsDoNotCrash).
  EXPECT_EQ(rs::check_solver_settings(nlopt_settings("AUGLAG"), p), "");
  for (const char* bad : {"GN_DIRECT_L", "AUGLAG", "LN_AUGLAG", "GN_MLSL", "LN_FOO"}) {
    rs::SolverSettings auglag = nlopt_settings("AUGLAG");
    auglag.local_algorithm = bad;
    const std::string msg = rs::check_solver_settings(auglag, p);
    EXPECT_NE(msg.find(std::string("local_algorithm '") + bad + "' is not a local NLopt algorithm"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("LN_BOBYQA"), std::string::npos) << msg;
    EXPECT_THROW(rs::minimize(p, std::vector<double>{0.2, 0.2}, auglag), std::invalid_argument);
  }
  rs::SolverSettings cobyla_with_local = nlopt_settings("LN_COBYLA");
  cobyla_with_local.local_algorithm = "LN_BOBYQA";
  EXPECT_NE(rs::check_solver_settings(cobyla_with_local, p).find("does not take one"), std::string::npos);

  const std::string unknown = rs::check_solver_settings(nlopt_settings("LN_FOO"), p);
  EXPECT_NE(unknown.find("unknown NLopt algorithm 'LN_FOO'"), std::string::npos) << unknown;
  for (const std::string& name : rs::nlopt_algorithm_names()) EXPECT_NE(unknown.find(name), std::string::npos);

  rs::SolverSettings lib = nlopt_settings("LN_COBYLA");
  lib.library = "snopt";
  EXPECT_NE(rs::check_solver_settings(lib, p).find("use \"nlopt\", \"ipopt\", \"pagmo\""), std::string::npos);

  // Accepted spellings; the Ipopt library ignores the algorithm name.
  EXPECT_EQ(rs::check_solver_settings(nlopt_settings("NLOPT_LN_COBYLA"), p), "");
  EXPECT_EQ(rs::check_solver_settings(nlopt_settings("ld_slsqp"), p), "");
  EXPECT_EQ(rs::check_solver_settings(ipopt_settings(), p), "");

  // More equalities than variables (NLopt 2.7.1 refuses; Ipopt has too few
  // degrees of freedom).
  const auto three_eq = LambdaProblem({0, 0}, {1, 1}, [](std::span<const double>) { return ok(0, {}, {0, 0, 0}); }, 0, 3);
  EXPECT_NE(rs::check_solver_settings(nlopt_settings("LD_SLSQP"), three_eq).find("3) than variables (2"),
            std::string::npos);
  EXPECT_NE(rs::check_solver_settings(ipopt_settings(), three_eq).find("degrees of freedom"), std::string::npos);

  // AUGLAG_EQ hands inequalities to its local algorithm.
  rs::SolverSettings aeq = nlopt_settings("AUGLAG_EQ");
  aeq.local_algorithm = "LN_BOBYQA";
  EXPECT_NE(rs::check_solver_settings(aeq, two_ineq).find("LN_BOBYQA cannot handle them"), std::string::npos);

  // Problem shape and numbers.
  const auto two_obj = LambdaProblem({0}, {1}, [](std::span<const double>) { return ok(0); }, 0, 0, 2);
  EXPECT_NE(rs::check_solver_settings(nlopt_settings("LN_COBYLA"), two_obj).find("one objective"), std::string::npos);
  const auto unbounded = LambdaProblem({0}, {HUGE_VAL}, [](std::span<const double>) { return ok(0); });
  EXPECT_NE(rs::check_solver_settings(nlopt_settings("LN_COBYLA"), unbounded).find("finite bounds"),
            std::string::npos);
  EXPECT_NE(rs::check_solver_settings(nlopt_settings("LN_COBYLA", 0), p).find("max_evaluations"), std::string::npos);
  EXPECT_NE(rs::check_solver_settings(nlopt_settings("LN_COBYLA"), p, std::vector<double>{1.0}).find("x0 has 1"),
            std::string::npos);

  // minimize() refuses with the same message.
  try {
    rs::minimize(two_ineq, std::vector<double>{0.5, 0.5}, nlopt_settings("LN_BOBYQA"));
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), bobyqa);
  }
}

// The shape-only check (what a study file decides before any problem
// exists) says which setting to change, with the same messages.
TEST(Settings, ShapeCheckNamesTheSettingToChange) {
  rs::ProblemShape two_ineq;
  two_ineq.dimension = 2;
  two_ineq.inequality = 2;
  const auto bobyqa = rs::check_solver_settings(nlopt_settings("LN_BOBYQA"), two_ineq);
  ASSERT_TRUE(bobyqa.has_value());
  EXPECT_EQ(bobyqa->setting, rs::SolverSetting::kAlgorithm);
  const auto as_problem = LambdaProblem({0, 0}, {1, 1}, [](std::span<const double>) { return ok(0, {0, 0}); }, 2);
  EXPECT_EQ(bobyqa->message, rs::check_solver_settings(nlopt_settings("LN_BOBYQA"), as_problem));
  EXPECT_FALSE(rs::check_solver_settings(nlopt_settings("LN_COBYLA"), two_ineq).has_value());

  rs::SolverSettings cobyla_with_local = nlopt_settings("LN_COBYLA");
  cobyla_with_local.local_algorithm = "LN_BOBYQA";
  EXPECT_EQ(rs::check_solver_settings(cobyla_with_local, two_ineq)->setting, rs::SolverSetting::kLocalAlgorithm);
  rs::SolverSettings aeq = nlopt_settings("AUGLAG_EQ");
  aeq.local_algorithm = "LN_BOBYQA";
  EXPECT_EQ(rs::check_solver_settings(aeq, two_ineq)->setting, rs::SolverSetting::kLocalAlgorithm);
  EXPECT_EQ(rs::check_solver_settings(nlopt_settings("AUGLAG_EQ"), two_ineq), std::nullopt);

  rs::SolverSettings lib = nlopt_settings("LN_COBYLA");
  lib.library = "snopt";
  EXPECT_EQ(rs::check_solver_settings(lib, two_ineq)->setting, rs::SolverSetting::kLibrary);
  rs::ProblemShape three_eq;
  three_eq.dimension = 2;
  three_eq.equality = 3;
  EXPECT_EQ(rs::check_solver_settings(ipopt_settings(), three_eq)->setting, rs::SolverSetting::kLibrary);
  EXPECT_EQ(rs::check_solver_settings(nlopt_settings("LD_SLSQP"), three_eq)->setting, rs::SolverSetting::kAlgorithm);
  EXPECT_EQ(rs::check_solver_settings(nlopt_settings("LN_COBYLA", 0), two_ineq)->setting, rs::SolverSetting::kNumbers);
  EXPECT_EQ(rs::check_solver_settings(nlopt_settings("LN_COBYLA"), rs::ProblemShape{})->setting,
            rs::SolverSetting::kProblem);
}

TEST(Settings, SubSolverDefaultsDoNotCrash) {
  // NLopt 2.7.1 segfaults in LN_/LD_AUGLAG(_EQ) and every MLSL variant when
  // no local optimizer is set, and the generic AUGLAG/AUGLAG_EQ/G_MLSL(_LDS)
  // throw; the adapter always sets one (LN_COBYLA / LD_MMA unless given).
  // A crash here kills the whole test binary, which is the point.
  const auto p = shifted_quadratic();
  for (const char* alg : {"LN_AUGLAG", "LD_AUGLAG_EQ", "GN_MLSL", "GN_MLSL_LDS", "GD_MLSL", "G_MLSL", "G_MLSL_LDS",
                          "AUGLAG", "AUGLAG_EQ"}) {
    SCOPED_TRACE(alg);
    const rs::SolverResult r = rs::minimize(p, std::vector<double>{0, 0, 0, 0}, nlopt_settings(alg, 400));
    EXPECT_TRUE(r.feasible);
    EXPECT_LE(r.evaluations, 400u);
    EXPECT_LT(r.evaluation.objectives[0], 0.1);  // start: sum w c^2 = 0.09+2.88+3.125+1.47 = 7.565
  }
  // With constraints, where the generic AUGLAGs matter: min x^2+y^2 s.t.
  // x + y >= 1 (AUGLAG) or = 1 (AUGLAG_EQ), both at (0.5, 0.5), f = 0.5.
  // AUGLAG_EQ passes the inequality on to its default local LN_COBYLA.
  const auto ineq = disk_above_line();
  const auto eq_and_ineq = LambdaProblem({-2, -2}, {2, 2},
                                         [](std::span<const double> x) {
                                           return ok(x[0] * x[0] + x[1] * x[1], {x[0] - 1.5}, {x[0] + x[1] - 1});
                                         },
                                         1, 1);
  for (const char* alg : {"AUGLAG", "AUGLAG_EQ"})
    for (const rs::Problem* q : {static_cast<const rs::Problem*>(&ineq), static_cast<const rs::Problem*>(&eq_and_ineq)}) {
      SCOPED_TRACE(std::string(alg) + (q == &ineq ? " inequality" : " equality + inequality"));
      const rs::SolverResult r = rs::minimize(*q, std::vector<double>{2.0, -1.0}, nlopt_settings(alg, 3000));
      ASSERT_TRUE(r.feasible) << r.status;
      EXPECT_NEAR(r.x[0], 0.5, 2e-3);
      EXPECT_NEAR(r.x[1], 0.5, 2e-3);
      EXPECT_LE(r.evaluations, 3000u);
    }
  // G_MLSL_LDS on the multimodal function: global minimum f = 0 at kShift.
  const rs::SolverResult g = rs::minimize(multimodal(), std::vector<double>{-3, 3}, nlopt_settings("G_MLSL_LDS", 3000));
  EXPECT_LT(g.evaluation.objectives[0], 0.5);  // inside the global basin (see multimodal())
  EXPECT_NEAR(g.x[0], kShift[0], 1e-2);
  EXPECT_NEAR(g.x[1], kShift[1], 1e-2);
}
