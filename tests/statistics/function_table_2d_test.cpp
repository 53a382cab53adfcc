// Verified two-input table: accuracy against the function at its covered
// points, tag switches never interpolated, a surface the centre checks reject
// left to direct evaluation, quartering, budget, determinism.
#include "rackopt/statistics/function_table_2d.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/core/error.hpp"

namespace rackopt::statistics {
namespace {

// Largest relative error of the table over a grid of covered points.
double max_rel_error_2d(const FunctionTable2D& t, const std::function<double(double, double)>& f, int* covered) {
  double e = 0;
  int c = 0;
  for (int j = 0; j <= 200; ++j)
    for (int i = 0; i <= 200; ++i) {
      const double x = i / 200.0, y = j / 200.0;
      const auto v = t(x, y);
      if (!v) continue;
      ++c;
      e = std::max(e, std::fabs(v->value - f(x, y)) / std::fabs(f(x, y)));
    }
  *covered = c;
  return e;
}

TEST(FunctionTable2D, SmoothSurfaceIsCoveredToTheTolerance) {
  auto f = [](double x, double y) { return std::exp(x) / (1.0 + 0.5 * y * y) + 1.0; };
  FunctionTable2DOptions o;
  o.rel_tolerance = 1e-4;
  o.nodes_x = o.nodes_y = 9;
  const FunctionTable2D t =
      FunctionTable2D::build([&](double x, double y) { return TaggedValue{f(x, y), 0}; }, 0, 1, 0, 1, o);
  EXPECT_EQ(t.cells_verified(), t.cells());
  EXPECT_EQ(t.uncovered_fraction(), 0.0);
  int covered = 0;
  EXPECT_LT(max_rel_error_2d(t, f, &covered), 2e-4);
  EXPECT_EQ(covered, 201 * 201);
  EXPECT_GE(t.evaluations(), 81 + 64);  // the grid and one check per cell, then quarters
  EXPECT_LE(t.evaluations(), o.max_evaluations);
}

// A failure-mode switch along a curve through the box: every cell it crosses
// is left to direct evaluation, and no covered point carries a wrong tag.
TEST(FunctionTable2D, FailureModeSwitchIsNeverInterpolated) {
  auto tag_of = [](double x, double y) { return x + 0.3 * y < 0.55 ? 0 : 1; };
  auto f = [&](double x, double y) { return tag_of(x, y) == 0 ? 1.0 + x + y : 3.0 - x; };  // a kink and a jump
  FunctionTable2DOptions o;
  o.nodes_x = o.nodes_y = 7;
  o.max_levels = 0;
  const FunctionTable2D t =
      FunctionTable2D::build([&](double x, double y) { return TaggedValue{f(x, y), tag_of(x, y)}; }, 0, 1, 0, 1, o);
  EXPECT_GT(t.cells_with_switch(), 0);
  EXPECT_GT(t.uncovered_fraction(), 0.0);
  int covered = 0;
  EXPECT_LT(max_rel_error_2d(t, f, &covered), 1e-12);  // linear on either side, exact away from the switch
  EXPECT_GT(covered, 0);
  for (int j = 0; j <= 100; ++j)
    for (int i = 0; i <= 100; ++i) {
      const double x = i / 100.0, y = j / 100.0;
      if (const auto v = t(x, y)) {
        EXPECT_EQ(v->tag, tag_of(x, y)) << x << " " << y;
      }
    }
  // Quartering the switch cells narrows what is left to direct evaluation.
  o.max_levels = 2;
  o.max_evaluations = 1000;
  const FunctionTable2D q =
      FunctionTable2D::build([&](double x, double y) { return TaggedValue{f(x, y), tag_of(x, y)}; }, 0, 1, 0, 1, o);
  EXPECT_LT(q.uncovered_fraction(), 0.5 * t.uncovered_fraction());
  EXPECT_LT(max_rel_error_2d(q, f, &covered), 1e-12);
}

// A narrow bump between the nodes: the interpolant alone would be wrong by
// far more than the tolerance near it. The checks catch it, so those points
// are not covered (what an unverified table would get wrong).
TEST(FunctionTable2D, CellsFailingTheirCheckAreNotCovered) {
  auto f = [](double x, double y) {
    const double dx = x - 0.5625, dy = y - 0.5625;  // the centre of a cell of the 9 x 9 grid
    return 1.0 + 0.2 * std::exp(-(dx * dx + dy * dy) / (2 * 0.01 * 0.01));
  };
  FunctionTable2DOptions o;
  o.max_levels = 0;
  const FunctionTable2D t =
      FunctionTable2D::build([&](double x, double y) { return TaggedValue{f(x, y), 0}; }, 0, 1, 0, 1, o);
  EXPECT_LT(t.cells_verified(), t.cells());
  EXPECT_FALSE(t.covers(0.5625, 0.5625));
  int covered = 0;
  EXPECT_LT(max_rel_error_2d(t, f, &covered), 5e-4);
  // Quartered, the cell's quarters check themselves. A centre check is an
  // estimate, not a bound: a quarter next to the bump's flank passes its
  // check and is off by 1.4 x the tolerance elsewhere (the bump itself is
  // 17 %, what the unchecked interpolant would give).
  o.max_levels = 3;
  o.max_evaluations = 2000;
  const FunctionTable2D q =
      FunctionTable2D::build([&](double x, double y) { return TaggedValue{f(x, y), 0}; }, 0, 1, 0, 1, o);
  EXPECT_GT(q.cells(), t.cells());
  EXPECT_LT(max_rel_error_2d(q, f, &covered), 1e-3);
}

TEST(FunctionTable2D, SameTableOnAnyThreadCountAndWithinTheBudget) {
  auto f = [](double x, double y) { return 1.0 + std::sin(6 * x) * std::cos(5 * y) * 0.3; };
  FunctionTable2DOptions o;
  o.max_levels = 2;
  o.max_evaluations = 200;
  const FunctionTable2D a =
      FunctionTable2D::build([&](double x, double y) { return TaggedValue{f(x, y), 0}; }, 0, 1, 0, 1, o);
  o.threads = 4;
  const FunctionTable2D b =
      FunctionTable2D::build([&](double x, double y) { return TaggedValue{f(x, y), 0}; }, 0, 1, 0, 1, o);
  EXPECT_LE(a.evaluations(), 200);
  EXPECT_EQ(a.evaluations(), b.evaluations());
  EXPECT_EQ(a.cells(), b.cells());
  for (int j = 0; j <= 50; ++j)
    for (int i = 0; i <= 50; ++i) {
      const auto va = a(i / 50.0, j / 50.0), vb = b(i / 50.0, j / 50.0);
      ASSERT_EQ(va.has_value(), vb.has_value());
      if (va) {
        EXPECT_EQ(va->value, vb->value);
      }
    }
}

TEST(FunctionTable2D, RejectsABadBoxOrNodes) {
  auto f = [](double, double) { return TaggedValue{1.0, 0}; };
  EXPECT_THROW(FunctionTable2D::build(f, 1, 0, 0, 1), InputError);
  FunctionTable2DOptions o;
  o.x_nodes = {0.0, 0.7, 0.5, 1.0};
  EXPECT_THROW(FunctionTable2D::build(f, 0, 1, 0, 1, o), InputError);
}

}  // namespace
}  // namespace rackopt::statistics
