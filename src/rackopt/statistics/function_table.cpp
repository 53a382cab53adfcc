#include "rackopt/statistics/function_table.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/statistics/sampling.hpp"

namespace rackopt::statistics {

namespace {

// Interval states while building.
enum : char { kPending = 0, kOk = 1, kBreak = 2, kDirect = 3 };

// Steffen's one-sided end slope (his eq. 26-27) from the two nearest secants
// s0 (the end interval, width h0) and s1 (the next one, h1).
double steffen_end(double s0, double s1, double h0, double h1) {
  const double p = s0 * (1.0 + h0 / (h0 + h1)) - s1 * h0 / (h0 + h1);
  if (p * s0 <= 0) return 0.0;
  if (std::fabs(p) > 2.0 * std::fabs(s0)) return 2.0 * s0;
  return p;
}

}  // namespace

std::size_t FunctionTable::interval_of(double x) const {
  const auto it = std::upper_bound(x_.begin(), x_.end(), x);
  const std::ptrdiff_t i = (it - x_.begin()) - 1;
  return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(x_.size()) - 2));
}

double FunctionTable::hermite(std::size_t i, double x, double* dydx) const {
  const double h = x_[i + 1] - x_[i];
  const double u = (x - x_[i]) / h;
  const double a = y_[i], b = y_[i + 1], da = d_[i] * h, db = d_[i + 1] * h;
  const double v = 1.0 - u;
  if (dydx) {
    *dydx = (6.0 * u * v * (b - a) + da * v * (1.0 - 3.0 * u) + db * u * (3.0 * u - 2.0)) / h;
  }
  return a * v * v * (1.0 + 2.0 * u) + da * u * v * v + b * u * u * (3.0 - 2.0 * u) - db * u * u * v;
}

void FunctionTable::compute_slopes() {
  const std::size_t n = x_.size();
  d_.assign(n, 0.0);
  auto usable = [&](std::ptrdiff_t i) {
    return i >= 0 && static_cast<std::size_t>(i) + 1 < n && ok_[static_cast<std::size_t>(i)] != 0;
  };
  auto secant = [&](std::size_t i) { return (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]); };
  auto width = [&](std::size_t i) { return x_[i + 1] - x_[i]; };
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::ptrdiff_t>(i);
    const bool left = usable(k - 1), right = usable(k);
    if (left && right) {
      const double s0 = secant(i - 1), s1 = secant(i), h0 = width(i - 1), h1 = width(i);
      const double p = (s0 * h1 + s1 * h0) / (h0 + h1);
      d_[i] = (std::copysign(1.0, s0) + std::copysign(1.0, s1)) *
              std::min({std::fabs(s0), std::fabs(s1), 0.5 * std::fabs(p)});
    } else if (right) {  // start of a piece
      d_[i] = usable(k + 1) ? steffen_end(secant(i), secant(i + 1), width(i), width(i + 1)) : secant(i);
    } else if (left) {   // end of a piece
      d_[i] = usable(k - 2) ? steffen_end(secant(i - 1), secant(i - 2), width(i - 1), width(i - 2))
                            : secant(i - 1);
    }
  }
}

FunctionTable FunctionTable::build(const std::function<TaggedValue(double)>& f, double a, double b,
                                   const FunctionTableOptions& o) {
  const auto bad = [](const std::string& m) { throw InputError(SourceMark{}, "function table", m); };
  if (!(std::isfinite(a) && std::isfinite(b) && a < b)) bad("needs a finite interval a < b");
  if (o.initial_nodes < 3) bad("needs at least 3 initial nodes");
  if (!(o.rel_tolerance >= 0) || !(o.abs_tolerance >= 0) || o.rel_tolerance + o.abs_tolerance <= 0)
    bad("tolerances must be >= 0, one of them > 0");
  if (o.max_levels < 0 || !(o.break_width > 0)) bad("max_levels >= 0 and break_width > 0 needed");

  FunctionTable t;
  auto evaluate = [&](const std::vector<double>& xs) {
    std::vector<TaggedValue> out(xs.size());
    parallel_for(xs.size(), std::max(1u, o.threads), [&](std::size_t i) {
      out[i] = f(xs[i]);
      if (!std::isfinite(out[i].value))
        throw DesignError("table_nonfinite", "tabulated function is not finite at " + std::to_string(xs[i]));
    });
    t.evaluations_ += static_cast<int>(xs.size());
    return out;
  };

  const int n0 = o.initial_nodes;
  for (int i = 0; i < n0; ++i) t.x_.push_back(i + 1 == n0 ? b : a + (b - a) * i / (n0 - 1));
  for (const TaggedValue& v : evaluate(t.x_)) {
    t.y_.push_back(v.value);
    t.tag_.push_back(v.tag);
  }
  std::vector<char> st(t.x_.size() - 1);
  std::vector<int> level(st.size(), 0);
  for (std::size_t i = 0; i < st.size(); ++i) st[i] = t.tag_[i] == t.tag_[i + 1] ? kPending : kBreak;
  const double min_break = o.break_width * (b - a);

  for (;;) {
    std::vector<std::size_t> todo;
    for (std::size_t i = 0; i < st.size(); ++i) {
      if (st[i] == kPending || (st[i] == kBreak && t.x_[i + 1] - t.x_[i] > min_break)) todo.push_back(i);
    }
    if (todo.empty() || t.evaluations_ + static_cast<int>(todo.size()) > o.max_evaluations) break;
    std::vector<double> mid;
    for (std::size_t i : todo) mid.push_back(0.5 * (t.x_[i] + t.x_[i + 1]));
    const std::vector<TaggedValue> mv = evaluate(mid);

    // The check compares the interpolant of the current nodes, with every
    // same-tag interval (pending or accepted) interpolable.
    t.ok_.assign(st.size(), 0);
    for (std::size_t i = 0; i < st.size(); ++i) t.ok_[i] = (st[i] == kPending || st[i] == kOk) ? 1 : 0;
    t.compute_slopes();

    std::vector<double> nx, ny;
    std::vector<int> ntag, nlevel;
    std::vector<char> nst;
    std::size_t k = 0;
    for (std::size_t i = 0; i < st.size(); ++i) {
      nx.push_back(t.x_[i]);
      ny.push_back(t.y_[i]);
      ntag.push_back(t.tag_[i]);
      if (k >= todo.size() || todo[k] != i) {
        nst.push_back(st[i]);
        nlevel.push_back(level[i]);
        continue;
      }
      const TaggedValue v = mv[k];
      const double m = mid[k];
      ++k;
      nx.push_back(m);
      ny.push_back(v.value);
      ntag.push_back(v.tag);
      char left, right;
      int lv = level[i] + 1;
      if (st[i] == kPending && v.tag == t.tag_[i]) {
        const double err = std::fabs(t.hermite(i, m, nullptr) - v.value);
        if (err <= o.rel_tolerance * std::fabs(v.value) + o.abs_tolerance) {
          left = right = kOk;
          if (v.value != 0) t.max_check_error_ = std::max(t.max_check_error_, err / std::fabs(v.value));
        } else {
          left = right = level[i] + 1 > o.max_levels ? kDirect : kPending;
        }
      } else {
        // A tag switch inside: the half whose ends differ keeps the break;
        // a same-tag half is checked like any interval (one check only when
        // it comes from bisecting a break: it is small and next to the switch).
        left = t.tag_[i] != v.tag ? kBreak : kPending;
        right = v.tag != t.tag_[i + 1] ? kBreak : kPending;
        if (st[i] == kBreak) lv = std::max(lv, o.max_levels);
      }
      nst.push_back(left);
      nst.push_back(right);
      nlevel.push_back(lv);
      nlevel.push_back(lv);
    }
    nx.push_back(t.x_.back());
    ny.push_back(t.y_.back());
    ntag.push_back(t.tag_.back());
    t.x_ = std::move(nx);
    t.y_ = std::move(ny);
    t.tag_ = std::move(ntag);
    st = std::move(nst);
    level = std::move(nlevel);
  }

  t.ok_.assign(st.size(), 0);
  for (std::size_t i = 0; i < st.size(); ++i) {
    t.ok_[i] = st[i] == kOk ? 1 : 0;
    if (st[i] == kBreak) t.breaks_.emplace_back(t.x_[i], t.x_[i + 1]);
  }
  t.compute_slopes();
  return t;
}

bool FunctionTable::covers(double x) const {
  if (!(x >= x_.front() && x <= x_.back())) return false;
  return ok_[interval_of(x)] != 0;
}

std::optional<TaggedValue> FunctionTable::operator()(double x) const {
  if (!covers(x)) return std::nullopt;
  const std::size_t i = interval_of(x);
  return TaggedValue{hermite(i, x, nullptr), tag_[i]};
}

double FunctionTable::slope(double x) const {
  if (!covers(x)) return 0.0;
  double d = 0;
  hermite(interval_of(x), x, &d);
  return d;
}

bool FunctionTable::monotone(bool* increasing) const {
  const bool up = y_.back() >= y_.front();
  if (increasing) *increasing = up;
  for (std::size_t i = 0; i + 1 < y_.size(); ++i) {
    if (up ? y_[i + 1] < y_[i] : y_[i + 1] > y_[i]) return false;
  }
  return true;
}

double FunctionTable::invert_in_interval(std::size_t i, double v) const {
  const double ya = y_[i], yb = y_[i + 1];
  if (!ok_[i] || ya == yb) {
    const double u = ya == yb ? 0.5 : std::clamp((v - ya) / (yb - ya), 0.0, 1.0);
    return x_[i] + u * (x_[i + 1] - x_[i]);
  }
  // The Steffen cubic is monotone on a monotone interval: bisection is safe.
  const bool up = yb > ya;
  double lo = x_[i], hi = x_[i + 1];
  for (int it = 0; it < 64 && hi - lo > 1e-15 * std::max(std::fabs(lo), std::fabs(hi)); ++it) {
    const double m = 0.5 * (lo + hi);
    if ((hermite(i, m, nullptr) < v) == up) lo = m; else hi = m;
  }
  return 0.5 * (lo + hi);
}

double FunctionTable::uncovered_fraction() const {
  double w = 0;
  for (std::size_t i = 0; i < ok_.size(); ++i)
    if (!ok_[i]) w += x_[i + 1] - x_[i];
  return w / (x_.back() - x_.front());
}

}  // namespace rackopt::statistics
