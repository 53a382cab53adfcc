#include "rackopt/statistics/function_table_2d.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/core/parallel_for.hpp"

namespace rackopt::statistics {

namespace {

// Steffen's one-sided end slope (his eq. 26-27), as in function_table.cpp.
double end_slope(double s0, double s1, double h0, double h1) {
  const double p = s0 * (1.0 + h0 / (h0 + h1)) - s1 * h0 / (h0 + h1);
  if (p * s0 <= 0) return 0.0;
  if (std::fabs(p) > 2.0 * std::fabs(s0)) return 2.0 * s0;
  return p;
}

// Steffen's interior slope from the secants on either side.
double inner_slope(double s0, double s1, double h0, double h1) {
  const double p = (s0 * h1 + s1 * h0) / (h0 + h1);
  return (std::copysign(1.0, s0) + std::copysign(1.0, s1)) *
         std::min({std::fabs(s0), std::fabs(s1), 0.5 * std::fabs(p)});
}

// Slope at node k of points (t, w), where usable(m) says whether interval
// [t_m, t_m+1] belongs to the same piece (the 1-D table's compute_slopes).
template <class T, class W, class U>
double node_slope(const T& t, const W& w, const U& usable, std::ptrdiff_t k) {
  auto s = [&](std::ptrdiff_t m) { return (w(m + 1) - w(m)) / (t(m + 1) - t(m)); };
  auto h = [&](std::ptrdiff_t m) { return t(m + 1) - t(m); };
  const bool left = usable(k - 1), right = usable(k);
  if (left && right) return inner_slope(s(k - 1), s(k), h(k - 1), h(k));
  if (right) return usable(k + 1) ? end_slope(s(k), s(k + 1), h(k), h(k + 1)) : s(k);
  if (left) return usable(k - 2) ? end_slope(s(k - 1), s(k - 2), h(k - 1), h(k - 2)) : s(k - 1);
  return 0.0;
}

double hermite(double a, double b, double da, double db, double h, double u) {
  const double v = 1.0 - u;
  return a * v * v * (1.0 + 2.0 * u) + da * h * u * v * v + b * u * u * (3.0 - 2.0 * u) - db * h * u * u * v;
}

std::size_t interval_in(const std::vector<double>& t, double x) {
  const auto it = std::upper_bound(t.begin(), t.end(), x);
  const std::ptrdiff_t i = (it - t.begin()) - 1;
  return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(t.size()) - 2));
}

}  // namespace

bool FunctionTable2D::same_row_tag(const Grid& g, std::size_t j, std::size_t i) {
  return g.tag[j * g.nx() + i] == g.tag[j * g.nx() + i + 1];
}

bool FunctionTable2D::uniform_cell(const Grid& g, std::size_t i, std::size_t j) {
  const std::size_t nx = g.nx();
  const int t = g.tag[j * nx + i];
  return g.tag[j * nx + i + 1] == t && g.tag[(j + 1) * nx + i] == t && g.tag[(j + 1) * nx + i + 1] == t;
}

void FunctionTable2D::row_slopes(Grid& g) {
  const std::size_t nx = g.nx();
  g.dx.assign(g.v.size(), 0.0);
  for (std::size_t j = 0; j < g.ny(); ++j) {
    const double* w = &g.v[j * nx];
    auto t = [&](std::ptrdiff_t m) { return g.x[static_cast<std::size_t>(m)]; };
    auto wv = [&](std::ptrdiff_t m) { return w[m]; };
    auto usable = [&](std::ptrdiff_t m) {
      return m >= 0 && static_cast<std::size_t>(m) + 1 < nx && same_row_tag(g, j, static_cast<std::size_t>(m));
    };
    for (std::size_t i = 0; i < nx; ++i) g.dx[j * nx + i] = node_slope(t, wv, usable, static_cast<std::ptrdiff_t>(i));
  }
}

double FunctionTable2D::row_value(const Grid& g, std::size_t j, std::size_t i, double x) {
  const std::size_t k = j * g.nx() + i;
  const double h = g.x[i + 1] - g.x[i];
  return hermite(g.v[k], g.v[k + 1], g.dx[k], g.dx[k + 1], h, (x - g.x[i]) / h);
}

double FunctionTable2D::value_in(const Grid& g, std::size_t i, std::size_t j, double x, double y) {
  // Rows j - 1 .. j + 2 along x; an outer row takes part in the y slopes only
  // when its interval carries the cell's tag.
  const int tag = g.tag[j * g.nx() + i];
  double w[4] = {0, 0, 0, 0}, t[4] = {0, 0, 0, 0};
  bool valid[4] = {false, true, true, false};
  for (int r = 0; r < 4; ++r) {
    const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(j) - 1 + r;
    if (row < 0 || static_cast<std::size_t>(row) >= g.ny()) continue;
    const auto rr = static_cast<std::size_t>(row);
    if ((r == 0 || r == 3) && !(same_row_tag(g, rr, i) && g.tag[rr * g.nx() + i] == tag)) continue;
    valid[r] = true;
    t[r] = g.y[rr];
    w[r] = row_value(g, rr, i, x);
  }
  auto tt = [&](std::ptrdiff_t m) { return t[m]; };
  auto ww = [&](std::ptrdiff_t m) { return w[m]; };
  auto usable = [&](std::ptrdiff_t m) { return m >= 0 && m < 3 && valid[m] && valid[m + 1]; };
  const double d1 = node_slope(tt, ww, usable, 1), d2 = node_slope(tt, ww, usable, 2);
  const double h = t[2] - t[1];
  return hermite(w[1], w[2], d1, d2, h, (y - t[1]) / h);
}

FunctionTable2D FunctionTable2D::build(const std::function<TaggedValue(double, double)>& f, double ax, double bx,
                                       double ay, double by, const FunctionTable2DOptions& o) {
  const auto bad = [](const std::string& m) { throw InputError(SourceMark{}, "function table 2d", m); };
  if (!(std::isfinite(ax) && std::isfinite(bx) && ax < bx && std::isfinite(ay) && std::isfinite(by) && ay < by))
    bad("needs a finite box ax < bx, ay < by");
  if (o.nodes_x < 3 || o.nodes_y < 3) bad("needs at least 3 nodes along each axis");
  if (!(o.rel_tolerance >= 0) || !(o.abs_tolerance >= 0) || o.rel_tolerance + o.abs_tolerance <= 0)
    bad("tolerances must be >= 0, one of them > 0");
  if (o.max_levels < 0) bad("max_levels >= 0 needed");
  if (!o.x_nodes.empty() && (o.x_nodes.size() < 3 || o.x_nodes.front() != ax || o.x_nodes.back() != bx ||
                             !std::is_sorted(o.x_nodes.begin(), o.x_nodes.end()) ||
                             std::adjacent_find(o.x_nodes.begin(), o.x_nodes.end()) != o.x_nodes.end()))
    bad("x_nodes must ascend strictly from ax to bx, at least 3 of them");
  if (!o.y_nodes.empty() && (o.y_nodes.size() < 3 || o.y_nodes.front() != ay || o.y_nodes.back() != by ||
                             !std::is_sorted(o.y_nodes.begin(), o.y_nodes.end()) ||
                             std::adjacent_find(o.y_nodes.begin(), o.y_nodes.end()) != o.y_nodes.end()))
    bad("y_nodes must ascend strictly from ay to by, at least 3 of them");
  if (!o.known_row.empty() && (o.known_row.size() != o.x_nodes.size() ||
                               std::find(o.y_nodes.begin(), o.y_nodes.end(), o.known_row_y) == o.y_nodes.end()))
    bad("known_row needs x_nodes of its length and known_row_y among y_nodes");

  FunctionTable2D t;
  auto evaluate = [&](const std::vector<std::pair<double, double>>& p) {
    std::vector<TaggedValue> out(p.size());
    parallel_for(p.size(), std::max(1u, o.threads), [&](std::size_t k) {
      out[k] = f(p[k].first, p[k].second);
      if (!std::isfinite(out[k].value))
        throw DesignError("table_nonfinite", "tabulated function is not finite at (" + std::to_string(p[k].first) +
                                                 ", " + std::to_string(p[k].second) + ")");
    });
    t.evaluations_ += static_cast<int>(p.size());
    return out;
  };
  auto uniform = [](double a, double b, int n) {
    std::vector<double> u;
    for (int k = 0; k < n; ++k) u.push_back(k + 1 == n ? b : a + (b - a) * k / (n - 1));
    return u;
  };

  t.root_ = std::make_unique<Grid>();
  Grid& root = *t.root_;
  root.x = o.x_nodes.empty() ? uniform(ax, bx, o.nodes_x) : o.x_nodes;
  root.y = o.y_nodes.empty() ? uniform(ay, by, o.nodes_y) : o.y_nodes;
  {
    std::vector<std::pair<double, double>> p;
    std::vector<std::size_t> at;
    root.v.assign(root.x.size() * root.y.size(), 0.0);
    root.tag.assign(root.v.size(), 0);
    for (std::size_t j = 0; j < root.y.size(); ++j)
      for (std::size_t i = 0; i < root.x.size(); ++i) {
        const std::size_t k = j * root.x.size() + i;
        if (!o.known_row.empty() && root.y[j] == o.known_row_y) {
          root.v[k] = o.known_row[i].value;
          root.tag[k] = o.known_row[i].tag;
        } else {
          p.emplace_back(root.x[i], root.y[j]);
          at.push_back(k);
        }
      }
    const std::vector<TaggedValue> pv = evaluate(p);
    for (std::size_t k = 0; k < pv.size(); ++k) {
      root.v[at[k]] = pv[k].value;
      root.tag[at[k]] = pv[k].tag;
    }
  }

  // Level by level: check every cell of the grids made at this level at its
  // centre, then quarter the cells that failed (or hold a switch) into the
  // grids of the next level while the budget lasts.
  std::vector<Grid*> pending{&root};
  while (!pending.empty()) {
    struct Cell {
      Grid* g;
      std::size_t i, j;
    };
    std::vector<Cell> checked, split;
    std::vector<std::pair<double, double>> centres;
    for (Grid* g : pending) {
      row_slopes(*g);
      const std::size_t cx = g->nx() - 1, cy = g->ny() - 1;
      g->ok.assign(cx * cy, 0);
      g->sub.resize(cx * cy);
      for (std::size_t j = 0; j < cy; ++j)
        for (std::size_t i = 0; i < cx; ++i) {
          if (uniform_cell(*g, i, j)) {
            checked.push_back({g, i, j});
            centres.emplace_back(0.5 * (g->x[i] + g->x[i + 1]), 0.5 * (g->y[j] + g->y[j + 1]));
          } else {
            split.push_back({g, i, j});
          }
        }
    }
    // A level whose checks do not fit leaves its cells unchecked (direct).
    if (t.evaluations_ + static_cast<int>(centres.size()) > o.max_evaluations) break;
    const std::vector<TaggedValue> cv = evaluate(centres);
    std::vector<TaggedValue> centre_of_split(split.size());
    std::vector<char> has_centre(split.size(), 0);
    for (std::size_t k = 0; k < checked.size(); ++k) {
      const Cell& c = checked[k];
      const Grid& g = *c.g;
      const TaggedValue& v = cv[k];
      bool pass = v.tag == g.tag[c.j * g.nx() + c.i];
      if (pass) {
        const double err = std::fabs(value_in(g, c.i, c.j, centres[k].first, centres[k].second) - v.value);
        pass = err <= o.rel_tolerance * std::fabs(v.value) + o.abs_tolerance;
        if (pass && v.value != 0) t.max_check_error_ = std::max(t.max_check_error_, err / std::fabs(v.value));
      }
      if (pass) {
        c.g->ok[c.j * (g.nx() - 1) + c.i] = 1;
      } else {
        split.push_back(c);
        centre_of_split.push_back(v);
        has_centre.push_back(1);
      }
    }
    // Quarter the cells in a fixed order (switches first, grid by grid) while
    // their new nodes and the quarters' checks fit in the budget.
    std::vector<Grid*> next;
    std::vector<std::pair<double, double>> p;
    std::vector<std::pair<Grid*, std::size_t>> fill;  // (sub-grid, node index) of each new point
    int reserved = 0;
    for (std::size_t k = 0; k < split.size(); ++k) {
      const Cell& c = split[k];
      if (c.g->level >= o.max_levels) continue;
      const int cost = (has_centre[k] ? 4 : 5) + 4;
      if (t.evaluations_ + reserved + cost > o.max_evaluations) break;
      reserved += cost;
      const Grid& g = *c.g;
      auto s = std::make_unique<Grid>();
      s->level = g.level + 1;
      s->x = {g.x[c.i], 0.5 * (g.x[c.i] + g.x[c.i + 1]), g.x[c.i + 1]};
      s->y = {g.y[c.j], 0.5 * (g.y[c.j] + g.y[c.j + 1]), g.y[c.j + 1]};
      s->v.assign(9, 0.0);
      s->tag.assign(9, 0);
      for (std::size_t b = 0; b < 2; ++b)
        for (std::size_t a = 0; a < 2; ++a) {
          const std::size_t from = (c.j + b) * g.nx() + c.i + a, to = 6 * b + 2 * a;
          s->v[to] = g.v[from];
          s->tag[to] = g.tag[from];
        }
      if (has_centre[k]) {
        s->v[4] = centre_of_split[k].value;
        s->tag[4] = centre_of_split[k].tag;
      } else {
        p.emplace_back(s->x[1], s->y[1]);
        fill.emplace_back(s.get(), 4);
      }
      for (std::size_t node : {1u, 3u, 5u, 7u}) {
        p.emplace_back(s->x[node % 3], s->y[node / 3]);
        fill.emplace_back(s.get(), node);
      }
      next.push_back(s.get());
      c.g->sub[c.j * (g.nx() - 1) + c.i] = std::move(s);
    }
    const std::vector<TaggedValue> nv = evaluate(p);
    for (std::size_t k = 0; k < nv.size(); ++k) {
      fill[k].first->v[fill[k].second] = nv[k].value;
      fill[k].first->tag[fill[k].second] = nv[k].tag;
    }
    pending = std::move(next);
  }
  // Grids made but never checked (the budget ran out) keep ok all 0.
  std::function<void(Grid&)> tally = [&](Grid& g) {
    const std::size_t cx = g.nx() - 1, cy = g.ny() - 1;
    if (g.ok.size() != cx * cy) {
      g.ok.assign(cx * cy, 0);
      g.sub.resize(cx * cy);
      row_slopes(g);
    }
    for (std::size_t j = 0; j < cy; ++j)
      for (std::size_t i = 0; i < cx; ++i) {
        const std::size_t c = j * cx + i;
        if (g.sub[c]) {
          tally(*g.sub[c]);
          continue;
        }
        ++t.cells_;
        if (g.ok[c]) {
          ++t.verified_;
        } else {
          if (!uniform_cell(g, i, j)) ++t.switches_;
          t.uncovered_area_ += (g.x[i + 1] - g.x[i]) * (g.y[j + 1] - g.y[j]);
        }
      }
  };
  tally(root);
  t.uncovered_area_ /= (bx - ax) * (by - ay);
  return t;
}

const FunctionTable2D::Grid* FunctionTable2D::leaf(double x, double y, std::size_t* i, std::size_t* j) const {
  const Grid* g = root_.get();
  if (!(x >= g->x.front() && x <= g->x.back() && y >= g->y.front() && y <= g->y.back())) return nullptr;
  for (;;) {
    *i = interval_in(g->x, x);
    *j = interval_in(g->y, y);
    const Grid* s = g->sub[*j * (g->nx() - 1) + *i].get();
    if (!s) return g;
    g = s;
  }
}

bool FunctionTable2D::covers(double x, double y) const {
  std::size_t i = 0, j = 0;
  const Grid* g = leaf(x, y, &i, &j);
  return g && g->ok[j * (g->nx() - 1) + i] != 0;
}

std::optional<TaggedValue> FunctionTable2D::operator()(double x, double y) const {
  std::size_t i = 0, j = 0;
  const Grid* g = leaf(x, y, &i, &j);
  if (!g || !g->ok[j * (g->nx() - 1) + i]) return std::nullopt;
  return TaggedValue{value_in(*g, i, j, x, y), g->tag[j * g->nx() + i]};
}

double FunctionTable2D::uncovered_fraction() const { return uncovered_area_; }

}  // namespace rackopt::statistics
