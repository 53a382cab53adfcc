#include "rackopt/study/sweep_sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

#include "rackopt/doe/samplers.hpp"
#include "rackopt/study/study_result.hpp"

namespace rackopt::study {
namespace {

// The usable (x, y) pairs of one metric.
struct MetricSample {
  std::vector<const std::vector<double>*> x;
  std::vector<double> y;
  std::size_t left_out = 0;
};

MetricSample sample_of(const std::string& label, const std::vector<DesignResult>& points) {
  MetricSample s;
  for (const DesignResult& p : points) {
    const auto it = std::find(p.metric_labels.begin(), p.metric_labels.end(), label);
    const auto k = static_cast<std::size_t>(it - p.metric_labels.begin());
    if (it == p.metric_labels.end() || k >= p.metric_values.size() || k >= p.metric_ok.size() ||
        !p.metric_ok[k] || !std::isfinite(p.metric_values[k])) {
      ++s.left_out;
      continue;
    }
    s.x.push_back(&p.x);
    s.y.push_back(p.metric_values[k]);
  }
  return s;
}

double mean_of(const std::vector<double>& y) {
  double sum = 0;
  for (double v : y) sum += v;
  return sum / static_cast<double>(y.size());
}

// Population variance (1/N), two-pass: the indices are ratios of variances of
// the same finite population, so 1/N everywhere keeps them consistent.
double variance_of(const std::vector<double>& y, double mean) {
  double ss = 0;
  for (double v : y) ss += (v - mean) * (v - mean);
  return ss / static_cast<double>(y.size());
}

double clamp01(double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0; }

// The levels the runner builds for a grid sweep (sweep_driver.cpp).
std::vector<std::vector<double>> grid_levels(const StudySpec& spec) {
  std::vector<std::vector<double>> levels;
  for (const DesignVariable& v : spec.variables) {
    if (v.discrete()) {
      levels.push_back(v.values);
    } else {
      levels.push_back(doe::linspace_levels(v.lower, v.upper, v.levels.value_or(spec.sweep.levels)));
    }
  }
  return levels;
}

// Index of x among `levels` (ascending), or -1 when it is none of them. The
// runner puts the level values themselves into the points; the tolerance only
// absorbs a value that went through a text round trip.
long level_index(const std::vector<double>& levels, double x) {
  const double span = std::max(std::abs(levels.back() - levels.front()), std::abs(x));
  const double tol = 1e-9 * (span > 0 ? span : 1.0);
  for (std::size_t l = 0; l < levels.size(); ++l)
    if (std::abs(levels[l] - x) <= tol) return static_cast<long>(l);
  return -1;
}

// Cell values of a complete full-factorial grid (mixed radix, first variable
// slowest), or nullopt when a cell is missing, doubled, or a point is off the
// grid.
std::optional<std::vector<double>> complete_grid(const std::vector<std::vector<double>>& levels,
                                                 const MetricSample& s) {
  std::size_t cells = 1;
  for (const auto& l : levels) cells *= l.size();
  if (cells != s.y.size()) return std::nullopt;
  std::vector<double> y(cells, 0.0);
  std::vector<bool> filled(cells, false);
  for (std::size_t p = 0; p < s.y.size(); ++p) {
    std::size_t cell = 0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const long l = level_index(levels[i], (*s.x[p])[i]);
      if (l < 0) return std::nullopt;
      cell = cell * levels[i].size() + static_cast<std::size_t>(l);
    }
    if (filled[cell]) return std::nullopt;
    filled[cell] = true;
    y[cell] = s.y[p];
  }
  return y;
}

// Exact Sobol-Hoeffding (ANOVA) indices of the uniform distribution on the
// grid's cells: S_i from the level means of X_i, S_Ti from the spread of Y
// within each line of cells along X_i (the other variables fixed).
VariableSensitivity grid_indices(const std::vector<std::vector<double>>& levels, const std::vector<double>& y,
                                 std::size_t i, double mean, double var) {
  const std::size_t n = levels[i].size();
  std::size_t stride = 1;
  for (std::size_t j = i + 1; j < levels.size(); ++j) stride *= levels[j].size();
  const std::size_t cells = y.size();

  std::vector<double> level_sum(n, 0.0);
  for (std::size_t c = 0; c < cells; ++c) level_sum[(c / stride) % n] += y[c];
  const double per_level = static_cast<double>(cells / n);
  double v_first = 0;
  for (double s : level_sum) v_first += (s / per_level - mean) * (s / per_level - mean);
  v_first /= static_cast<double>(n);

  // Within-line variances, computed directly rather than as Var(Y) minus the
  // variance of the line means, so that a total index near 0 does not drown
  // in cancellation.
  double within = 0;
  std::size_t lines = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    if ((c / stride) % n != 0) continue;
    double m = 0;
    for (std::size_t l = 0; l < n; ++l) m += y[c + l * stride];
    m /= static_cast<double>(n);
    double ss = 0;
    for (std::size_t l = 0; l < n; ++l) ss += (y[c + l * stride] - m) * (y[c + l * stride] - m);
    within += ss / static_cast<double>(n);
    ++lines;
  }
  within /= static_cast<double>(lines);

  VariableSensitivity v;
  v.first_order = clamp01(v_first / var);
  v.total = clamp01(within / var);
  v.classes = n;
  return v;
}

// The classes of X_i for the given-data estimator: its distinct values when it
// is discrete or has at most `target` of them (an incomplete grid), else about
// `target` bins of equal count along the sorted values, a bin never splitting
// equal values. Returns the class of every point and the class count.
std::pair<std::vector<std::size_t>, std::size_t> classes_of(const MetricSample& s, std::size_t i, bool discrete,
                                                            std::size_t target) {
  const std::size_t n = s.y.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto xi = [&](std::size_t p) { return (*s.x[p])[i]; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return xi(a) < xi(b); });
  std::size_t distinct = n == 0 ? 0 : 1;
  for (std::size_t k = 1; k < n; ++k)
    if (xi(order[k]) != xi(order[k - 1])) ++distinct;

  std::vector<std::size_t> cls(n, 0);
  std::size_t count = 0;
  if (discrete || distinct <= target) {
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0 && xi(order[k]) != xi(order[k - 1])) ++count;
      cls[order[k]] = count;
    }
    return {cls, distinct};
  }
  std::size_t begin = 0;
  for (std::size_t b = 1; begin < n; ++b) {
    std::size_t end = b >= target ? n : std::max(begin + 1, (b * n + target / 2) / target);
    while (end < n && xi(order[end]) == xi(order[end - 1])) ++end;  // keep ties together
    for (std::size_t k = begin; k < end; ++k) cls[order[k]] = count;
    ++count;
    begin = end;
  }
  return {cls, count};
}

// Given-data first-order index: the correlation ratio of Y on the classes of
// X_i, between-class sum of squares over the total. With `correct`, less its
// expected value when the other variables fall at random into each class
// ((M-1) within-class mean squares, Kelley's correction). Balanced designs
// (Sobol nets, grid levels) stratify the other variables inside each class,
// so their class means carry little of that noise and the correction would
// remove a bias that is not there (docs/models/sensitivity.md has the numbers).
std::optional<VariableSensitivity> binned_first_order(const MetricSample& s, std::size_t i, bool discrete,
                                                      std::size_t target, double mean, bool correct) {
  const auto [cls, m] = classes_of(s, i, discrete, target);
  const std::size_t n = s.y.size();
  if (m < 2 || n <= m) return std::nullopt;
  std::vector<double> sum(m, 0.0);
  std::vector<std::size_t> cnt(m, 0);
  for (std::size_t p = 0; p < n; ++p) {
    sum[cls[p]] += s.y[p];
    ++cnt[cls[p]];
  }
  double ss_between = 0, ss_within = 0;
  for (std::size_t c = 0; c < m; ++c) {
    const double cm = sum[c] / static_cast<double>(cnt[c]);
    ss_between += static_cast<double>(cnt[c]) * (cm - mean) * (cm - mean);
  }
  for (std::size_t p = 0; p < n; ++p) {
    const double cm = sum[cls[p]] / static_cast<double>(cnt[cls[p]]);
    ss_within += (s.y[p] - cm) * (s.y[p] - cm);
  }
  const double ss_total = ss_between + ss_within;
  const double ms_within = ss_within / static_cast<double>(n - m);
  VariableSensitivity v;
  const double expected_noise = correct ? static_cast<double>(m - 1) * ms_within : 0.0;
  v.first_order = ss_total > 0 ? clamp01((ss_between - expected_noise) / ss_total) : 0.0;
  v.classes = m;
  return v;
}

std::string fixed(double v, int digits) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

void rank(std::vector<VariableSensitivity>& vars) {
  std::stable_sort(vars.begin(), vars.end(), [](const VariableSensitivity& a, const VariableSensitivity& b) {
    if (a.first_order != b.first_order) return a.first_order > b.first_order;
    return a.total.value_or(0.0) > b.total.value_or(0.0);
  });
}

void append(std::string& note, const std::string& sentence) {
  if (!note.empty()) note += ' ';
  note += sentence;
}

std::string names(const std::vector<std::string>& keys) {
  std::string out;
  for (const auto& k : keys) out += (out.empty() ? "" : ", ") + k;
  return out;
}

MetricSensitivity one_metric(const StudySpec& spec, const std::string& label,
                             const std::vector<DesignResult>& points) {
  MetricSensitivity r;
  r.metric = label;
  r.method = "none";
  const MetricSample s = sample_of(label, points);
  r.points_used = s.y.size();
  r.points_left_out = s.left_out;
  if (s.left_out > 0)
    append(r.note, std::to_string(s.left_out) + " of " + std::to_string(points.size()) +
                       " points left out (metric not computed).");
  if (s.y.size() < 2) {
    append(r.note, "Fewer than 2 points with this metric: no sensitivity.");
    return r;
  }
  const double mean = mean_of(s.y);
  r.variance = variance_of(s.y, mean);
  double largest = 0;
  for (double v : s.y) largest = std::max(largest, std::abs(v));
  if (!(std::sqrt(r.variance) > 1e-12 * largest)) {
    r.variance = 0;
    append(r.note, "Constant over the sweep: no variable moves it, no ranking.");
    return r;
  }

  const std::size_t nvar = spec.variables.size();
  std::optional<std::vector<double>> grid;
  std::vector<std::vector<double>> levels;
  if (spec.sweep.method == SweepSpec::Method::kGrid) {
    try {
      levels = grid_levels(spec);
      grid = complete_grid(levels, s);
    } catch (const std::invalid_argument&) {
      grid.reset();  // levels the runner could not have built: the points are not that grid
    }
  }

  std::vector<std::string> single;
  if (grid) {
    r.method = "grid ANOVA";
    for (std::size_t i = 0; i < nvar; ++i) {
      if (levels[i].size() < 2) {
        single.push_back(spec.variables[i].key);
        continue;
      }
      VariableSensitivity v = grid_indices(levels, *grid, i, mean, r.variance);
      v.variable = spec.variables[i].key;
      r.variables.push_back(v);
    }
  } else {
    r.method = "given-data binning";
    const auto target = std::max<std::size_t>(
        2, static_cast<std::size_t>(std::lround(std::sqrt(static_cast<double>(s.y.size())))));
    const bool correct = spec.sweep.method == SweepSpec::Method::kLatinHypercube;
    std::vector<std::string> thin;
    for (std::size_t i = 0; i < nvar; ++i) {
      const double x0 = (*s.x[0])[i];
      const bool constant = std::all_of(s.x.begin(), s.x.end(), [&](const auto* x) { return (*x)[i] == x0; });
      if (constant) {
        single.push_back(spec.variables[i].key);
        continue;
      }
      auto v = binned_first_order(s, i, spec.variables[i].discrete(), target, mean, correct);
      if (!v) {
        thin.push_back(spec.variables[i].key);
        continue;
      }
      v->variable = spec.variables[i].key;
      r.variables.push_back(*v);
    }
    if (spec.sweep.method == SweepSpec::Method::kGrid)
      append(r.note, "The grid is incomplete for this metric, so the exact grid decomposition does not apply.");
    append(r.note, "First order from " + std::to_string(s.y.size()) + " points, each variable's range in " +
                       std::to_string(target) + " equal-count bins (grid levels and discrete values as they are)" +
                       (correct ? ", less the spread an uninfluential variable would show by chance; "
                                  "accurate to about 1/sqrt(N) = " +
                                      fixed(1.0 / std::sqrt(static_cast<double>(s.y.size())), 2) + "."
                                : ".") +
                       " Total indices need a complete grid.");
    if (!thin.empty()) append(r.note, "Too few points per value to estimate: " + names(thin) + ".");
  }
  if (!single.empty()) append(r.note, "Not varied: " + names(single) + ".");
  if (r.variables.empty()) r.method = "none";
  rank(r.variables);
  return r;
}

// Markdown table cells must not contain a bare '|'.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::vector<MetricSensitivity> sweep_sensitivity(const StudySpec& spec, const std::vector<DesignResult>& points) {
  std::vector<MetricSensitivity> out;
  if (points.empty()) return out;
  for (const DesignResult& p : points)
    if (p.x.size() != spec.variables.size())
      throw std::invalid_argument("sweep_sensitivity: point '" + p.label + "' has " + std::to_string(p.x.size()) +
                                  " coordinates, the study has " + std::to_string(spec.variables.size()) +
                                  " variables");
  for (const std::string& label : points.front().metric_labels) out.push_back(one_metric(spec, label, points));
  return out;
}

std::string sensitivity_markdown(const std::vector<MetricSensitivity>& sensitivities) {
  std::string md;
  for (const MetricSensitivity& m : sensitivities) {
    md += "**" + cell(m.metric) + "** (" + m.method + ", " + std::to_string(m.points_used) + " points)\n\n";
    if (!m.variables.empty()) {
      md += "| variable | first order S_i | total S_Ti |\n|---|---|---|\n";
      for (const VariableSensitivity& v : m.variables)
        md += "| " + cell(v.variable) + " | " + fixed(v.first_order, 3) + " | " + (v.total ? fixed(*v.total, 3) : "-") +
              " |\n";
      md += "\n";
    }
    if (!m.note.empty()) md += m.note + "\n\n";
  }
  return md;
}

void sensitivity_json(JsonWriter& w, const std::vector<MetricSensitivity>& sensitivities) {
  w.begin_array();
  for (const MetricSensitivity& m : sensitivities) {
    w.begin_object();
    w.key("metric").value(m.metric);
    w.key("method").value(m.method);
    w.key("points_used").value(static_cast<long>(m.points_used));
    w.key("points_left_out").value(static_cast<long>(m.points_left_out));
    w.key("variance").value(m.variance);
    w.key("note").value(m.note);
    w.key("variables").begin_array();
    for (const VariableSensitivity& v : m.variables) {
      w.begin_object();
      w.key("variable").value(v.variable);
      w.key("first_order").value(v.first_order);
      w.key("total");
      if (v.total) {
        w.value(*v.total);
      } else {
        w.null();
      }
      w.key("classes").value(static_cast<long>(v.classes));
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
}

}  // namespace rackopt::study
