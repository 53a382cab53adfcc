// Verified tensor-product table of an expensive scalar function of two
// variables, for a Monte Carlo whose two random inputs both shape the result
// (the wear life over the contact ratio and the load): a few hundred
// evaluations replace one per sample.
//
// Nodes form a uniform grid on [ax, bx] x [ay, by]. The interpolant is
// Steffen's monotone cubic (function_table.hpp) along x in each of the four
// rows around a point, then along y through those four values; both steps are
// local and never overshoot, so it is as smooth as the 1-D table in each
// direction.
//
// Nothing is interpolated unverified, as in the 1-D table:
//  - every cell is checked at its centre against a direct evaluation
//    (|interpolated - direct| <= rel_tolerance |direct| + abs_tolerance);
//  - a cell whose four corners or centre carry different tags (a failure-mode
//    switch inside) is never interpolated, and neither does a row or column
//    step reach across a tag change for its slopes;
//  - a cell that fails its check and is still wider than max_levels halvings
//    of the initial spacing is split in four, each quarter a small grid of its
//    own with its own checks, while the budget lasts;
//  - cells still failing, or left unchecked when the budget ran out, are left
//    to direct evaluation.
// `covers(x, y)` says whether (x, y) may be interpolated; callers evaluate the
// rest directly.
//
// Determinism: the nodes and checks depend only on f, the box and the
// options, never on the thread count (evaluations run in parallel and are
// stored by index).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "rackopt/statistics/function_table.hpp"

namespace rackopt::statistics {

struct FunctionTable2DOptions {
  int nodes_x = 9, nodes_y = 9;  // initial grid, >= 3 each
  // When not empty: the initial grid's x nodes (ascending, first ax, last bx,
  // >= 3) instead of nodes_x uniform ones, e.g. the nodes a 1-D table placed
  // where f changes fastest along x.
  std::vector<double> x_nodes;
  // The same for y (nodes_y uniform ones when empty).
  std::vector<double> y_nodes;
  // f's values at (x_nodes, known_row_y) when already computed (known_row
  // as long as x_nodes, known_row_y one of y_nodes): that row is not
  // evaluated again.
  double known_row_y = 0;
  std::vector<TaggedValue> known_row;
  double rel_tolerance = 5e-4;   // centre check, relative to |direct|
  double abs_tolerance = 0;      // centre check, absolute (>= 0)
  int max_levels = 2;            // quarterings of a failing cell
  int max_evaluations = 400;     // total budget including the initial grid
  unsigned threads = 1;          // result does not depend on it
};

class FunctionTable2D {
 public:
  // Tabulates f on [ax, bx] x [ay, by] (finite, ax < bx, ay < by, else
  // InputError). f must be deterministic and thread-safe; exceptions from f
  // propagate, and a non-finite value throws DesignError "table_nonfinite".
  static FunctionTable2D build(const std::function<TaggedValue(double, double)>& f, double ax, double bx,
                               double ay, double by, const FunctionTable2DOptions& options = {});

  // True when (x, y) lies in a verified cell (interpolation allowed).
  bool covers(double x, double y) const;
  // Interpolated value and tag; nullopt when !covers(x, y): evaluate f directly.
  std::optional<TaggedValue> operator()(double x, double y) const;

  int evaluations() const { return evaluations_; }
  // Cells of the finest grids (leaves): verified, with a tag switch, failing
  // the check or unchecked.
  int cells() const { return cells_; }
  int cells_verified() const { return verified_; }
  int cells_with_switch() const { return switches_; }
  // Largest centre check error accepted (relative to |direct|).
  double max_check_error() const { return max_check_error_; }
  // Fraction of the box's area left to direct evaluation.
  double uncovered_fraction() const;
  // Node coordinates of the initial grid.
  const std::vector<double>& x() const { return root_->x; }
  const std::vector<double>& y() const { return root_->y; }

 private:
  struct Grid {
    std::vector<double> x, y;          // ascending
    std::vector<double> v;             // v[j * nx + i] = f(x_i, y_j)
    std::vector<int> tag;
    std::vector<double> dx;            // Steffen slope along x at each node, within its row
    std::vector<char> ok;              // cell (i, j), (nx - 1) * j + i: verified
    std::vector<std::unique_ptr<Grid>> sub;  // cell's quarter-grid when refined (else empty)
    int level = 0;
    std::size_t nx() const { return x.size(); }
    std::size_t ny() const { return y.size(); }
  };
  static void row_slopes(Grid& g);
  static bool same_row_tag(const Grid& g, std::size_t j, std::size_t i);  // interval i of row j
  static bool uniform_cell(const Grid& g, std::size_t i, std::size_t j);
  static double row_value(const Grid& g, std::size_t j, std::size_t i, double x);
  static double value_in(const Grid& g, std::size_t i, std::size_t j, double x, double y);
  const Grid* leaf(double x, double y, std::size_t* i, std::size_t* j) const;

  std::unique_ptr<Grid> root_;
  int evaluations_ = 0, cells_ = 0, verified_ = 0, switches_ = 0;
  double max_check_error_ = 0, uncovered_area_ = 0;
};

}  // namespace rackopt::statistics
