// Adaptive, verified tabulation of an expensive scalar function of one
// variable, for Monte Carlo with one random input (a life at R from 1000
// samples in well under 100 ms): a few dozen evaluations replace one per
// sample.
//
// The interpolant is Steffen's (1990) monotone piecewise cubic Hermite
// ("A simple method for monotonic interpolation in one dimension", A&A 239,
// 443): C1, local, no overshoot, so a monotone function stays monotone and
// its table can be inverted.
//
// Nothing is interpolated unverified:
//  - every interval is checked at its midpoint against a direct evaluation
//    (|interpolated - direct| <= rel_tolerance |direct| + abs_tolerance),
//    and halved until it passes or max_levels is reached;
//  - every value carries a tag (for the wear life: the failure criterion and
//    the limiting member). Nodes of different tags are never interpolated
//    across: the switch point is bracketed by bisection to break_width and
//    that bracket is left to direct evaluation. A kink or jump where the tag
//    changes (h_max vs contact-ratio criterion, a sample failing at once) is
//    therefore never smeared;
//  - intervals still failing the check (a kink or jump with the same tag, a
//    function noisier than the tolerance) are left to direct evaluation.
// `covers(x)` says whether x may be interpolated; callers evaluate the rest
// directly, so the table only decides speed, never correctness beyond the
// checked tolerance.
//
// Determinism: the nodes depend only on f, [a, b] and the options, never on
// the thread count (evaluations of one refinement level run in parallel and
// are stored by index).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace rackopt::statistics {

struct TaggedValue {
  double value = 0;
  int tag = 0;  // regime of f at that point; interpolation never crosses a tag change
};

struct FunctionTableOptions {
  int initial_nodes = 9;         // uniform on [a, b], >= 3
  double rel_tolerance = 5e-4;   // midpoint check, relative to |direct|
  double abs_tolerance = 0;      // midpoint check, absolute (>= 0)
  int max_levels = 5;            // halvings of the initial spacing for the check
  int max_evaluations = 96;      // total budget including the initial nodes
  double break_width = 1e-3;     // tag switches bracketed to this fraction of b - a
  unsigned threads = 1;          // result does not depend on it
};

class FunctionTable {
 public:
  // Tabulates f on [a, b] (a < b, both finite, else InputError). f must be
  // deterministic and thread-safe; exceptions from f propagate, and a
  // non-finite value throws DesignError "table_nonfinite": the caller then
  // falls back to direct evaluation.
  static FunctionTable build(const std::function<TaggedValue(double)>& f, double a, double b,
                             const FunctionTableOptions& options = {});

  // True when x lies in a verified interval (interpolation allowed).
  bool covers(double x) const;
  // Interpolated value and tag; nullopt when !covers(x): evaluate f directly.
  std::optional<TaggedValue> operator()(double x) const;
  // Slope of the interpolant at a covered x (0 when not covered).
  double slope(double x) const;

  // Nodes, ascending, with f's exact values and tags.
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<int>& tags() const { return tag_; }
  // verified()[i]: interval [x_i, x_{i+1}] may be interpolated.
  const std::vector<char>& verified() const { return ok_; }

  // Node values never decrease (increasing = true) or never increase.
  bool monotone(bool* increasing = nullptr) const;
  // x with interpolant(x) = v inside interval i (verified, its node values
  // bracketing v), by bisection on the cubic; for an unverified interval the
  // linear interpolation of its node values.
  double invert_in_interval(std::size_t i, double v) const;

  int evaluations() const { return evaluations_; }
  // Largest midpoint check error of the intervals accepted (relative to
  // |direct|): an a-posteriori estimate for the coarser interpolant the final
  // table refines.
  double max_check_error() const { return max_check_error_; }
  // Brackets [lo, hi] of tag switches (left to direct evaluation).
  const std::vector<std::pair<double, double>>& breaks() const { return breaks_; }
  // Fraction of [a, b] left to direct evaluation.
  double uncovered_fraction() const;

 private:
  void compute_slopes();
  std::size_t interval_of(double x) const;  // i with x_i <= x <= x_{i+1}; x inside [a, b]
  double hermite(std::size_t i, double x, double* dydx) const;

  std::vector<double> x_, y_, d_;
  std::vector<int> tag_;
  std::vector<char> ok_;
  std::vector<std::pair<double, double>> breaks_;
  int evaluations_ = 0;
  double max_check_error_ = 0;
};

}  // namespace rackopt::statistics
