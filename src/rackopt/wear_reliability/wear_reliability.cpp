#include "rackopt/wear_reliability/wear_reliability.hpp"

#include <algorithm>
#include <stdexcept>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
#include <optional>
#include <thread>

#include "rackopt/core/error.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/parallel_for.hpp"
#include "rackopt/core/progress_bar.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/wear_reliability/design_scatter.hpp"
#include "rackopt/wear_reliability/life_scaling.hpp"
#include "rackopt/wear_reliability/life_at_R_check.hpp"
#include "rackopt/wear_reliability/sample_domain.hpp"
#include "rackopt/statistics/distribution.hpp"
#include "rackopt/statistics/function_table.hpp"
#include "rackopt/statistics/function_table_2d.hpp"
#include "rackopt/statistics/sampling.hpp"

namespace rackopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Failure criteria as table tags (with the limiting member): the table never
// interpolates across a change of either, i.e. across a kink of life(input).
const char* const kCriteria[] = {"max_depth", "case_depth", "contact_ratio", "initial_contact_ratio",
                                 "contact_ratio_above_max"};
constexpr int kCriteriaCount = static_cast<int>(sizeof(kCriteria) / sizeof(kCriteria[0]));

int criterion_tag(const WearLifeResult& r) {
  int c = kCriteriaCount;  // unknown criterion: a tag of its own
  for (int i = 0; i < kCriteriaCount; ++i)
    if (r.criterion == kCriteria[i]) c = i;
  return 2 * c + (r.limiting_member == Member::kRack ? 0 : 1);
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string criterion_of_tag(int tag) {
  const int c = tag / 2;
  return c < kCriteriaCount ? kCriteria[c] : std::string("other");
}

// The status of a Monte Carlo run and one summary warning per kind of failed sample
// (docs/models/reliability.md, "Failed samples"): inputs outside their
// domain (once per input, with the count), every sample failing at once, and
// a life at R that is 0 because more than 1 - R of the samples fail at once.
void failed_sample_warnings(const Drive& drive, const WearModel& model, WearReliabilityResult& out) {
  const statistics::ReliabilitySummary& s = out.summary;
  const std::size_t n = out.lives.size();
  const std::string of_n = " of " + std::to_string(n) + " samples";
  for (std::size_t k = 0; k < out.outside_domain_samples.size(); ++k) {
    const std::size_t c = out.outside_domain_samples[k];
    if (c == 0) continue;
    const std::string& key = out.input_keys[k];
    out.summary.warnings.push_back(
        key + ": " + std::to_string(c) + of_n + " have a sampled value " +
        (input_must_be_positive(key) ? "that is not positive or not finite" : "that is not finite") +
        " (the distribution reaches outside the input's domain): they are not drives and are excluded as "
        "failed evaluations; R(t) and the life at R are conditional on a valid sample" +
        (input_must_be_positive(key) ? " (a lognormal keeps a positive input positive)" : ""));
  }
  const std::size_t evaluated = s.samples_total - s.failed_evaluations;
  if (evaluated == 0) {
    out.status = SamplingStatus::kNoValidSample;
    out.summary.warnings.push_back("no life at reliability R: none" + of_n +
                           " could be evaluated, so there is no R(t) and no life at R");
    return;
  }
  const std::string bounds = "contact ratio outside [" + num(std::max(1.0, drive.wear.min_contact_ratio)) + ", " +
                             num(model.max_contact_ratio()) + "]";
  if (s.immediate_failures == evaluated) {
    out.status = SamplingStatus::kEverySampleFailsAtOnce;
    out.summary.warnings.push_back("no life at reliability R: every evaluated sample (" + std::to_string(evaluated) + of_n +
                           ") fails at once (life 0, " + bounds +
                           "), so the life at every R is 0 and R(t) = 0");
    return;
  }
  out.status = SamplingStatus::kOk;
  if (s.immediate_failures == 0) return;
  const double p0 = static_cast<double>(s.immediate_failures) / static_cast<double>(evaluated);
  std::string unreachable;
  for (double R : drive.reliability.reliabilities) {
    if (p0 > 1.0 - R) unreachable += (unreachable.empty() ? "" : ", ") + num(R);
  }
  if (!unreachable.empty()) {
    out.summary.warnings.push_back("life at R = " + unreachable + " is 0: " + std::to_string(s.immediate_failures) + " of " +
                           std::to_string(evaluated) + " evaluated samples fail at once (" + bounds +
                           "), more than 1 - R");
  }
}

}  // namespace

WearSample wear_sample_for(const Drive& d, const std::vector<RandomInput>& inputs, const std::vector<double>& x) {
  WearSample s;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string& key = inputs[i].key;
    const double v = x[i];
    if (key == "contact_ratio") {
      s.contact_ratio = v;  // any finite value, 0 included: out of range fails at once
    } else if (key == "wear.coefficient") {
      s.wear_coefficient_scale = v / d.wear.coefficient;
    } else if (key == "load") {
      s.force_scale = v / d.load.force;
    } else if (key == "surface_hardness") {
      s.surface_hardness_scale = v / design_value(d, key, 0.0);
    } else {
      throw InputError({d.source_file, 0, 0}, "reliability.random",
                       "unknown random input '" + key + "' (allowed: contact_ratio, wear_coefficient, load, surface_hardness)");
    }
  }
  return s;
}

WearReliabilityOptions wear_reliability_options(const Drive& drive) {
  WearReliabilityOptions o;
  o.bootstrap_replicates = drive.reliability.bootstrap_replicates;
  o.life_table = drive.reliability.life_table;
  o.life_table_tolerance = drive.reliability.life_table_tolerance;
  return o;
}

WearReliabilityResult run_wear_reliability(const Drive& drive, const WearReliabilityOptions& opt) {
  const SourceMark where{drive.source_file, 0, 0};
  // The caller's own numbers (a Python call, a library user) get the limits
  // the loader gives the file's.
  if (opt.samples) check_count(*opt.samples, kSamplesLimit, "samples");
  if (opt.seed) check_count(*opt.seed, kSeedLimit, "seed");
  check_count(opt.threads, kThreadsLimit, "threads");
  if (!(drive.wear.coefficient > 0)) {
    throw InputError(where, "wear.coefficient", "wear is not configured: give wear.coefficient (and wear.hardness, duty)");
  }
  if (!(drive.duty.rack_meshes_per_year > 0)) {
    throw InputError(where, "duty.rack_meshes_per_year", "a duty is needed for lives in years: give duty.rack_meshes_per_year > 0");
  }
  WearReliabilityResult out;
  const WearModel model(drive);
  auto t0 = std::chrono::steady_clock::now();
  out.nominal = model.life({}, opt.nominal_detail);
  out.nominal_ms = ms_since(t0);

  const ReliabilitySpec& spec = drive.reliability;
  const std::vector<RandomInput>& inputs = spec.inputs;
  if (inputs.empty()) return out;

  // Each input's distribution around this design's own value (absolute
  // inputs as given).
  std::vector<statistics::Distribution> dist;
  for (const RandomInput& in : inputs) {
    dist.push_back(input_distribution(in, design_value(drive, in.key, model.nominal_contact_ratio())));
    out.input_keys.push_back(in.key);
  }
  const std::size_t dim = inputs.size();
  // One input, in the probabilities of its quantiles:
  //  [v0, 1]: the valid samples. A positive input's values <= 0 (probability
  //    v0 = F(0)) are outside its domain and excluded, as in the Monte Carlo
  //    summary: R(t) and the life at R are conditional on a valid sample.
  //  [qa, qb] inside it: the inputs that do not fail at once. A sampled
  //    contact ratio outside [max(1, [eps]), eps_max] fails at once (life 0):
  //    R(t) and the life at R count it as failed at t = 0 (the ship-lift wear-reliability paper's
  //    R = P([eps] <= eps <= eps_max)). qb >= qa even when [eps] > eps_max.
  struct InputBounds {
    double v0 = 0.0, qa = 0.0, qb = 1.0, xa = -kInf, xb = kInf;
    bool positive = false;
  };
  auto bounds_of = [&](std::size_t k) {
    InputBounds b;
    b.positive = input_must_be_positive(inputs[k].key);
    if (b.positive) {
      b.v0 = std::clamp(dist[k].cdf(0.0), 0.0, 1.0);
      b.qa = b.v0;
    } else if (inputs[k].key == "contact_ratio") {
      b.xa = std::max(1.0, drive.wear.min_contact_ratio);
      b.xb = model.max_contact_ratio();
      b.qa = dist[k].cdf(b.xa);
      b.qb = std::max(b.qa, dist[k].cdf(b.xb));
    }
    return b;
  };
  const InputBounds one = dim == 1 ? bounds_of(0) : InputBounds{};
  const double v0 = one.v0, qa = one.qa, qb = one.qb;
  const double valid_probability = 1.0 - v0;
  // The exact results alone are wanted and they exist: no samples.
  const bool skip_samples = opt.exact_only && dim == 1 && valid_probability > 0;
  const std::size_t n = skip_samples ? 0 : static_cast<std::size_t>(opt.samples.value_or(spec.samples));
  const std::uint64_t seed = static_cast<std::uint64_t>(opt.seed.value_or(static_cast<long>(spec.seed)));
  const statistics::PointSet points = skip_samples    ? statistics::PointSet{}
                                      : spec.sobol    ? statistics::sobol_points(n, dim, true, seed)
                                                      : statistics::pseudo_random_points(n, dim, seed);
  out.input_values.assign(n, std::vector<double>(dim));
  // Values outside their input's domain (wear_reliability/sample_domain.hpp): the sample
  // is not evaluated but recorded as a failed evaluation with this reason.
  std::vector<std::string> outside(n);
  out.outside_domain_samples.assign(dim, 0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < dim; ++k) {
      const double x = dist[k].quantile(points.at(i, k));
      out.input_values[i][k] = x;
      if (auto why = outside_input_domain(inputs[k].key, x)) {
        ++out.outside_domain_samples[k];
        if (outside[i].empty()) {
          outside[i] = "sampled " + inputs[k].key + " " + (std::isfinite(x) ? num(x) + " " : "") + *why +
                       ": not a drive, excluded";
        }
      }
    }
  }
  unsigned threads = resolve_threads(opt.threads);
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(n, 1)));
  out.threads_used = threads;
  out.seed_used = seed;
  out.samples_used = static_cast<long>(n);
  out.criteria.assign(n, std::string());

  // Every life below but the nominal one is read for its years, criterion
  // and limiting member only: no snapshots, no profiles.
  constexpr WearModel::Detail kLifeOnly = WearModel::Detail::kLifeOnly;
  auto life_of = [&](double x) { return model.life(wear_sample_for(drive, inputs, {x}), kLifeOnly); };


  // Several inputs of which at most one shapes the life (the contact ratio
  // or the load): the others scale it exactly (life_scaling.hpp), so each
  // sample is the life along that one input, from the table below, times its
  // factor; with none, the nominal life times its factor.
  // Two that shape it (the contact ratio and the load): the two-input table
  // over both, times the others' factor.
  std::size_t shaping = 0, ti = 0, ti1 = 0;  // inputs that shape the life; the tabulated input(s)
  for (std::size_t k = 0; k < dim; ++k) {
    if (input_scales_life(inputs[k].key)) continue;
    if (shaping == 0) ti1 = k;
    ++shaping;
    ti = k;
  }
  const bool two_d = dim > 1 && shaping == 2 && opt.life_table;
  if (two_d) std::swap(ti, ti1);  // ti the first shaping input, ti1 the second
  const bool scaled = dim > 1 && (shaping <= 1 || two_d) && opt.life_table;
  const bool scaled_nominal = scaled && shaping == 0;
  const InputBounds tb = dim == 1 ? one : bounds_of(ti);
  const std::vector<RandomInput> table_inputs{inputs[ti]};
  auto table_life = [&](double x) { return model.life(wear_sample_for(drive, table_inputs, {x}), kLifeOnly); };

  // The life table (one input, or the one shaping input): nodes over the
  // [1e-9, 1 - 1e-9] quantiles of the input (clipped to [xa, xb]), so that it
  // serves the samples and the exact map and does not depend on the samples
  // drawn.
  t0 = std::chrono::steady_clock::now();
  std::optional<statistics::FunctionTable> table;
  std::optional<statistics::FunctionTable2D> table2;
  LifeTableReport& tr = out.table;
  constexpr double kTail = 1e-9;
  // The tabulated range of input k: its [1e-9, 1 - 1e-9] quantiles clipped
  // to the inputs that do not fail at once; empty when nothing is left.
  auto range_of = [&](std::size_t k, const InputBounds& b) -> std::optional<std::pair<double, double>> {
    // A positive input's lowest node stays above 0 (the value at v0 is 0).
    const double ql = std::max(b.qa, kTail) + (b.positive && b.v0 > 0 ? kTail : 0.0);
    const double qh = std::min(b.qb, 1.0 - kTail);
    // Quantiles only strictly inside (0, 1): a scatter wholly outside the
    // bounds (e.g. shifted above eps_max) has qh = 0 or ql = 1.
    if (!(qh > ql)) return std::nullopt;
    const double lo = std::max(b.xa, dist[k].quantile(ql)), hi = std::min(b.xb, dist[k].quantile(qh));
    if (!(hi > lo)) return std::nullopt;
    return std::pair{lo, hi};
  };
  // The one-input table of the life along input ti over [lo, hi].
  auto one_input_table = [&](double lo, double hi) {
    statistics::FunctionTableOptions o;
    o.initial_nodes = opt.life_table_nodes;
    o.rel_tolerance = opt.life_table_tolerance;
    o.max_evaluations = opt.life_table_max_evaluations;
    o.threads = threads;
    return statistics::FunctionTable::build(
        [&](double x) {
          const WearLifeResult r = table_life(x);
          return statistics::TaggedValue{r.life_years, criterion_tag(r)};
        },
        lo, hi, o);
  };
  // Builds a table; a node the model rejects leaves the tables unused, saying why.
  auto build_or_say_why = [&](auto&& build) {
    try {
      build();
    } catch (const InputError& e) {
      tr.not_used = std::string("the model rejected a table node: ") + e.what();
    } catch (const DesignError& e) {
      tr.not_used = std::string("the model failed at a table node: ") + e.what();
    }
  };
  if (scaled) {
    for (std::size_t k = 0; k < dim; ++k)
      if (input_scales_life(inputs[k].key)) tr.scaling_inputs.push_back(inputs[k].key);
  }
  if (!opt.life_table) {
    tr.not_used = "life_table option off";
  } else if (scaled_nominal) {
    tr.not_used = "every random input scales the life: each sample is the nominal life times its factor";
  } else if (two_d) {
    const auto rx = range_of(ti, tb), ry = range_of(ti1, bounds_of(ti1));
    if (!rx || !ry) {
      tr.not_used = "almost every sample fails at once or lies outside an input's domain";
    } else {
      const std::vector<RandomInput> pair_inputs{inputs[ti], inputs[ti1]};
      int extra = 0;
      statistics::FunctionTable2DOptions to;
      to.nodes_y = opt.life_table_2d_nodes;
      to.max_levels = opt.life_table_2d_max_levels;
      to.rel_tolerance = opt.life_table_tolerance;
      to.max_evaluations = opt.life_table_2d_max_evaluations;
      to.threads = threads;
      build_or_say_why([&] {
        // The life's fine structure along the contact ratio (where the
        // discretised profile's contacts change) stays at the same contact
        // ratios as the load changes: the 1-D table along the first input,
        // at the second's design value, places the grid's x nodes there.
        const statistics::FunctionTable along = one_input_table(rx->first, rx->second);
        to.x_nodes = along.x();
        extra = along.evaluations();
        // With the second input's design value among the y nodes (uniform
        // on either side of it), the 1-D table's nodes are that row.
        const double y0 = design_value(drive, inputs[ti1].key, model.nominal_contact_ratio());
        if (y0 > ry->first && y0 < ry->second && to.nodes_y >= 3) {
          const int below = std::clamp(static_cast<int>(std::lround((to.nodes_y - 1) * (y0 - ry->first) /
                                                                    (ry->second - ry->first))),
                                       1, to.nodes_y - 2);
          const int above = to.nodes_y - 1 - below;
          for (int k = 0; k < below; ++k) to.y_nodes.push_back(ry->first + (y0 - ry->first) * k / below);
          to.y_nodes.push_back(y0);
          for (int k = 1; k < above; ++k) to.y_nodes.push_back(y0 + (ry->second - y0) * k / above);
          to.y_nodes.push_back(ry->second);
          to.known_row_y = y0;
          for (std::size_t k = 0; k < along.x().size(); ++k)
            to.known_row.push_back({along.y()[k], along.tags()[k]});
        }
        table2 = statistics::FunctionTable2D::build(
            [&](double x, double y) {
              const WearLifeResult r = model.life(wear_sample_for(drive, pair_inputs, {x, y}), kLifeOnly);
              return statistics::TaggedValue{r.life_years, criterion_tag(r)};
            },
            rx->first, rx->second, ry->first, ry->second, to);
      });
      if (table2) {
        tr.used = true;
        tr.input = inputs[ti].key;
        tr.input2 = inputs[ti1].key;
        tr.x_min = rx->first;
        tr.x_max = rx->second;
        tr.y_min = ry->first;
        tr.y_max = ry->second;
        tr.nodes = static_cast<int>(table2->x().size() * table2->y().size());
        tr.evaluations = table2->evaluations() + extra;
        tr.max_check_error = table2->max_check_error();
        tr.uncovered_fraction = table2->uncovered_fraction();
        tr.cells = table2->cells();
        tr.cells_verified = table2->cells_verified();
        tr.cells_with_switch = table2->cells_with_switch();
      }
    }
  } else {
    const auto range = range_of(ti, tb);
    if (!range) {
      tr.not_used = "almost every sample fails at once or lies outside the input's domain";
    } else {
      const double lo = range->first, hi = range->second;
      build_or_say_why([&] { table = one_input_table(lo, hi); });
      if (table) {
        tr.used = true;
        tr.input = inputs[ti].key;
        tr.x_min = lo;
        tr.x_max = hi;
        tr.nodes = static_cast<int>(table->x().size());
        tr.evaluations = table->evaluations();
        tr.max_check_error = table->max_check_error();
        tr.uncovered_fraction = table->uncovered_fraction();
        tr.breaks = table->breaks();
      }
    }
  }

  std::atomic<std::size_t> interpolated{0};
  auto sample_life = [&](std::size_t i) {
    if (opt.stop && opt.stop()) return std::numeric_limits<double>::quiet_NaN();  // skipped, thrown below
    if (opt.progress) opt.progress->tick();
    if (!outside[i].empty()) throw DesignError("sample_outside_domain", outside[i]);
    double years;
    const double x = out.input_values[i][ti];
    if (table2) {
      const std::optional<statistics::TaggedValue> v = (*table2)(x, out.input_values[i][ti1]);
      if (v) {
        years = v->value * life_scale(wear_sample_for(drive, inputs, out.input_values[i]));
        out.criteria[i] = criterion_of_tag(v->tag);
        interpolated.fetch_add(1, std::memory_order_relaxed);
        return years * kSecondsPerYear;
      }
    }
    if (table && table->covers(x)) {
      const statistics::TaggedValue v = *(*table)(x);
      years = scaled ? v.value * life_scale(wear_sample_for(drive, inputs, out.input_values[i])) : v.value;
      out.criteria[i] = criterion_of_tag(v.tag);  // each index written by one thread only
      interpolated.fetch_add(1, std::memory_order_relaxed);
    } else if (scaled_nominal) {
      years = out.nominal.life_years * life_scale(wear_sample_for(drive, inputs, out.input_values[i]));
      out.criteria[i] = out.nominal.criterion;
      interpolated.fetch_add(1, std::memory_order_relaxed);
    } else {
      const WearLifeResult r = model.life(wear_sample_for(drive, inputs, out.input_values[i]), kLifeOnly);
      out.criteria[i] = r.criterion;
      years = r.life_years;
    }
    return years * kSecondsPerYear;
  };
  // Samples [first, last) on this process's threads.
  auto here = [&](std::size_t first, std::size_t last) {
    SampleLives share;
    share.lives = statistics::evaluate_samples(last - first, threads,
                                               [&](std::size_t j) { return sample_life(first + j); });
    share.criteria.assign(out.criteria.begin() + static_cast<std::ptrdiff_t>(first),
                          out.criteria.begin() + static_cast<std::ptrdiff_t>(last));
    share.interpolated = interpolated.exchange(0);
    return share;
  };
  if (opt.sample_share) {
    // One share of another process's run: the same samples, the same lives.
    const std::size_t first = std::min(opt.sample_share->first, n);
    out.share_lives = here(first, std::clamp(opt.sample_share->second, first, n));
    if (opt.stop && opt.stop()) throw Interrupted("wear life at R: stopped during the Monte Carlo samples");
    return out;
  }
  if (opt.sample_executor && n > 0) {
    SampleLives all = opt.sample_executor(n, here);
    if (all.lives.size() != n || all.criteria.size() != n)
      throw std::runtime_error("wear life at R: the sample executor returned " + std::to_string(all.lives.size()) +
                               " lives for " + std::to_string(n) + " samples");
    out.lives = std::move(all.lives);
    out.criteria = std::move(all.criteria);
    interpolated = all.interpolated;
    out.processes_used = all.processes;
  } else {
    out.lives = statistics::evaluate_samples(n, threads, sample_life);
  }
  if (opt.stop && opt.stop()) throw Interrupted("wear life at R: stopped during the Monte Carlo samples");
  tr.samples_interpolated = table || table2 || scaled_nominal ? interpolated.load() : 0;
  tr.samples_direct = n - tr.samples_interpolated;
  out.samples_ms = ms_since(t0);

  t0 = std::chrono::steady_clock::now();
  statistics::ReliabilityRequest req;
  req.ks_level = spec.ks_level;
  req.reliabilities = spec.reliabilities;
  req.times = spec.times;
  req.bootstrap_replicates = opt.bootstrap_replicates;
  req.seed = seed;
  req.threads = threads;
  req.stop = opt.stop;  // the fits over up to a million lives poll it too
  const std::size_t evaluated = static_cast<std::size_t>(
      std::count_if(out.lives.begin(), out.lives.end(), [](const statistics::SampleResult& s) { return s.ok(); }));
  if (evaluated > 0) {
    out.summary = statistics::summarize_lives(out.lives, req);
  } else {
    // Nothing to summarize (summarize_lives rejects an empty sample): the
    // counts only, no R(t) and no life at R.
    out.summary.samples_total = n;
    out.summary.failed_evaluations = n;
  }

  // Exact results for one monotone input: the life at R is the life at that
  // input's quantile (docs/models/reliability.md).
  const auto t_exact = std::chrono::steady_clock::now();
  if (opt.stop && opt.stop()) throw Interrupted("wear life at R: stopped before the exact quantiles");
  if (dim == 1) {
    const statistics::Distribution& d0 = dist[0];
    auto life_at_q = [&](double q) { return life_of(d0.quantile(q)).life_years; };
    ExactReliability& ex = out.exact;
    ex.available = valid_probability > 0;  // else every sample lies outside the domain
    ex.input = inputs[0].key;
    ex.outside_domain = v0;
    ex.failed_at_start = ex.available ? std::clamp(1.0 - (qb - qa) / valid_probability, 0.0, 1.0) : 0.0;
    if (!ex.available) {
      // no life at R and no R(t) from the exact path
    } else if (qb - qa > 1e-12) {
      bool increasing = true;
      ex.monotone_verified = table && table->monotone(&increasing);
      auto inside = [&](double q) { return std::clamp(q, qa + 1e-12, qb - 1e-12); };
      std::vector<std::pair<double, double>> probed;  // (quantile, life) already computed
      if (ex.monotone_verified) {
        ex.life_increases = increasing;
      } else {
        // The direction from two lives. The first R's two candidate
        // quantiles (where its life at R lies if the life rises, and if it
        // falls) decide it when both lie inside [qa, qb] and at least as far
        // apart as the quartiles (R >= 0.75 or so): one of the two lives is
        // then that life at R, one model life fewer than probing elsewhere.
        // Otherwise the quartiles of [qa, qb].
        double ql = qa + 0.25 * (qb - qa), qh = qa + 0.75 * (qb - qa);
        if (!spec.reliabilities.empty()) {
          const double R0 = spec.reliabilities.front();
          const double q_rise = qb - R0 * valid_probability, q_fall = qa + R0 * valid_probability;
          if (q_rise >= qa && q_fall <= qb && inside(q_fall) - inside(q_rise) >= 0.5 * (qb - qa)) {
            ql = inside(q_rise);
            qh = inside(q_fall);
          }
        }
        const double l1 = life_at_q(ql), l2 = life_at_q(qh);
        ex.model_evaluations += 2;
        ex.life_increases = l2 >= l1;
        probed = {{ql, l1}, {qh, l2}};
      }
      // life at R: P(life > t_R | valid) = R, one model life at the
      // quantile. An R above the probability of starting inside the bounds
      // cannot be reached: life 0.
      for (double R : spec.reliabilities) {
        const double q = ex.life_increases ? qb - R * valid_probability : qa + R * valid_probability;
        if (q < qa || q > qb) {
          ex.life_at_R_years.push_back(0.0);
          continue;
        }
        const double qc = inside(q);
        const auto known = std::find_if(probed.begin(), probed.end(), [&](const auto& p) { return p.first == qc; });
        if (known != probed.end()) {
          ex.life_at_R_years.push_back(known->second);
        } else {
          ex.life_at_R_years.push_back(life_at_q(qc));
          ++ex.model_evaluations;
        }
      }
      // R(t): the probability q* in [qa, qb] where the life crosses t.
      const bool up = ex.life_increases;
      auto R_of_q = [&](double q) { return std::clamp((up ? qb - q : q - qa) / valid_probability, 0.0, 1.0); };
      ex.R_at_times.assign(spec.times.size(), 0.0);
      std::vector<int> evaluations(spec.times.size(), 0);
      if (ex.monotone_verified) {
        // Invert the table, then polish with two model lives (a Newton step
        // on the table's slope, then the secant through both): the root of
        // the model's own life, not of the interpolant.
        const std::vector<double>& xs = table->x();
        const std::vector<double>& ys = table->y();
        parallel_for(spec.times.size(), threads, [&](std::size_t k) {
          const double t = spec.times[k] / kSecondsPerYear;
          // Outside the node values the root lies in the 1e-9 tails (or in
          // the inputs that fail at once): R is the bound's, to 1e-9.
          if (up ? t < ys.front() : t >= ys.front()) {
            ex.R_at_times[k] = R_of_q(qa);
            return;
          }
          if (up ? t >= ys.back() : t < ys.back()) {
            ex.R_at_times[k] = R_of_q(qb);
            return;
          }
          std::size_t j = 0;
          while (j + 2 < ys.size() && (up ? !(t < ys[j + 1]) : !(t >= ys[j + 1]))) ++j;
          const double xl = xs[j], xr = xs[j + 1];
          const double x1 = table->invert_in_interval(j, t);
          const double f1 = life_of(x1).life_years - t;
          double root = x1;
          int used = 1;
          double s = table->slope(x1);
          if (!(s != 0)) s = (ys[j + 1] - ys[j]) / (xr - xl);
          const double x2 = std::clamp(x1 - f1 / s, xl, xr);
          if (f1 != 0 && x2 != x1) {
            const double f2 = life_of(x2).life_years - t;
            ++used;
            root = f2 != f1 ? std::clamp(x2 - f2 * (x2 - x1) / (f2 - f1), xl, xr) : x2;
          }
          evaluations[k] = used;
          ex.R_at_times[k] = R_of_q(d0.cdf(root));
        });
      } else {
        // Bisection on the probability, one model life per step.
        for (std::size_t k = 0; k < spec.times.size(); ++k) {
          if (opt.stop && opt.stop()) throw Interrupted("wear life at R: stopped during the exact R(t)");
          const double t_years = spec.times[k] / kSecondsPerYear;
          double a = qa + 1e-12, b = qb - 1e-12;
          for (int it = 0; it < 60; ++it) {
            const double m = 0.5 * (a + b);
            const bool below = life_at_q(m) <= t_years;  // life(q) <= t
            if (up == below) {
              a = m;
            } else {
              b = m;
            }
          }
          evaluations[k] = 60;
          ex.R_at_times[k] = R_of_q(0.5 * (a + b));
        }
      }
      for (int e : evaluations) ex.model_evaluations += e;
    } else {
      ex.life_at_R_years.assign(spec.reliabilities.size(), 0.0);
      ex.R_at_times.assign(spec.times.size(), 0.0);
    }
  }
  out.exact_ms = ms_since(t_exact);
  out.fit_ms = ms_since(t0);

  if (!skip_samples) failed_sample_warnings(drive, model, out);  // else nothing was sampled: no status

  const double nominal_years = out.nominal.life_years;
  for (std::size_t k = 0; k < out.exact.life_at_R_years.size() && k < spec.reliabilities.size(); ++k) {
    if (auto w = life_at_R_above_nominal(spec.reliabilities[k], out.exact.life_at_R_years[k], nominal_years,
                                         "exact quantile of " + out.exact.input))
      out.warnings.push_back(*w);
  }
  if (out.warnings.empty() && !out.exact.available && n > 1) {  // one warning per R: the exact life when there is one
    for (const statistics::LifeAtReliability& la : out.summary.life) {
      const statistics::LifeInterval& li = la.fit ? *la.fit : la.empirical;
      if (!li.lower_bounded) continue;
      if (auto w = life_at_R_above_nominal(la.reliability, li.lower / kSecondsPerYear, nominal_years,
                                           la.fit ? "lower end of the fitted interval"
                                                  : "lower end of the empirical interval"))
        out.warnings.push_back(*w);
    }
  }
  return out;
}

std::string_view to_string(SamplingStatus status) {
  switch (status) {
    case SamplingStatus::kOk: return "ok";
    case SamplingStatus::kEverySampleFailsAtOnce: return "every_sample_fails_at_once";
    case SamplingStatus::kNoValidSample: return "no_valid_sample";
  }
  return "?";
}

}  // namespace rackopt
