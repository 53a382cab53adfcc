#include "rackopt/statistics/reliability.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "rackopt/core/error.hpp"
#include "rackopt/core/interrupt.hpp"

namespace rackopt::statistics {

namespace {

[[noreturn]] void bad(const std::string& message) {
  throw InputError(SourceMark{}, "reliability", message);
}

void require_open_unit(double v, const char* what) {
  if (!(v > 0 && v < 1)) bad(std::string(what) + " must be strictly inside (0, 1)");
}

void require_finite_sample(std::span<const double> x) {
  if (x.empty()) bad("no life samples");
  for (double v : x)
    if (!std::isfinite(v)) bad("life samples must be finite");
}

// P(B <= k) for B ~ Binomial(n, p); k < 0 gives 0.
double binomial_cdf(long k, double p, std::size_t n) {
  if (k < 0) return 0.0;
  if (static_cast<std::size_t>(k) >= n) return 1.0;
  return gsl_cdf_binomial_P(static_cast<unsigned>(k), p, static_cast<unsigned>(n));
}

// Linear-interpolated quantile (Hyndman & Fan type 7) of sorted values.
double sorted_quantile(const std::vector<double>& s, double p) {
  const double h = p * static_cast<double>(s.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(h));
  if (i + 1 >= s.size()) return s.back();
  return s[i] + (h - static_cast<double>(i)) * (s[i + 1] - s[i]);
}

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

double reliability_at(const Distribution& life, double t) {
  if (std::isnan(t)) bad("time is NaN");
  return life.survival(t);
}

double life_at_reliability(const Distribution& life, double reliability) {
  require_open_unit(reliability, "reliability R");
  return life.survival_quantile(reliability);
}

double empirical_reliability(std::span<const double> lives, double t) {
  require_finite_sample(lives);
  if (std::isnan(t)) bad("time is NaN");
  std::size_t surviving = 0;
  for (double v : lives) surviving += v > t ? 1 : 0;
  return static_cast<double>(surviving) / static_cast<double>(lives.size());
}

LifeInterval empirical_life_at_reliability(std::span<const double> lives, double reliability,
                                           double confidence) {
  require_open_unit(reliability, "reliability R");
  require_open_unit(confidence, "confidence");
  require_finite_sample(lives);
  std::vector<double> s(lives.begin(), lives.end());
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  const double p = 1.0 - reliability;
  const double tail = 0.5 * (1.0 - confidence);
  LifeInterval out;
  out.confidence = confidence;
  // Order statistic r = ceil(n p), 1-based, kept in [1, n]. The small
  // tolerance keeps n p = 50.000000001 (rounding of 1 - R) from jumping to 51.
  auto r = static_cast<std::size_t>(std::ceil(static_cast<double>(n) * p - 1e-9));
  r = std::clamp<std::size_t>(r, 1, n);
  out.estimate = s[r - 1];
  // P(B <= k) is non-decreasing in k: binary searches on k.
  // Lower: largest l in [1, n] with P(B <= l-1) <= tail.
  long lo = 0, hi = static_cast<long>(n);  // answer l in [0, n]; 0 = none
  while (lo < hi) {
    const long mid = (lo + hi + 1) / 2;
    if (binomial_cdf(mid - 1, p, n) <= tail) lo = mid; else hi = mid - 1;
  }
  if (lo >= 1) {
    out.lower = s[static_cast<std::size_t>(lo) - 1];
  } else {
    out.lower = 0.0;
    out.lower_bounded = false;
  }
  // Upper: smallest u in [1, n] with P(B <= u-1) >= 1 - tail.
  lo = 1, hi = static_cast<long>(n) + 1;  // n + 1 = none
  while (lo < hi) {
    const long mid = (lo + hi) / 2;
    if (mid <= static_cast<long>(n) && binomial_cdf(mid - 1, p, n) >= 1.0 - tail) hi = mid;
    else lo = mid + 1;
  }
  if (lo <= static_cast<long>(n)) {
    out.upper = s[static_cast<std::size_t>(lo) - 1];
  } else {
    out.upper = kInf;
    out.upper_bounded = false;
  }
  return out;
}

ReliabilitySummary summarize_lives(std::span<const double> lives,
                                   const ReliabilityRequest& request) {
  require_open_unit(request.ks_level, "KS level");
  require_open_unit(request.confidence, "confidence");
  for (double r : request.reliabilities) require_open_unit(r, "reliability R");
  for (double t : request.times)
    if (!(t >= 0) || !std::isfinite(t)) bad("times for R(t) must be finite and >= 0");
  if (request.candidates.empty()) bad("no candidate distribution to fit");

  ReliabilitySummary out;
  out.samples_total = lives.size();
  std::vector<double> finite, positive;
  for (double v : lives) {
    if (!std::isfinite(v)) {
      ++out.failed_evaluations;
      continue;
    }
    if (v < 0) bad("a life sample is negative (" + std::to_string(v) + " s)");
    finite.push_back(v);
    if (v > 0) positive.push_back(v); else ++out.immediate_failures;
  }
  if (finite.empty()) bad("all " + std::to_string(lives.size()) + " life samples failed");
  out.samples_fitted = positive.size();
  if (out.failed_evaluations > 0)
    out.warnings.push_back(std::to_string(out.failed_evaluations) + " of " +
                           std::to_string(out.samples_total) +
                           " samples failed to evaluate and are excluded");
  const double p0 = static_cast<double>(out.immediate_failures) / static_cast<double>(finite.size());
  if (out.immediate_failures > 0)
    out.warnings.push_back(std::to_string(out.immediate_failures) + " samples fail at once (life 0)" +
                           (positive.empty() ? std::string()
                                             : ": fitted R(t) is scaled by " + std::to_string(1.0 - p0)));

  // Life at R of a positive-life fit S, with the immediate failures: (1-p0) S(t) = R.
  auto fit_life = [&](const Distribution& d, double r) {
    const double q = r / (1.0 - p0);
    return q >= 1.0 ? 0.0 : d.survival_quantile(q);
  };

  for (std::size_t c = 0; c < request.candidates.size(); ++c) {
    CandidateFit cf;
    cf.family = request.candidates[c];
    if (request.stop && request.stop()) throw Interrupted("reliability fit: stopped by " + stop_reason());
    try {
      cf.fit = fit_life_distribution(cf.family, positive);
      BootstrapOptions bo;
      bo.replicates = request.bootstrap_replicates;
      // One independent bootstrap stream per candidate position.
      bo.seed = mix64(request.seed + 0x9E3779B97F4A7C15ULL * (c + 1));
      bo.threads = request.threads;
      bo.stop = request.stop;
      const auto reps = parametric_bootstrap(cf.family, cf.fit->distribution, positive.size(), bo);
      cf.ks = ks_test_from_bootstrap(cf.fit->distribution, positive, request.ks_level, reps);
      for (double r : request.reliabilities) {
        std::vector<double> boot;
        for (const auto& rep : reps)
          if (rep.refit) boot.push_back(fit_life(*rep.refit, r));
        std::sort(boot.begin(), boot.end());
        LifeInterval li;
        li.confidence = request.confidence;
        li.estimate = fit_life(cf.fit->distribution, r);
        li.lower = sorted_quantile(boot, 0.5 * (1.0 - request.confidence));
        li.upper = sorted_quantile(boot, 0.5 * (1.0 + request.confidence));
        cf.life_at_reliability.push_back(li);
      }
    } catch (const DesignError& e) {
      cf.fit.reset();
      cf.error = e.what();
    } catch (const InputError& e) {
      cf.fit.reset();
      cf.error = e.what();
    }
    out.candidates.push_back(std::move(cf));
  }

  // Choice: lowest AIC among the accepted, else lowest AIC overall.
  for (int pass = 0; pass < 2 && out.chosen < 0; ++pass) {
    for (std::size_t c = 0; c < out.candidates.size(); ++c) {
      const auto& cf = out.candidates[c];
      if (!cf.fit || (pass == 0 && !cf.ks.accepted)) continue;
      if (out.chosen < 0 || cf.fit->aic < out.candidates[out.chosen].fit->aic)
        out.chosen = static_cast<int>(c);
    }
    if (pass == 0 && out.chosen >= 0) out.chosen_accepted = true;
  }
  if (out.chosen < 0 && positive.empty()) {
    out.warnings.push_back("no distribution could be fitted: no sample has a positive life (every one fails at "
                           "once); empirical results only");
  } else if (out.chosen < 0) {
    out.warnings.push_back("no distribution could be fitted (" + out.candidates.front().error +
                           "): empirical results only");
  } else if (!out.chosen_accepted) {
    out.warnings.push_back(std::string("no candidate passed the KS test at level ") +
                           std::to_string(request.ks_level) + "; using the lowest AIC (" +
                           family_name(out.candidates[out.chosen].family) + ")");
  }
  const CandidateFit* chosen = out.chosen_fit();

  for (double t : request.times) {
    ReliabilityAtTime rt;
    rt.t = t;
    rt.empirical = empirical_reliability(finite, t);
    if (chosen) rt.fit = (1.0 - p0) * chosen->fit->distribution.survival(t);
    out.reliability.push_back(rt);
  }
  for (std::size_t i = 0; i < request.reliabilities.size(); ++i) {
    LifeAtReliability lr;
    lr.reliability = request.reliabilities[i];
    lr.empirical = empirical_life_at_reliability(finite, lr.reliability, request.confidence);
    if (chosen) lr.fit = chosen->life_at_reliability[i];
    out.life.push_back(lr);
  }
  return out;
}

ReliabilitySummary summarize_lives(std::span<const SampleResult> samples,
                                   const ReliabilityRequest& request) {
  std::vector<double> lives;
  lives.reserve(samples.size());
  for (const auto& s : samples)
    lives.push_back(s.ok() ? s.value : std::numeric_limits<double>::quiet_NaN());
  return summarize_lives(lives, request);
}

}  // namespace rackopt::statistics
