#include "rackopt/statistics/life_fit.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sf_gamma.h>
#include <gsl/gsl_sf_psi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rackopt/core/error.hpp"

namespace rackopt::statistics {

namespace {

[[noreturn]] void bad(const std::string& message) {
  throw InputError(SourceMark{}, "life samples", message);
}

// Positive, finite, at least two distinct values. Returns the maximum.
double check_life_sample(std::span<const double> x, bool positive) {
  if (x.empty()) bad("no life samples to fit");
  double lo = x[0], hi = x[0];
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || (positive && !(x[i] > 0)))
      bad("sample " + std::to_string(i) + " is " + std::to_string(x[i]) +
          (positive ? "; lives must be finite and > 0" : "; values must be finite"));
    lo = std::min(lo, x[i]);
    hi = std::max(hi, x[i]);
  }
  // Lives that agree to 1e-6 have no spread a fit can resolve: the gamma
  // shape then rests on ln mean - mean ln ~ cv^2/2 < 1e-12, near the rounding
  // of the logarithms, and the bootstrap KS test of such nearly discrete
  // values is meaningless (seen: shape 6e17, D = 0.95 "accepted" for lives
  // 8e-9 apart). A real wear scatter is far wider (the model's own jitter
  // is 2e-4).
  if (x.size() < 2 || hi - lo <= 1e-6 * std::max(std::fabs(hi), std::fabs(lo)))
    throw DesignError("degenerate_life_sample",
                      "the " + std::to_string(x.size()) +
                          " life samples have no spread (all equal to " + std::to_string(hi) +
                          "): no two-parameter life distribution can be fitted");
  return hi;
}

double mean_of(std::span<const double> x) {
  double s = 0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

LifeFit finish(Distribution d, std::span<const double> x, int iterations) {
  const double ll = log_likelihood(d, x);
  return LifeFit{d, ll, 2.0 * 2.0 - 2.0 * ll, iterations};
}

// ln k - psi(k) and its derivative 1/k - psi'(k). For large k both are small
// differences of large numbers; the asymptotic series (Abramowitz & Stegun
// 6.3.18, 6.4.12) keeps full relative accuracy there.
double gamma_score(double k) {
  if (k < 50.0) return std::log(k) - gsl_sf_psi(k);
  const double r = 1.0 / k, r2 = r * r;
  return r * (0.5 + r * (1.0 / 12.0 - r2 * (1.0 / 120.0 - r2 / 252.0)));
}
double gamma_score_slope(double k) {
  if (k < 50.0) return 1.0 / k - gsl_sf_psi_1(k);
  const double r = 1.0 / k, r2 = r * r;
  return -r2 * (0.5 + r * (1.0 / 6.0 - r2 * (1.0 / 30.0 - r2 / 42.0)));
}

}  // namespace

double log_likelihood(const Distribution& d, std::span<const double> sample) {
  if (d.family() == Family::kGamma &&
      std::all_of(sample.begin(), sample.end(), [](double v) { return v > 0; })) {
    // ln Gamma(k) once, not per value (it dominated the bootstrap refits).
    const double k = d.first(), theta = d.second();
    double s = 0;
    for (double v : sample) s += (k - 1.0) * std::log(v) - v / theta;
    return s - static_cast<double>(sample.size()) * (gsl_sf_lngamma(k) + k * std::log(theta));
  }
  double s = 0;
  for (double v : sample) s += d.log_pdf(v);
  return s;
}

LifeFit fit_gamma(std::span<const double> x) {
  check_life_sample(x, true);
  const double m = mean_of(x);
  // s = ln(mean) - mean(ln x) = mean(d - ln(1+d)) + (ln(1+dbar) - dbar), d = x/m - 1.
  double sum_d = 0, sum_gap = 0;
  for (double v : x) {
    const double d = (v - m) / m;
    sum_d += d;
    sum_gap += d - std::log1p(d);
  }
  const double n = static_cast<double>(x.size());
  const double dbar = sum_d / n;
  const double s = sum_gap / n + (std::log1p(dbar) - dbar);
  if (!(s > 0))
    throw DesignError("degenerate_life_sample",
                      "life samples have no measurable spread (ln mean - mean ln = " +
                          std::to_string(s) + "): no gamma fit");
  // Minka (2002) / Choi & Wette (1969) starting value, within ~1.5% of the root.
  double k = (3.0 - s + std::sqrt((s - 3.0) * (s - 3.0) + 24.0 * s)) / (12.0 * s);
  int it = 0;
  for (; it < 100; ++it) {
    // Newton on y = ln k: f(y) = g(e^y) - s, f'(y) = k g'(k) < 0 (g decreasing).
    // Working in ln k keeps k > 0; the step limit guards the first iterations.
    const double f = gamma_score(k) - s;
    const double fp = k * gamma_score_slope(k);
    double step = -f / fp;
    step = std::clamp(step, -2.0, 2.0);  // at most a factor e^2 per step
    k *= std::exp(step);
    if (std::fabs(step) < 1e-13) break;
  }
  return finish(Distribution::gamma(k, m / k), x, it + 1);
}

LifeFit fit_weibull(std::span<const double> x) {
  const double xmax = check_life_sample(x, true);
  const std::size_t n = x.size();
  std::vector<double> l(n);  // ln(x / xmax) <= 0
  double mean_l = 0;
  for (std::size_t i = 0; i < n; ++i) {
    l[i] = std::log(x[i] / xmax);
    mean_l += l[i];
  }
  mean_l /= static_cast<double>(n);
  // g(b) = sum y^b l / sum y^b - 1/b - mean l, increasing from -inf to -mean l > 0.
  auto g = [&](double b, double* slope) {
    double s0 = 0, s1 = 0, s2 = 0;
    for (double li : l) {
      const double w = std::exp(b * li);
      s0 += w;
      s1 += w * li;
      s2 += w * li * li;
    }
    const double a1 = s1 / s0;
    if (slope) *slope = s2 / s0 - a1 * a1 + 1.0 / (b * b);
    return a1 - 1.0 / b - mean_l;
  };
  // Start from the Gumbel moment estimate: sd(ln X) = pi / (b sqrt 6).
  double var_l = 0;
  for (double li : l) var_l += (li - mean_l) * (li - mean_l);
  var_l /= static_cast<double>(n);
  double b = 1.2825498301618641 / std::sqrt(std::max(var_l, 1e-300));
  double lo = b, hi = b;
  int it = 0;
  while (g(lo, nullptr) > 0 && it < 200) lo *= 0.5, ++it;
  while (g(hi, nullptr) < 0 && it < 400) hi *= 2.0, ++it;
  b = std::clamp(b, lo, hi);
  for (int k = 0; k < 200; ++k, ++it) {
    double slope = 0;
    const double v = g(b, &slope);
    if (v == 0) break;
    (v < 0 ? lo : hi) = b;
    double next = b - v / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket
    const bool done = std::fabs(next - b) <= 1e-13 * b || hi - lo <= 1e-14 * b;
    b = next;
    if (done) break;
  }
  double mean_w = 0;
  for (double li : l) mean_w += std::exp(b * li);
  mean_w /= static_cast<double>(n);
  const double scale = xmax * std::exp(std::log(mean_w) / b);
  return finish(Distribution::weibull(scale, b), x, it);
}

LifeFit fit_lognormal(std::span<const double> x) {
  check_life_sample(x, true);
  double mu = 0;
  for (double v : x) mu += std::log(v);
  mu /= static_cast<double>(x.size());
  double var = 0;
  for (double v : x) var += (std::log(v) - mu) * (std::log(v) - mu);
  var /= static_cast<double>(x.size());
  return finish(Distribution::lognormal(std::exp(mu), std::sqrt(var)), x, 0);
}

LifeFit fit_normal(std::span<const double> x) {
  check_life_sample(x, false);
  const double m = mean_of(x);
  double var = 0;
  for (double v : x) var += (v - m) * (v - m);
  var /= static_cast<double>(x.size());
  return finish(Distribution::normal(m, std::sqrt(var)), x, 0);
}

LifeFit fit_life_distribution(Family family, std::span<const double> x) {
  switch (family) {
    case Family::kGamma: return fit_gamma(x);
    case Family::kWeibull: return fit_weibull(x);
    case Family::kLognormal: return fit_lognormal(x);
    case Family::kNormal: return fit_normal(x);
    case Family::kUniform: {
      check_life_sample(x, false);
      const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
      return finish(Distribution::uniform(*lo, *hi), x, 0);
    }
  }
  bad("unknown family");
}

// ---------------------------------------------------------------------------
// Least squares on reliability points.

namespace {

Distribution make_from_coords(Family f, const std::array<double, 2>& c) {
  switch (f) {
    case Family::kGamma: return Distribution::gamma(std::exp(c[0]), std::exp(c[1]));
    case Family::kWeibull: return Distribution::weibull(std::exp(c[0]), std::exp(c[1]));
    case Family::kLognormal: return Distribution::lognormal(std::exp(c[0]), std::exp(c[1]));
    case Family::kNormal: return Distribution::normal(c[0], std::exp(c[1]));
    case Family::kUniform: break;
  }
  bad("fit_to_reliability_points supports gamma, weibull, lognormal and normal");
}

// Straight line y = p + q x by least squares.
std::array<double, 2> line_fit(const std::vector<double>& xs, const std::vector<double>& ys) {
  const double n = static_cast<double>(xs.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    sx += xs[i], sy += ys[i], sxx += xs[i] * xs[i], sxy += xs[i] * ys[i];
  }
  const double den = n * sxx - sx * sx;
  const double q = den != 0 ? (n * sxy - sx * sy) / den : 0.0;
  return {(sy - q * sx) / n, q};
}

}  // namespace

ReliabilityPointFit fit_to_reliability_points(Family family, std::span<const double> t,
                                              std::span<const double> r) {
  if (t.size() != r.size() || t.size() < 2)
    throw InputError(SourceMark{}, "reliability points",
                     "need at least two (t, R) pairs of equal count");
  for (std::size_t i = 0; i < t.size(); ++i)
    if (!(t[i] > 0 && std::isfinite(t[i])) || !(r[i] > 0 && r[i] < 1))
      throw InputError(SourceMark{}, "reliability points",
                       "point " + std::to_string(i) + " needs t > 0 and 0 < R < 1");
  // Starting point from a straight line in the family's probability paper.
  std::vector<double> xs, ys;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (family == Family::kWeibull) {
      xs.push_back(std::log(t[i]));
      ys.push_back(std::log(-std::log(r[i])));  // = b ln t - b ln a
    } else {
      xs.push_back(family == Family::kLognormal ? std::log(t[i]) : t[i]);
      ys.push_back(gsl_cdf_ugaussian_Qinv(r[i]));  // = (x - mu) / sigma
    }
  }
  auto [p, q] = line_fit(xs, ys);
  if (!(q > 0)) q = 1.0 / (xs.back() - xs.front() + 1.0);  // unusable line: a wide guess
  const double loc = -p / q, spread = 1.0 / q;
  std::array<double, 2> c{};
  switch (family) {
    case Family::kGamma: {
      const double mu = std::max(loc, 1e-300), sd = spread;
      c = {std::log((mu / sd) * (mu / sd)), std::log(sd * sd / mu)};
      break;
    }
    case Family::kWeibull: c = {loc, std::log(q)}; break;       // loc = ln a
    case Family::kLognormal: c = {loc, std::log(spread)}; break;  // loc = ln median
    case Family::kNormal: c = {loc, std::log(spread)}; break;
    case Family::kUniform: make_from_coords(family, c); break;  // throws
  }
  auto cost = [&](const std::array<double, 2>& cc) {
    try {
      const Distribution d = make_from_coords(family, cc);
      double s = 0;
      for (std::size_t i = 0; i < t.size(); ++i) {
        const double e = d.survival(t[i]) - r[i];
        s += e * e;
      }
      return std::isfinite(s) ? s : std::numeric_limits<double>::max();
    } catch (const InputError&) {
      return std::numeric_limits<double>::max();
    }
  };
  // Nelder-Mead (standard coefficients 1, 2, 0.5, 0.5), restarted from the
  // best vertex until a restart no longer improves: cheap insurance against
  // the simplex collapsing in the long curved valley between shape and scale.
  double best = cost(c);
  for (int restart = 0; restart < 20; ++restart) {
    std::array<std::array<double, 2>, 3> v{c, c, c};
    v[1][0] += 0.1;
    v[2][1] += 0.1;
    std::array<double, 3> fv{cost(v[0]), cost(v[1]), cost(v[2])};
    for (int iter = 0; iter < 2000; ++iter) {
      std::array<int, 3> o{0, 1, 2};
      std::sort(o.begin(), o.end(), [&](int i, int j) { return fv[i] < fv[j]; });
      const auto b0 = v[o[0]], b1 = v[o[1]], w = v[o[2]];
      const double f0 = fv[o[0]], f1 = fv[o[1]], fw = fv[o[2]];
      if (std::fabs(fw - f0) <= 1e-16 * (f0 + 1e-30) + 1e-30 &&
          std::max(std::fabs(w[0] - b0[0]), std::fabs(w[1] - b0[1])) < 1e-12)
        break;
      const std::array<double, 2> cen{0.5 * (b0[0] + b1[0]), 0.5 * (b0[1] + b1[1])};
      auto along = [&](double a) {
        return std::array<double, 2>{cen[0] + a * (w[0] - cen[0]), cen[1] + a * (w[1] - cen[1])};
      };
      const auto xr = along(-1.0);
      const double fr = cost(xr);
      std::array<double, 2> nw = w;
      double fn = fw;
      if (fr < f0) {
        const auto xe = along(-2.0);
        const double fe = cost(xe);
        nw = fe < fr ? xe : xr;
        fn = std::min(fe, fr);
      } else if (fr < f1) {
        nw = xr, fn = fr;
      } else {
        const auto xc = fr < fw ? along(-0.5) : along(0.5);
        const double fc = cost(xc);
        if (fc < std::min(fr, fw)) {
          nw = xc, fn = fc;
        } else {  // shrink towards the best vertex
          for (int k : {o[1], o[2]}) {
            v[k] = {b0[0] + 0.5 * (v[k][0] - b0[0]), b0[1] + 0.5 * (v[k][1] - b0[1])};
            fv[k] = cost(v[k]);
          }
          continue;
        }
      }
      v[o[2]] = nw;
      fv[o[2]] = fn;
    }
    const int ib = static_cast<int>(std::min_element(fv.begin(), fv.end()) - fv.begin());
    const bool improved = fv[ib] < best * (1.0 - 1e-10);
    if (fv[ib] <= best) best = fv[ib], c = v[ib];
    if (!improved && restart > 0) break;
  }
  const Distribution d = make_from_coords(family, c);
  ReliabilityPointFit out{d, 0.0, 0.0};
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double e = d.survival(t[i]) - r[i];
    out.sum_squared_residuals += e * e;
    out.max_abs_residual = std::max(out.max_abs_residual, std::fabs(e));
  }
  return out;
}

}  // namespace rackopt::statistics
