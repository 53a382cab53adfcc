#include "rackopt/life/wear_reliability.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "rackopt/core/error.hpp"
#include "rackopt/core/progress_bar.hpp"
#include "rackopt/reliability/distribution.hpp"
#include "rackopt/reliability/sampling.hpp"

namespace rackopt {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double nominal_surface_hardness(const Drive& d) {
  const double h = d.wear.rack_hardness.surface > 0 ? d.wear.rack_hardness.surface : d.wear.pinion_hardness.surface;
  return h;
}

}  // namespace

WearSample wear_sample_for(const Drive& d, const std::vector<RandomInput>& inputs, const std::vector<double>& x) {
  WearSample s;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string& key = inputs[i].key;
    const double v = x[i];
    if (key == "contact_ratio") {
      s.contact_ratio = v;
    } else if (key == "wear.coefficient") {
      s.wear_coefficient_scale = v / d.wear.coefficient;
    } else if (key == "load") {
      s.force_scale = v / d.load.force;
    } else if (key == "surface_hardness") {
      const double h0 = nominal_surface_hardness(d);
      if (!(h0 > 0)) throw InputError({d.source_file, 0, 0}, "reliability.random", "surface_hardness needs a surface hardness in wear.hardness");
      s.surface_hardness_scale = v / h0;
    } else {
      throw InputError({d.source_file, 0, 0}, "reliability.random",
                       "unknown random input '" + key + "' (allowed: contact_ratio, wear_coefficient, load, surface_hardness)");
    }
  }
  return s;
}

WearReliabilityResult run_wear_reliability(const Drive& drive, const WearReliabilityOptions& opt) {
  const SourceMark where{drive.source_file, 0, 0};
  if (!(drive.wear.coefficient > 0)) {
    throw InputError(where, "wear.coefficient", "wear is not configured: give wear.coefficient (and wear.hardness, duty)");
  }
  if (!(drive.duty.rack_meshes_per_year > 0)) {
    throw InputError(where, "duty.rack_meshes_per_year", "a duty is needed for lives in years: give duty.rack_meshes_per_year > 0");
  }
  WearReliabilityResult out;
  const WearModel model(drive);
  auto t0 = std::chrono::steady_clock::now();
  out.nominal = model.life();
  out.nominal_ms = ms_since(t0);

  const ReliabilitySpec& spec = drive.reliability;
  const std::vector<RandomInput>& inputs = spec.inputs;
  if (inputs.empty()) return out;

  std::vector<reliability::Distribution> dist;
  for (const RandomInput& in : inputs) {
    dist.push_back(reliability::to_distribution(in));
    out.input_keys.push_back(in.key);
  }
  const std::size_t n = static_cast<std::size_t>(opt.samples > 0 ? opt.samples : spec.samples);
  const std::uint64_t seed = static_cast<std::uint64_t>(opt.seed >= 0 ? opt.seed : static_cast<long>(spec.seed));
  const std::size_t dim = inputs.size();
  const reliability::PointSet points = spec.sobol ? reliability::sobol_points(n, dim, true, seed)
                                                  : reliability::pseudo_random_points(n, dim, seed);
  out.input_values.assign(n, std::vector<double>(dim));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < dim; ++k) out.input_values[i][k] = dist[k].quantile(points.at(i, k));
  }
  unsigned threads = opt.threads > 0 ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(n, 1)));
  out.threads_used = threads;
  out.criteria.assign(n, std::string());
  t0 = std::chrono::steady_clock::now();
  out.lives = reliability::evaluate_samples(n, threads, [&](std::size_t i) {
    const WearLifeResult r = model.life(wear_sample_for(drive, inputs, out.input_values[i]));
    out.criteria[i] = r.criterion;  // each index written by one thread only
    if (opt.progress) opt.progress->tick();
    return r.life_years * kSecondsPerYear;
  });
  out.samples_ms = ms_since(t0);

  t0 = std::chrono::steady_clock::now();
  reliability::ReliabilityRequest req;
  req.ks_level = spec.ks_level;
  req.reliabilities = spec.reliabilities;
  req.times = spec.times;
  req.bootstrap_replicates = opt.bootstrap_replicates;
  req.seed = seed;
  req.threads = threads;
  out.summary = reliability::summarize_lives(out.lives, req);

  // Exact results for one monotone input (issue 3: "the life at R is exact
  // from that input's quantile").
  if (dim == 1) {
    const reliability::Distribution& d0 = dist[0];
    auto life_at_q = [&](double q) {
      return model.life(wear_sample_for(drive, inputs, {d0.quantile(q)})).life_years;
    };
    // A sampled contact ratio outside [max(1, [eps]), eps_max] fails at once
    // (life 0): the life is monotone only on the probabilities [qa, qb]
    // between those bounds, and R(t) and the life at R count the rest as
    // failed at t = 0 (seed 004's R = P([eps] <= eps <= eps_max)).
    double qa = 0.0, qb = 1.0;
    if (inputs[0].key == "contact_ratio") {
      qa = d0.cdf(std::max(1.0, drive.wear.min_contact_ratio));
      qb = d0.cdf(model.max_contact_ratio());
    }
    ExactReliability& ex = out.exact;
    ex.available = true;
    ex.input = inputs[0].key;
    ex.failed_at_start = qa + (1.0 - qb);
    if (qb - qa > 1e-12) {
      const double lo = life_at_q(qa + 0.25 * (qb - qa)), hi = life_at_q(qa + 0.75 * (qb - qa));
      ex.life_increases = hi >= lo;
      // life at R: P(life > t_R) = R. An R above the probability of starting
      // inside the bounds cannot be reached: life 0.
      for (double R : spec.reliabilities) {
        const double q = ex.life_increases ? qb - R : qa + R;
        ex.life_at_R_years.push_back(q < qa || q > qb ? 0.0 : life_at_q(std::clamp(q, qa + 1e-12, qb - 1e-12)));
      }
      // R(t): the probability q* in [qa, qb] where the life crosses t, by
      // bisection on q.
      for (double t : spec.times) {
        const double t_years = t / kSecondsPerYear;
        double a = qa + 1e-12, b = qb - 1e-12;
        for (int it = 0; it < 60; ++it) {
          const double m = 0.5 * (a + b);
          const bool below = life_at_q(m) <= t_years;  // life(q) <= t
          if (ex.life_increases == below) {
            a = m;
          } else {
            b = m;
          }
        }
        const double q = 0.5 * (a + b);
        ex.R_at_times.push_back(std::clamp(ex.life_increases ? qb - q : q - qa, 0.0, 1.0));
      }
    } else {
      ex.life_at_R_years.assign(spec.reliabilities.size(), 0.0);
      ex.R_at_times.assign(spec.times.size(), 0.0);
    }
  }
  out.fit_ms = ms_since(t0);
  return out;
}

}  // namespace rackopt
