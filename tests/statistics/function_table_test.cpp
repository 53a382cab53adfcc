// Verified adaptive table (Steffen monotone cubic): accuracy against the
// function itself, tag switches and jumps left to direct evaluation, budget,
// determinism.
#include "rackopt/statistics/function_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rackopt/core/error.hpp"

namespace rackopt::statistics {
namespace {

// Largest relative error of the table over a fine grid of covered points,
// and the number of covered grid points.
double max_rel_error(const FunctionTable& t, const std::function<double(double)>& f, double a, double b,
                     int* covered = nullptr) {
  double e = 0;
  int c = 0;
  for (int i = 0; i <= 4000; ++i) {
    const double x = a + (b - a) * i / 4000.0;
    const auto v = t(x);
    if (!v) continue;
    ++c;
    e = std::max(e, std::fabs(v->value - f(x)) / std::fabs(f(x)));
  }
  if (covered) *covered = c;
  return e;
}

TEST(FunctionTable, SmoothFunctionIsCoveredToTheTolerance) {
  auto f = [](double x) { return std::exp(2.0 * x) + 1.0 / (x + 0.2); };
  FunctionTableOptions o;
  o.rel_tolerance = 1e-5;
  o.max_evaluations = 1000;
  o.max_levels = 8;  // 1/(x + 0.2) near 0 needs intervals of 1/1024
  const FunctionTable t = FunctionTable::build([&](double x) { return TaggedValue{f(x), 0}; }, 0.0, 2.0, o);
  EXPECT_EQ(t.uncovered_fraction(), 0.0);
  EXPECT_TRUE(t.breaks().empty());
  int covered = 0;
  EXPECT_LT(max_rel_error(t, f, 0.0, 2.0, &covered), o.rel_tolerance);
  EXPECT_EQ(covered, 4001);
  EXPECT_LE(t.evaluations(), o.max_evaluations);
  // The nodes hold f exactly.
  for (std::size_t i = 0; i < t.x().size(); ++i) EXPECT_EQ(t.y()[i], f(t.x()[i]));
}

// Steffen's interpolant is monotone between monotone data: the table of a
// monotone function is monotone and inverts to the function's inverse.
TEST(FunctionTable, MonotoneAndInvertible) {
  const FunctionTable t = FunctionTable::build([](double x) { return TaggedValue{std::exp(x), 0}; }, 0.0, 3.0,
                                              {.rel_tolerance = 1e-6, .max_evaluations = 1000});
  ASSERT_EQ(t.uncovered_fraction(), 0.0);
  bool up = false;
  EXPECT_TRUE(t.monotone(&up));
  EXPECT_TRUE(up);
  double prev = -1;
  for (int i = 0; i <= 3000; ++i) {
    const auto tv = t(3.0 * i / 3000.0);
    ASSERT_TRUE(tv.has_value()) << i;
    const double v = tv->value;
    EXPECT_GE(v, prev);
    prev = v;
  }
  for (double y : {1.5, 4.0, 19.0}) {
    std::size_t k = 0;
    while (!(t.y()[k] <= y && y <= t.y()[k + 1])) ++k;
    EXPECT_NEAR(t.invert_in_interval(k, y), std::log(y), 2e-6) << y;  // d ln y = dy / y
  }
}

// A kink where the regime changes (min of two branches, tagged by branch):
// no interpolation across it, the switch is bracketed to break_width, and
// every covered point is accurate.
TEST(FunctionTable, TagSwitchIsBracketedNotSmeared) {
  const double c = 0.6180339887;  // not on any dyadic node
  auto f = [&](double x) { return x < c ? 1.0 + x : 1.0 + c + 3.0 * (x - c); };
  FunctionTableOptions o;
  o.rel_tolerance = 1e-6;
  const FunctionTable t =
      FunctionTable::build([&](double x) { return TaggedValue{f(x), x < c ? 0 : 1}; }, 0.0, 1.0, o);
  ASSERT_EQ(t.breaks().size(), 1u);
  EXPECT_LE(t.breaks()[0].first, c);
  EXPECT_GE(t.breaks()[0].second, c);
  EXPECT_LE(t.breaks()[0].second - t.breaks()[0].first, o.break_width * 1.0 + 1e-15);
  EXPECT_FALSE(t.covers(c));
  EXPECT_LT(max_rel_error(t, f, 0.0, 1.0), 1e-12);  // both branches are linear
  EXPECT_LT(t.uncovered_fraction(), 0.01);
}

// A jump and a kink inside one regime (same tag): the midpoint check cannot
// pass there, so those intervals are left to direct evaluation; the rest of
// the table stays accurate.
TEST(FunctionTable, SameTagJumpAndKinkAreLeftToDirectEvaluation) {
  auto f = [](double x) { return 2.0 + x + (x > 0.37 ? 0.5 : 0.0) + 3.0 * std::fabs(x - 0.81); };
  FunctionTableOptions o;
  o.rel_tolerance = 1e-4;
  o.max_evaluations = 200;
  const FunctionTable t = FunctionTable::build([&](double x) { return TaggedValue{f(x), 0}; }, 0.0, 1.0, o);
  EXPECT_FALSE(t.covers(0.37));
  EXPECT_FALSE(t.covers(0.81));
  // The covered points are within a few tolerances (the check is at the
  // midpoints of the coarser level; the final table is finer).
  EXPECT_LT(max_rel_error(t, f, 0.0, 1.0), 3.0 * o.rel_tolerance);
  EXPECT_LT(t.uncovered_fraction(), 0.05);
}

TEST(FunctionTable, NoisyFunctionStaysWithinBudgetAndIsNotInterpolated) {
  auto f = [](double x) { return 1.0 + x + 1e-2 * std::sin(4000.0 * x); };
  FunctionTableOptions o;
  o.rel_tolerance = 1e-4;
  o.max_evaluations = 60;
  const FunctionTable t = FunctionTable::build([&](double x) { return TaggedValue{f(x), 0}; }, 0.0, 1.0, o);
  EXPECT_LE(t.evaluations(), 60);
  EXPECT_GT(t.uncovered_fraction(), 0.5);
  EXPECT_LT(max_rel_error(t, f, 0.0, 1.0), 3.0 * 1e-2);  // whatever is covered passed a check
}

TEST(FunctionTable, SameNodesOnAnyThreadCount) {
  auto g = [](double x) { return TaggedValue{std::cos(3.0 * x) + 2.0, x > 1.3 ? 1 : 0}; };
  FunctionTableOptions o;
  o.threads = 1;
  const FunctionTable a = FunctionTable::build(g, 0.0, 2.0, o);
  o.threads = 2;
  const FunctionTable b = FunctionTable::build(g, 0.0, 2.0, o);
  EXPECT_EQ(a.x(), b.x());
  EXPECT_EQ(a.y(), b.y());
  EXPECT_EQ(a.verified(), b.verified());
}

TEST(FunctionTable, BadInputAndNonFiniteValues) {
  auto one = [](double) { return TaggedValue{1.0, 0}; };
  EXPECT_THROW(FunctionTable::build(one, 1.0, 1.0), InputError);
  EXPECT_THROW(FunctionTable::build(one, 0.0, std::numeric_limits<double>::infinity()), InputError);
  EXPECT_THROW(FunctionTable::build(one, 0.0, 1.0, {.initial_nodes = 2}), InputError);
  EXPECT_THROW(FunctionTable::build([](double x) { return TaggedValue{x > 0.5 ? std::nan("") : 1.0, 0}; }, 0.0, 1.0),
               DesignError);
}

}  // namespace
}  // namespace rackopt::statistics
