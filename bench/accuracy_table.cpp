// Error versus time for each fidelity knob of the stiffness curve and of the
// wear life / life at reliability R; prints the Markdown tables of docs/accuracy.md.
//
//   ./build/accuracy_table                         stiffness (both bundled problems), then wear
//   ./build/accuracy_table stiffness [problem.yaml ...]
//                                                  stiffness only (default: the bundled
//                                                  rack_railway and ship_lift problems)
//   ./build/accuracy_table problem.yaml ...        the same (stiffness only)
//   ./build/accuracy_table wear [problem.yaml]     wear only (default: problems/ship_lift.yaml;
//                                                  the cases are chosen for that drive, ~1-2 min)
//   ./build/accuracy_table wear_points [--detail]  the wear life against wear.profile_points on
//                                                  every shipped problem with a wear section and
//                                                  a spread of lifting platforms (~20 s; --detail:
//                                                  one row per drive and pressure angle)
//   ./build/accuracy_table wear_order              the three end-of-life criteria with the profile
//                                                  update (max depth, contact ratio, case depth)
//                                                  against profile points and block fraction, with
//                                                  Heun's and the frozen-rate block, against 3840
//                                                  points and block 0.0025 (~1 min)
//   ./build/accuracy_table wear_resolution         wear model resolution (positions per point,
//                                                  compliance-table intervals) on the start
//                                                  designs of the ship-lift and gantry studies
//   ./build/accuracy_table study                   optimizers on studies/rack_railway_sizing.yaml
//                                                  (quality vs budget, forward vs central FD; ~2-3 min)
//   ./build/accuracy_table two_shaping_inputs [problem.yaml]
//                                                  the contact ratio and the load at once: the
//                                                  two-input life table against direct lives
//   ./build/accuracy_table metric_sampling         the metrics' positions per period
//                                                  (metric_options.positions_per_period) on the
//                                                  sizing study's designs and its optimum (~1 min)
//
// Stiffness knobs:
//  * numerics.quadrature_order: fixed Gauss-Legendre points per tooth integral,
//    against GSL adaptive quadrature (QAGS, rel. 1e-12) as the reference;
//  * numerics.positions_per_period: uniform samples per mesh period, against
//    3200 per period as the reference. Besides k_min/k_max/k_mean, the
//    "curve" column is the largest error of the piecewise-linear curve drawn
//    through the samples (what a plot or a downstream interpolation sees),
//    measured at 4 points between every pair of reference samples.
//
// Wear knobs (docs/models/wear.md):
//  * wear.profile_points: points along each flank, against 1920 points;
//  * wear.block_fraction: the adaptive block (update_profile on), against 0.001;
//  * samples and reliability.sampling (pseudo / Sobol) of the life at R, against
//    the exact quantile map of the single random input (result.exact).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gsl/gsl_errno.h>

#include "rackopt/core/error.hpp"
#include "rackopt/wear_reliability/design_scatter.hpp"
#include "rackopt/wear_reliability/sample_domain.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/solvers/solver.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/studyfile/study_loader.hpp"
#include "rackopt/wear/wear_life.hpp"

namespace {

using rackopt::Drive;
using rackopt::MeshStiffnessModel;
using rackopt::StiffnessCurve;

// Median wall time [ms] of building the model and computing the curve.
double time_curve_ms(const Drive& d, StiffnessCurve* out) {
  std::vector<double> t;
  const auto t_start = std::chrono::steady_clock::now();
  for (int rep = 0; rep < 51; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    StiffnessCurve c = MeshStiffnessModel(d).curve();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (rep == 0 && out) *out = std::move(c);
    if (rep >= 4 && std::chrono::steady_clock::now() - t_start > std::chrono::seconds(2)) break;
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

double rel(double a, double ref) { return std::abs(a - ref) / std::abs(ref); }

// Piecewise-linear value of the curve at X (right limit at a jump).
double linear_at(const StiffnessCurve& c, double X) {
  auto it = std::upper_bound(c.samples.begin(), c.samples.end(), X,
                             [](double x, const rackopt::MeshState& s) { return x < s.travel; });
  if (it == c.samples.begin()) return it->stiffness;
  if (it == c.samples.end()) return c.samples.back().stiffness;
  const auto& b = *it;
  const auto& a = *(it - 1);
  if (b.travel == a.travel) return b.stiffness;
  const double w = (X - a.travel) / (b.travel - a.travel);
  return a.stiffness + w * (b.stiffness - a.stiffness);
}

// Largest relative error of the sampled curve against the model itself,
// probed between the reference curve's samples (away from discontinuities).
double curve_error(const StiffnessCurve& c, const StiffnessCurve& ref, const MeshStiffnessModel& model) {
  double worst = 0;
  for (std::size_t i = 0; i + 1 < ref.samples.size(); i += 7) {
    const double a = ref.samples[i].travel, b = ref.samples[i + 1].travel;
    if (b <= a) continue;
    const double X = a + 0.37 * (b - a);
    const double exact = model.stiffness(X);
    // Skip probes next to a breakpoint of c (the linear segment spans a jump).
    worst = std::max(worst, rel(linear_at(c, X), exact));
  }
  return worst;
}

void quadrature_table(const Drive& base) {
  Drive ref_d = base;
  ref_d.numerics.adaptive_quadrature = true;
  StiffnessCurve ref;
  const double t_ref = time_curve_ms(ref_d, &ref);
  std::printf("| quadrature | k_min error | k_mean error | k_max error | largest sample error | ms per curve |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (int n : {2, 3, 4, 6, 8, 12, 16, 24, 32}) {
    Drive d = base;
    d.numerics.quadrature_order = n;
    StiffnessCurve c;
    const double t = time_curve_ms(d, &c);
    double worst = 0;
    for (std::size_t i = 0; i < c.samples.size() && i < ref.samples.size(); ++i) {
      worst = std::max(worst, rel(c.samples[i].stiffness, ref.samples[i].stiffness));
    }
    std::printf("| Gauss-Legendre %d | %.1e | %.1e | %.1e | %.1e | %.3f |\n", n, rel(c.k_min, ref.k_min),
                rel(c.k_mean, ref.k_mean), rel(c.k_max, ref.k_max), worst, t);
  }
  std::printf("| adaptive QAGS (reference) | – | – | – | – | %.3f |\n\n", t_ref);
}

void positions_table(const Drive& base) {
  Drive ref_d = base;
  ref_d.numerics.positions_per_period = 3200;
  StiffnessCurve ref;
  const double t_ref = time_curve_ms(ref_d, &ref);
  const MeshStiffnessModel model(base);
  std::printf("| positions per period | samples | k_min error | k_mean error | k_max error | curve (linear) error | ms per curve |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (int n : {4, 10, 25, 50, 100, 200, 400}) {
    Drive d = base;
    d.numerics.positions_per_period = n;
    StiffnessCurve c;
    const double t = time_curve_ms(d, &c);
    std::printf("| %d | %zu | %.1e | %.1e | %.1e | %.1e | %.3f |\n", n, c.samples.size(), rel(c.k_min, ref.k_min),
                rel(c.k_mean, ref.k_mean), rel(c.k_max, ref.k_max), curve_error(c, ref, model), t);
  }
  std::printf("| 3200 (reference) | %zu | – | – | – | – | %.3f |\n\n", ref.samples.size(), t_ref);
}

// ---------------------------------------------------------------------------
// Wear life and life at R.

using rackopt::WearLifeResult;
using rackopt::WearModel;
using rackopt::WearSample;

struct TimedLife {
  WearLifeResult r;
  double ms = 0;  // median wall time of one life() call (model built once)
};

// Median time of WearModel::life(sample): at least 3 calls, at most 21 or ~1 s.
TimedLife time_life(const WearModel& model, const WearSample& sample) {
  TimedLife out;
  std::vector<double> t;
  const auto t_start = std::chrono::steady_clock::now();
  for (int rep = 0; rep < 21; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    WearLifeResult r = model.life(sample);
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (rep == 0) out.r = std::move(r);
    if (rep >= 2 && std::chrono::steady_clock::now() - t_start > std::chrono::seconds(1)) break;
  }
  std::sort(t.begin(), t.end());
  out.ms = t[t.size() / 2];
  return out;
}

double signed_rel(double a, double ref) { return (a - ref) / std::abs(ref); }

// One deterministic case of the wear tables.
struct WearCase {
  const char* label;
  std::optional<double> contact_ratio;  // WearSample::contact_ratio (empty = nominal)
  bool update_profile;
  double min_contact_ratio;  // < 0: the problem's
};

rackopt::Drive wear_drive(const Drive& base, const WearCase& c, int points, double block_fraction) {
  Drive d = base;
  d.wear.update_profile = c.update_profile;
  if (c.min_contact_ratio >= 0) d.wear.min_contact_ratio = c.min_contact_ratio;
  if (points > 0) d.wear.profile_points = points;
  if (block_fraction > 0) d.wear.block_fraction = block_fraction;
  return d;
}

TimedLife wear_case(const Drive& base, const WearCase& c, int points, double block_fraction) {
  const WearModel model(wear_drive(base, c, points, block_fraction));
  return time_life(model, WearSample{.contact_ratio = c.contact_ratio});
}

constexpr int kReferencePoints = 1920;
constexpr double kReferenceBlock = 0.001;

void profile_points_table(const Drive& base, const std::vector<WearCase>& cases) {
  std::vector<TimedLife> ref;
  for (const WearCase& c : cases) ref.push_back(wear_case(base, c, kReferencePoints, -1));
  std::printf("| profile points |");
  for (const WearCase& c : cases) std::printf(" %s: life error | ms |", c.label);
  std::printf("\n|---|");
  for (std::size_t k = 0; k < cases.size(); ++k) std::printf("---|---|");
  std::printf("\n");
  for (int n : {30, 60, 120, 240, 480, 960}) {
    std::printf("| %d |", n);
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const TimedLife t = wear_case(base, cases[k], n, -1);
      std::printf(" %+.1e | %.3f |", signed_rel(t.r.life_years, ref[k].r.life_years), t.ms);
    }
    std::printf("\n");
  }
  std::printf("| %d (reference) |", kReferencePoints);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::printf(" %.3f y (%s) | %.3f |", ref[k].r.life_years, ref[k].r.criterion.c_str(), ref[k].ms);
  }
  std::printf("\n\n");
}

// The contact-ratio criterion: life, final loaded contact ratio and criterion per N.
void contact_ratio_criterion_table(const Drive& base, const WearCase& c) {
  const TimedLife ref = wear_case(base, c, kReferencePoints, -1);
  std::printf("| profile points | life [y] | life error | final loaded contact ratio | criterion | ms |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (int n : {30, 60, 120, 240, 480, 960}) {
    const TimedLife t = wear_case(base, c, n, -1);
    std::printf("| %d | %.3f | %+.1e | %.4f | %s | %.3f |\n", n, t.r.life_years,
                signed_rel(t.r.life_years, ref.r.life_years), t.r.final_contact_ratio, t.r.criterion.c_str(), t.ms);
  }
  std::printf("| %d (reference) | %.3f | – | %.4f | %s | %.3f |\n\n", kReferencePoints, ref.r.life_years,
              ref.r.final_contact_ratio, ref.r.criterion.c_str(), ref.ms);
}

void block_fraction_table(const Drive& base, const std::vector<WearCase>& cases) {
  std::vector<TimedLife> ref;
  for (const WearCase& c : cases) ref.push_back(wear_case(base, c, -1, kReferenceBlock));
  std::printf("| block fraction |");
  for (const WearCase& c : cases) std::printf(" %s: life error | blocks | ms |", c.label);
  std::printf("\n|---|");
  for (std::size_t k = 0; k < cases.size(); ++k) std::printf("---|---|---|");
  std::printf("\n");
  for (double f : {0.2, 0.1, 0.05, 0.02, 0.01, 0.005}) {
    std::printf("| %g |", f);
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const TimedLife t = wear_case(base, cases[k], -1, f);
      std::printf(" %+.1e | %d | %.3f |", signed_rel(t.r.life_years, ref[k].r.life_years), t.r.blocks, t.ms);
    }
    std::printf("\n");
  }
  std::printf("| %g (reference) |", kReferenceBlock);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::printf(" %.4f y | %d | %.3f |", ref[k].r.life_years, ref[k].r.blocks, ref[k].ms);
  }
  std::printf("\n\n");
}

// Life at R against samples and sampling. Each (sampling, N) row is run for
// several seeds on one thread; errors and half-widths are relative to the
// exact life at R of the single random input.
struct IntervalStats {
  double half_width = 0;  // mean over seeds of (upper - lower) / 2 / exact
  double mean_abs_error = 0, max_abs_error = 0;  // of the estimate
  int covers = 0;         // seeds whose interval contains the exact value
  bool one_sided = false; // some seed's interval unbounded on one side
};

void add_interval(IntervalStats& s, const rackopt::statistics::LifeInterval& li, double exact_s, int n_seeds) {
  if (!li.lower_bounded || !li.upper_bounded) s.one_sided = true;
  s.half_width += 0.5 * (li.upper - li.lower) / exact_s / n_seeds;
  const double e = std::abs(li.estimate - exact_s) / exact_s;
  s.mean_abs_error += e / n_seeds;
  s.max_abs_error = std::max(s.max_abs_error, e);
  if (li.lower <= exact_s && exact_s <= li.upper) ++s.covers;
}

// (samples, seeds) rows: fewer seeds for the largest N keep the section near 2 min.
void life_at_R_table(const Drive& base, const std::vector<std::pair<long, int>>& rows) {
  const auto& Rs = base.reliability.reliabilities;
  std::vector<std::size_t> which;  // the R = 0.9 and 0.99 entries of the problem's list
  for (std::size_t i = 0; i < Rs.size(); ++i)
    if (std::abs(Rs[i] - 0.9) < 1e-12 || std::abs(Rs[i] - 0.99) < 1e-12) which.push_back(i);
  if (which.empty()) {
    std::printf("(the problem asks for neither R = 0.9 nor R = 0.99: no life-at-R table)\n\n");
    return;
  }
  std::vector<double> exact_years;
  {
    const rackopt::WearReliabilityResult r = rackopt::run_wear_reliability(
        base, {.samples = 16, .seed = 1, .threads = 1, .bootstrap_replicates = 20});
    if (!r.exact.available) {
      std::printf("(no exact reference: the problem needs exactly one random input)\n\n");
      return;
    }
    exact_years = r.exact.life_at_R_years;
    std::printf("Exact life at R (quantile map of `%s`):", r.exact.input.c_str());
    for (std::size_t i : which) std::printf(" R = %g: %.4f y;", Rs[i], exact_years[i]);
    std::printf(" probability of failing at once %.4f.\n\n", r.exact.failed_at_start);
  }
  std::printf("| R | sampling | samples | seeds | empirical: CI half-width | mean (max) abs error | CI covers exact "
              "| fit: CI half-width | mean (max) abs error | CI covers exact | ms samples | ms fit + exact |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const bool sobol : {false, true}) {
    for (const auto& [n, n_seeds] : rows) {
      std::vector<IntervalStats> emp(which.size()), fit(which.size());
      double ms_samples = 0, ms_fit = 0;
      for (int seed = 1; seed <= n_seeds; ++seed) {
        Drive d = base;
        d.reliability.sobol = sobol;
        const rackopt::WearReliabilityResult r =
            rackopt::run_wear_reliability(d, {.samples = n, .seed = seed, .threads = 1});
        ms_samples += r.samples_ms / n_seeds;
        ms_fit += r.fit_ms / n_seeds;
        for (std::size_t k = 0; k < which.size(); ++k) {
          const auto& life = r.summary.life[which[k]];
          const double exact_s = exact_years[which[k]] * rackopt::kSecondsPerYear;
          add_interval(emp[k], life.empirical, exact_s, n_seeds);
          if (life.fit) add_interval(fit[k], *life.fit, exact_s, n_seeds);
        }
      }
      for (std::size_t k = 0; k < which.size(); ++k) {
        auto hw = [](const IntervalStats& s) {
          char b[48];
          std::snprintf(b, sizeof b, s.one_sided ? "%.2f %% (one-sided)" : "%.2f %%", 100 * s.half_width);
          return std::string(b);
        };
        std::printf("| %g | %s | %ld | %d | %s | %.2f (%.2f) %% | %d/%d | %s | %.2f (%.2f) %% | %d/%d | %.0f | %.0f |\n",
                    Rs[which[k]], sobol ? "Sobol" : "pseudo", n, n_seeds, hw(emp[k]).c_str(), 100 * emp[k].mean_abs_error,
                    100 * emp[k].max_abs_error, emp[k].covers, n_seeds, hw(fit[k]).c_str(),
                    100 * fit[k].mean_abs_error, 100 * fit[k].max_abs_error, fit[k].covers, n_seeds, ms_samples,
                    ms_fit);
      }
    }
  }
  std::printf("\n");
}

// The contact ratio and the load together (both shape the life): the lives of
// the two-input table (statistics/function_table_2d.hpp) against one model
// life per sample, as in BM_LifeAtRSeveralInputs inputs:3.
void two_shaping_inputs_table(const std::string& file) {
  Drive d = rackopt::load_problem(file);
  rackopt::RandomInput load;
  load.key = "load";
  load.distribution = rackopt::RandomInput::Distribution::kNormal;
  load.cv = 0.05;
  d.reliability.inputs = {d.reliability.inputs.at(0), load};
  rackopt::WearReliabilityOptions opt{.samples = 1000, .seed = 1, .threads = 1};
  const rackopt::WearReliabilityResult table = rackopt::run_wear_reliability(d, opt);
  opt.life_table = false;
  const rackopt::WearReliabilityResult direct = rackopt::run_wear_reliability(d, opt);
  const rackopt::LifeTableReport& t = table.table;
  std::printf("### Two shaping inputs: contact ratio and load (%s)\n\n", file.substr(file.find_last_of('/') + 1).c_str());
  std::printf("Table: %s, %s; used %s; %d model lives (%d initial nodes), %d finest cells: %d verified, %d with a "
              "failure-mode switch; uncovered area %.3g; largest accepted check %.2e; samples %zu from the table, "
              "%zu direct.\n\n",
              t.input.c_str(), t.input2.c_str(), t.used ? "yes" : t.not_used.c_str(), t.evaluations, t.nodes, t.cells,
              t.cells_verified, t.cells_with_switch, t.uncovered_fraction, t.max_check_error, t.samples_interpolated,
              t.samples_direct);
  double worst = 0;
  std::size_t criteria_differ = 0, positive = 0;
  for (std::size_t i = 0; i < table.lives.size(); ++i) {
    if (table.criteria[i] != direct.criteria[i]) ++criteria_differ;
    const double a = table.lives[i].value, b = direct.lives[i].value;
    if (!(b > 0)) continue;
    ++positive;
    worst = std::max(worst, rel(a, b));
  }
  std::printf("| quantity | one model life per sample | table | difference |\n|---|---|---|---|\n");
  std::printf("| largest relative life difference, %zu samples with life > 0 | – | – | %.2e |\n", positive, worst);
  std::printf("| failure criterion of each sample | – | – | %zu of %zu differ |\n", criteria_differ,
              table.lives.size());
  for (std::size_t k = 0; k < table.summary.life.size() && k < direct.summary.life.size(); ++k) {
    const auto& a = table.summary.life[k];
    const auto& b = direct.summary.life[k];
    if (a.fit && b.fit) {
      std::printf("| life at R = %g (fit), years | %.6g | %.6g | %.2e |\n", a.reliability,
                  b.fit->estimate / rackopt::kSecondsPerYear, a.fit->estimate / rackopt::kSecondsPerYear,
                  rel(a.fit->estimate, b.fit->estimate));
    }
    std::printf("| life at R = %g (empirical), years | %.6g | %.6g | %.2e |\n", a.reliability,
                b.empirical.estimate / rackopt::kSecondsPerYear, a.empirical.estimate / rackopt::kSecondsPerYear,
                rel(a.empirical.estimate, b.empirical.estimate));
  }
  std::printf("\nTime (one thread, this run): table %.1f ms for the sample lives, direct %.1f ms.\n\n",
              table.samples_ms, direct.samples_ms);
}

void wear_tables(const std::string& file) {
  const Drive d = rackopt::load_problem(file);
  if (!(d.wear.coefficient > 0)) throw rackopt::InputError({file, 0, 0}, "wear", "the wear tables need a wear section");
  std::printf("### Wear: %s (%s)\n\n", d.name.c_str(), file.substr(file.find_last_of('/') + 1).c_str());
  std::printf("Problem settings: profile_points %d, block_fraction %g, update_profile %s, min_contact_ratio %g.\n"
              "Times: median wall time of one `WearModel::life()` (model built once), one core.\n\n",
              d.wear.profile_points, d.wear.block_fraction, d.wear.update_profile ? "on" : "off",
              d.wear.min_contact_ratio);

  std::printf("Profile points (block_fraction %g; error signed, relative to %d points):\n\n", d.wear.block_fraction,
              kReferencePoints);
  profile_points_table(d, {{"nominal, update off", std::nullopt, false, -1},
                           {"nominal, update on", std::nullopt, true, -1},
                           {"ε 1.44, update off", 1.44, false, -1},
                           {"ε 1.44, update on", 1.44, true, -1}});

  const WearCase cr_case{"ε 1.52, [ε] 1.49, update on", 1.52, true, 1.49};
  std::printf("Contact-ratio criterion governing: sampled ε 1.52, wear.min_contact_ratio 1.49, update on:\n\n");
  contact_ratio_criterion_table(d, cr_case);

  std::printf("Block fraction (update on, profile_points %d; error relative to block_fraction %g):\n\n",
              d.wear.profile_points, kReferenceBlock);
  block_fraction_table(d, {{"nominal", std::nullopt, true, -1}, {"ε 1.44", 1.44, true, -1}, cr_case});

  if (d.reliability.inputs.size() == 1) {
    std::printf("Life at R vs samples and sampling (the problem's settings, seeds 1..n per row, 1 thread, "
                "95 %% intervals, 200 bootstrap replicates; half-widths and errors relative to the exact life at R;\n"
                "times are per run):\n\n");
    life_at_R_table(d, {{100, 5}, {300, 5}, {1000, 5}, {3000, 5}, {10000, 3}});
  }
}

// -------------------------------------------------- wear model resolution
// What the resolution knobs of one wear model (WearOptions: mesh positions
// per profile point, compliance-table intervals, hardness-integral cells) change in a study design's
// wear metrics, against the defaults, and what the design's wear model then
// costs (docs/accuracy.md, "Compliance tables and mesh positions per point").
// The reference is the finest setting of before the cap (WearOptions). The lives are those of the `wear_life` and `wear_life_at_R` metrics on the
// exact quantile path: the nominal life, and the life at the random input's
// quantile for each R of the study (found with the default model; the other
// settings are evaluated at the same input value).

struct ResolutionCase {
  std::string label;
  rackopt::WearOptions options;
};

void wear_resolution_table(const std::string& study_file, const ResolutionCase& fine,
                           const std::vector<ResolutionCase>& cases) {
  const rackopt::study::StudySpec spec = rackopt::studyfile::load_study_file(study_file);
  const rackopt::study::StudyProblem problem(spec);
  const Drive d = problem.drive_at(problem.start_design());
  if (d.reliability.inputs.size() != 1) throw std::runtime_error(study_file + ": one random input expected");
  const rackopt::RandomInput& in = d.reliability.inputs.front();
  const rackopt::WearModel reference(d, fine.options);
  const rackopt::statistics::Distribution dist =
      rackopt::input_distribution(in, rackopt::design_value(d, in.key, reference.nominal_contact_ratio()));
  double qa = 0, qb = 1;
  if (in.key == "contact_ratio") {
    qa = dist.cdf(std::max(1.0, d.wear.min_contact_ratio));
    qb = std::max(qa, dist.cdf(reference.max_contact_ratio()));
  } else if (rackopt::input_must_be_positive(in.key)) {
    qa = dist.cdf(0.0);
  }
  const double valid = 1.0 - (rackopt::input_must_be_positive(in.key) ? qa : 0.0);
  // The life at R is the smaller of the lives at the two candidate
  // quantiles (rising or falling life), as the exact path decides it.
  std::vector<double> inputs_at_R;
  const std::array<double, 2> probes{dist.quantile(qb - 0.9 * valid), dist.quantile(qa + 0.9 * valid)};
  for (double R : {0.5, 0.9, 0.99}) {
    const double x_rise = dist.quantile(qb - R * valid), x_fall = dist.quantile(qa + R * valid);
    const double l_rise = reference.life(rackopt::wear_sample_for(d, {in}, {x_rise})).life_years;
    const double l_fall = reference.life(rackopt::wear_sample_for(d, {in}, {x_fall})).life_years;
    inputs_at_R.push_back(l_rise <= l_fall ? x_rise : x_fall);
  }
  auto lives = [&](const rackopt::WearModel& m) {
    std::vector<double> out{m.life().life_years};
    for (double x : inputs_at_R) out.push_back(m.life(rackopt::wear_sample_for(d, {in}, {x})).life_years);
    return out;
  };
  // What one design of the study spends in the wear model: construction,
  // the nominal life and the two lives of the exact path.
  auto design_ms = [&](const rackopt::WearOptions& o) {
    std::vector<double> t;
    for (int rep = 0; rep < 15; ++rep) {
      const auto t0 = std::chrono::steady_clock::now();
      const rackopt::WearModel m(d, o);
      double sink = m.life().life_years;
      for (double x : probes) sink += m.life(rackopt::wear_sample_for(d, {in}, {x})).life_years;
      t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      if (!std::isfinite(sink)) std::printf("(non-finite life)\n");
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  };
  const std::vector<double> ref = lives(reference);
  std::printf("%s, start design (profile_points %d, update_profile %s; random input %s; R = 0.5 / 0.9 / 0.99 at "
              "%s = %.6g / %.6g / %.6g):\n\n",
              spec.name.c_str(), d.wear.profile_points, d.wear.update_profile ? "on" : "off", in.key.c_str(),
              in.key.c_str(), inputs_at_R[0], inputs_at_R[1], inputs_at_R[2]);
  std::printf("| setting | nominal life error | life at R = 0.5 error | life at R = 0.9 error | life at R = 0.99 error "
              "| largest | ms per design (model + 3 lives) |\n|---|---|---|---|---|---|---|\n");
  std::printf("| %s (reference): %.6f / %.6f / %.6f / %.6f y | – | – | – | – | – | %.3f |\n", fine.label.c_str(),
              ref[0], ref[1], ref[2], ref[3], design_ms(fine.options));
  for (const ResolutionCase& c : cases) {
    const rackopt::WearModel m(d, c.options);
    const std::vector<double> v = lives(m);
    double worst = 0;
    std::printf("| %s |", c.label.c_str());
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double e = (v[k] - ref[k]) / ref[k];
      worst = std::max(worst, std::abs(e));
      std::printf(" %+.1e |", e);
    }
    std::printf(" %.1e | %.3f |\n", worst, design_ms(c.options));
  }
  std::printf("\n");
}

// ------------------------------------------------------- wear_points --
// The wear life against wear.profile_points on every shipped problem with a
// wear section and on a spread of lifting-platform drives (module 6-10 mm,
// 17-25 teeth, pressure angle 17-25 deg in steps of 0.5 deg, through- and
// case-hardened): the signed error against 1920 points, its range over the
// pressure angles, and the time of one life.
struct SpreadDrive {
  const char* label;
  std::vector<std::string> overrides;  // on problems/gantry_axis.yaml
};

std::vector<SpreadDrive> lifting_platforms() {
  const std::string case_h = "{kind: case_hardened, surface: 650 HV, core: 350 HV, case_depth: ";
  auto drive = [&](const char* label, int m, int z, int face, int thrust_kN, bool through) {
    std::vector<std::string> o = {"pinion.module=" + std::to_string(m) + " mm",
                                  "pinion.teeth=" + std::to_string(z),
                                  "pinion.face_width=" + std::to_string(face) + " mm",
                                  "load.thrust=" + std::to_string(thrust_kN) + " kN",
                                  "rack.body_height=" + std::to_string(5 * m) + " mm",
                                  "wear.max_depth=0.3 mm",
                                  "duty.travel_per_year=300 km/yr",
                                  "duty.stroke=4 m"};
    const std::string h = through ? "{kind: constant, surface: 300 HB}"
                                  : case_h + std::to_string(0.15 * m).substr(0, 4) + " mm, limit: 550 HV}";
    o.push_back("wear.pinion_hardness=" + h);
    o.push_back("wear.rack_hardness=" + h);
    return SpreadDrive{label, o};
  };
  return {drive("m6 z17 case", 6, 17, 60, 25, false), drive("m8 z21 through", 8, 21, 80, 40, true),
          drive("m8 z17 case", 8, 17, 80, 60, false), drive("m10 z25 through", 10, 25, 100, 60, true)};
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();
const std::vector<int> kSpreadPoints = {30, 60, 90, 120, 180, 240, 360, 480};

double life_at_points(const Drive& base, int points) {
  Drive d = base;
  d.wear.profile_points = points;
  return WearModel(d).life({}, WearModel::Detail::kLifeOnly).life_cycles;
}

double ms_at_points(const Drive& base, int points) {
  Drive d = base;
  d.wear.profile_points = points;
  return time_life(WearModel(d), {}).ms;
}

void wear_points_tables(bool detail) {
  const std::string dir = std::string(RACKOPT_SOURCE_DIR) + "/problems/";
  std::printf("Shipped problems (each file's settings but the profile points; error against %d points):\n\n",
              kReferencePoints);
  struct Shipped {
    const char* label;
    std::string file;
    std::vector<std::string> overrides;
  };
  const std::vector<Shipped> shipped = {{"gantry_axis", dir + "gantry_axis.yaml", {}},
                                        {"ship_lift (update off)", dir + "ship_lift.yaml", {}},
                                        {"ship_lift, update on", dir + "ship_lift.yaml", {"wear.update_profile=on"}}};
  std::printf("| profile points |");
  for (const Shipped& s : shipped) std::printf(" %s: life error | ms |", s.label);
  std::printf("\n|---|");
  for (std::size_t k = 0; k < shipped.size(); ++k) std::printf("---|---|");
  std::printf("\n");
  std::vector<Drive> sd;
  std::vector<double> sref;
  for (const Shipped& s : shipped) {
    sd.push_back(rackopt::load_problem(s.file, s.overrides));
    sref.push_back(life_at_points(sd.back(), kReferencePoints));
  }
  for (int n : kSpreadPoints) {
    std::printf("| %d |", n);
    for (std::size_t k = 0; k < shipped.size(); ++k)
      std::printf(" %+.1e | %.2f |", signed_rel(life_at_points(sd[k], n), sref[k]), ms_at_points(sd[k], n));
    std::printf("\n");
  }
  std::printf("\nLifting platforms (problems/gantry_axis.yaml with module, teeth, face width, thrust, hardness; "
              "update on; pressure angle 17..25 deg in 0.5 deg steps; error against %d points: smallest .. largest "
              "over the 17 angles; ms at 21 deg):\n\n",
              kReferencePoints);
  const std::vector<SpreadDrive> drives = lifting_platforms();
  std::printf("| profile points |");
  for (const SpreadDrive& s : drives) std::printf(" %s: life error | ms |", s.label);
  std::printf("\n|---|");
  for (std::size_t k = 0; k < drives.size(); ++k) std::printf("---|---|");
  std::printf("\n");
  std::vector<std::vector<double>> lo(drives.size(), std::vector<double>(kSpreadPoints.size(), kInfinity)),
      hi(drives.size(), std::vector<double>(kSpreadPoints.size(), -kInfinity)), ms = lo;
  for (std::size_t k = 0; k < drives.size(); ++k) {
    for (int a2 = 34; a2 <= 50; ++a2) {
      std::vector<std::string> o = drives[k].overrides;
      char pa[64];
      std::snprintf(pa, sizeof pa, "pinion.pressure_angle=%g deg", a2 / 2.0);
      o.push_back(pa);
      const Drive d = rackopt::load_problem(dir + "gantry_axis.yaml", o);
      const double ref = life_at_points(d, kReferencePoints);
      if (detail) std::printf("%s %4.1f deg:", drives[k].label, a2 / 2.0);
      for (std::size_t j = 0; j < kSpreadPoints.size(); ++j) {
        const double e = signed_rel(life_at_points(d, kSpreadPoints[j]), ref);
        lo[k][j] = std::min(lo[k][j], e);
        hi[k][j] = std::max(hi[k][j], e);
        if (a2 == 42) ms[k][j] = ms_at_points(d, kSpreadPoints[j]);
        if (detail) std::printf(" %+.4f", e);
      }
      if (detail) std::printf("\n");
    }
  }
  if (detail) {
    // The smoothness of life(contact ratio) on the ship lift (update off):
    // the largest second difference over 1.40..1.50 in steps of 0.002 (the
    // jitter a coarse grid adds), and the largest difference from 960 points.
    const Drive ship = rackopt::load_problem(dir + "ship_lift.yaml");
    auto lives = [&](int n) {
      Drive d = ship;
      d.wear.profile_points = n;
      const WearModel m(d);
      std::vector<double> life;
      for (int k = 0; k <= 50; ++k)
        life.push_back(m.life({.contact_ratio = 1.40 + 0.002 * k}, WearModel::Detail::kLifeOnly).life_years);
      return life;
    };
    const std::vector<double> ref = lives(960);
    for (int n : {60, 120, 240, 960}) {
      const std::vector<double> life = lives(n);
      double d2 = 0, dref = 0;
      for (int k = 1; k < 50; ++k) d2 = std::max(d2, std::abs(life[k + 1] - 2 * life[k] + life[k - 1]) / life[k]);
      for (int k = 0; k <= 50; ++k) dref = std::max(dref, std::abs(life[k] / ref[k] - 1));
      std::printf("ship lift life(eps), eps 1.40..1.50 step 0.002, %d points: largest |second difference| %.1e, "
                  "largest |life / life(960 points) - 1| %.1e\n", n, d2, dref);
    }
  }
  for (std::size_t j = 0; j < kSpreadPoints.size(); ++j) {
    std::printf("| %d |", kSpreadPoints[j]);
    for (std::size_t k = 0; k < drives.size(); ++k)
      std::printf(" %+.1e .. %+.1e | %.2f |", lo[k][j], hi[k][j], ms[k][j]);
    std::printf("\n");
  }
  std::printf("\n");
}

// ------------------------------------------------------- wear_order --
// The order of convergence of the wear life with the profile update, for each
// end-of-life criterion: the life against wear.profile_points (block 0.0025)
// and against wear.block_fraction (3840 points), Heun's block and the
// frozen-rate block (WearOptions::heun_blocks), signed and relative to 3840
// points and block 0.0025 of the same block rule; then the candidate
// defaults with the time of one life (median, model built once).
struct OrderCase {
  const char* label;
  std::string file;
  std::vector<std::string> overrides;
  std::optional<double> contact_ratio;
};

TimedLife order_life(const OrderCase& c, int points, double block_fraction, bool heun, bool timed = false) {
  Drive d = rackopt::load_problem(c.file, c.overrides);
  d.wear.profile_points = points;
  d.wear.block_fraction = block_fraction;
  const WearModel model(d, {.heun_blocks = heun});
  if (timed) return time_life(model, WearSample{.contact_ratio = c.contact_ratio});
  return {model.life({.contact_ratio = c.contact_ratio}, WearModel::Detail::kLifeOnly), 0.0};
}

void wear_order_tables() {
  const std::string dir = std::string(RACKOPT_SOURCE_DIR) + "/problems/";
  const std::string case_h =
      "wear.hardness={kind: case_hardened, surface: 650 HV, core: 350 HV, case_depth: 0.15 mm, limit: 550 HV}";
  const std::vector<OrderCase> cases = {
      {"ship_lift, update on (max_depth)", dir + "ship_lift.yaml", {"wear.update_profile=on"}, std::nullopt},
      {"ship_lift, ε 1.52, [ε] 1.49 (contact_ratio)", dir + "ship_lift.yaml",
       {"wear.update_profile=on", "wear.min_contact_ratio=1.49"}, 1.52},
      {"gantry_axis, case depth 0.15 mm (case_depth)", dir + "gantry_axis.yaml",
       {case_h, "wear.stop_at_case_depth=on", "wear.max_depth=0.3 mm"}, std::nullopt}};
  constexpr int kRefPoints = 3840;
  constexpr double kRefBlock = 0.0025;
  for (const OrderCase& c : cases) {
    std::printf("%s:\n\n", c.label);
    for (const bool heun : {true, false}) {
      const TimedLife ref = order_life(c, kRefPoints, kRefBlock, heun);
      std::printf("%s block; reference %d points, block %g: %.6g rack passes (%s)\n\n",
                  heun ? "Heun's" : "Frozen-rate", kRefPoints, kRefBlock, ref.r.life_cycles, ref.r.criterion.c_str());
      std::printf("| profile points (block %g) | life error | criterion | block fraction (%d points) | life error | criterion |\n",
                  kRefBlock, kRefPoints);
      std::printf("|---|---|---|---|---|---|\n");
      const int pts[] = {60, 120, 240, 480, 960, 1920};
      const double blk[] = {0.2, 0.1, 0.05, 0.02, 0.01, 0.005};
      for (int k = 0; k < 6; ++k) {
        const TimedLife a = order_life(c, pts[k], kRefBlock, heun);
        const TimedLife b = order_life(c, kRefPoints, blk[k], heun);
        std::printf("| %d | %+.1e | %s | %g | %+.1e | %s |\n", pts[k], signed_rel(a.r.life_cycles, ref.r.life_cycles),
                    a.r.criterion.c_str(), blk[k], signed_rel(b.r.life_cycles, ref.r.life_cycles), b.r.criterion.c_str());
      }
      std::printf("\n");
    }
  }
  std::printf("Settings (error against 3840 points and block 0.0025 with Heun's block; ms: one life):\n\n");
  std::printf("| points | block fraction | block |");
  for (const OrderCase& c : cases) std::printf(" %s: life error | ms |", c.label);
  std::printf("\n|---|---|---|");
  for (std::size_t k = 0; k < cases.size(); ++k) std::printf("---|---|");
  std::printf("\n");
  std::vector<double> ref;
  for (const OrderCase& c : cases) ref.push_back(order_life(c, kRefPoints, kRefBlock, true).r.life_cycles);
  const std::vector<std::tuple<int, double, bool>> settings = {
      {240, 0.02, false}, {120, 0.05, true}, {240, 0.02, true}, {240, 0.05, true}, {240, 0.1, true}, {480, 0.05, true}};
  for (const auto& [n, f, heun] : settings) {
    std::printf("| %d | %g | %s |", n, f, heun ? "Heun" : "frozen rates");
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const TimedLife t = order_life(cases[k], n, f, heun, true);
      std::printf(" %+.1e | %.2f |", signed_rel(t.r.life_cycles, ref[k]), t.ms);
    }
    std::printf("\n");
  }
  std::printf("\n");
}

void wear_resolution_tables() {
  // The reference: every knob at its finest default of before (2 positions
  // per point whatever the points, 512 table intervals).
  ResolutionCase fine{"positions_per_point 2, no cap, 512 intervals, 4096 hardness cells", {}};
  fine.options.positions_cap = 1e9;
  fine.options.compliance_intervals = 512;
  fine.options.hardness_cells = 4096;
  std::vector<ResolutionCase> cases{{"default (positions_cap 240, 256 intervals, 2048 hardness cells)", {}}};
  for (double ppp : {1.5, 1.0, 0.5}) {
    rackopt::WearOptions o = fine.options;
    o.positions_per_point = ppp;
    char label[64];
    std::snprintf(label, sizeof label, "positions_per_point %g", ppp);
    cases.push_back({label, o});
  }
  for (int n : {256, 128, 64, 32, 16}) {
    rackopt::WearOptions o = fine.options;
    o.compliance_intervals = n;
    cases.push_back({"compliance_intervals " + std::to_string(n), o});
  }
  for (int n : {2048, 1024, 512}) {
    rackopt::WearOptions o = fine.options;
    o.hardness_cells = n;
    cases.push_back({"hardness_cells " + std::to_string(n), o});
  }
  for (const char* f : {"ship_lift_wear_tradeoff.yaml", "gantry_sizing.yaml"})
    wear_resolution_table(std::string(RACKOPT_SOURCE_DIR) + "/studies/" + f, fine, cases);
}

// ---------------------------------------------------------------- studies
// Solution quality against evaluations and time on
// studies/rack_railway_sizing.yaml (docs/accuracy.md, "Studies"). Each run
// does what run_study does for an optimize study, without the recorder:
// the start design sets the objective scale, then every module value is
// solved from the start point with solvers::minimize on StudyProblem, and
// the best feasible design over the three is kept. Quality is always the
// EXACT stiffness fluctuation of that design, also for the runs that
// minimize its KS aggregate.

struct StudyConfig {
  std::string name;
  std::string library = "nlopt", algorithm = "LN_COBYLA";
  bool central = false;
  bool ks_objective = false;  // minimize stiffness_fluctuation_ks(500) instead
  int starts = 1;
};

struct StudyOutcome {
  double fluctuation = INFINITY;  // exact, of the best feasible design (inf: none)
  std::vector<double> x;          // that design, SI, spec order
  std::size_t evaluations = 0, probes = 0;
  double seconds = 0;
  std::string status;             // per module value, "/"-separated
};

rackopt::study::StudySpec sizing_spec(bool ks_objective) {
  rackopt::study::StudySpec s =
      rackopt::studyfile::load_study_file(std::string(RACKOPT_SOURCE_DIR) + "/studies/rack_railway_sizing.yaml");
  if (ks_objective) {
    s.objectives[0].metric =
        rackopt::metrics::resolve_request(rackopt::metrics::parse_metric_request("stiffness_fluctuation_ks"));
    s.objectives[0].label = rackopt::metrics::to_string(s.objectives[0].metric);
    // Keep the exact value in every evaluation (read back below).
    s.report_metrics.push_back(rackopt::metrics::parse_metric_request("stiffness_fluctuation"));
  }
  return s;
}

double exact_fluctuation(const rackopt::study::StudyProblem& p, const rackopt::study::DesignEvaluation& d) {
  const auto& labels = p.metric_labels();
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels[i] == "stiffness_fluctuation") return d.metric_ok[i] ? d.metric_values[i] : INFINITY;
  throw std::runtime_error("no stiffness_fluctuation in the study's metrics");
}

StudyOutcome solve_sizing(const StudyConfig& cfg, std::size_t budget, double xtol_rel = -1) {
  using rackopt::study::StudyProblem;
  const rackopt::study::StudySpec spec = sizing_spec(cfg.ks_objective);
  rackopt::solvers::SolverSettings s = spec.solver;
  s.library = cfg.library;
  s.algorithm = cfg.algorithm;
  s.central_differences = cfg.central;
  s.max_evaluations = budget;
  s.starts = cfg.starts;
  if (xtol_rel >= 0) s.xtol_rel = xtol_rel;
  StudyOutcome out;
  const auto t0 = std::chrono::steady_clock::now();
  StudyProblem base(spec);
  base.set_objective_scales_from(base.evaluate_design(base.start_design()));
  out.evaluations = 1;
  std::vector<std::pair<StudyProblem, rackopt::solvers::SolverResult>> runs;
  for (std::size_t c = 0; c < base.num_combinations(); ++c) {
    StudyProblem q = base.for_combination(c);
    rackopt::solvers::SolverResult r = rackopt::solvers::minimize(q, q.start_unit(), s);
    out.evaluations += r.evaluations;
    out.probes += r.gradient_evaluations;
    out.status += (c ? "/" : "") + std::string(to_string(r.status));
    runs.emplace_back(std::move(q), std::move(r));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Outside the timing: the exact fluctuation of each module's best feasible
  // design (deterministic, so the same value the run saw).
  for (const auto& [q, r] : runs) {
    if (!r.feasible) continue;
    const std::vector<double> x = q.to_design(r.x);
    const double f = exact_fluctuation(q, q.evaluate_design(x));
    if (f < out.fluctuation) {
      out.fluctuation = f;
      out.x = x;
    }
  }
  return out;
}

std::string design_text(const std::vector<double>& x) {
  if (x.size() != 4) return "–";
  char buf[160];
  std::snprintf(buf, sizeof buf, "%.3f deg, %.0f mm, %.4f m, %.3f mm", x[0] * 180 / std::numbers::pi, x[1] * 1e3, x[2],
                x[3] * 1e3);
  return buf;
}

std::string gap_text(double f, double ref) {
  if (!std::isfinite(f)) return "no feasible design";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2e", (f - ref) / ref);
  return buf;
}

void study_tables() {
  const std::vector<StudyConfig> configs = {
      {"LN_COBYLA, 3 starts (shipped)", "nlopt", "LN_COBYLA", false, false, 3},
      {"LN_COBYLA, one start", "nlopt", "LN_COBYLA", false, false},
      {"LD_SLSQP, forward FD", "nlopt", "LD_SLSQP", false, false},
      {"LD_SLSQP, central FD", "nlopt", "LD_SLSQP", true, false},
      {"Ipopt, central FD", "ipopt", "", true, false},
      {"LD_SLSQP, forward FD, KS objective", "nlopt", "LD_SLSQP", false, true},
      {"Ipopt, central FD, KS objective", "ipopt", "", true, true},
  };

  // Reference: the best exact fluctuation of long runs of every configuration
  // (4000 evaluations per module value, xtol_rel 1e-10), plus a multistart
  // COBYLA and a global stochastic search against a local optimum that every
  // local solver shares.
  double ref = INFINITY;
  std::string ref_by;
  std::vector<double> ref_x;
  std::printf("Long runs (4000 evaluations per module value, xtol_rel 1e-10); the best is the reference:\n\n");
  std::printf("| configuration | fluctuation | design (angle, module, span, clearance) | evaluations | s | status |\n");
  std::printf("|---|---|---|---|---|---|\n");
  std::vector<StudyConfig> long_runs = configs;
  long_runs.push_back({"LN_COBYLA, 10 starts (x0 + 9 LHS points)", "nlopt", "LN_COBYLA", false, false, 10});
  long_runs.push_back({"GN_ISRES (global, stochastic, seed 1)", "nlopt", "GN_ISRES", false, false});
  for (const StudyConfig& c : long_runs) {
    const StudyOutcome o = solve_sizing(c, 4000, 1e-10);
    std::printf("| %s | %.6f | %s | %zu | %.2f | %s |\n", c.name.c_str(), o.fluctuation, design_text(o.x).c_str(),
                o.evaluations, o.seconds, o.status.c_str());
    std::fflush(stdout);
    if (o.fluctuation < ref) {
      ref = o.fluctuation;
      ref_by = c.name;
      ref_x = o.x;
    }
  }
  std::printf("\nReference optimum: fluctuation %.6f (%s) at %s.\n\n", ref, ref_by.c_str(),
              design_text(ref_x).c_str());

  std::printf("Budget per module value (the study's max_evaluations; 3 module values, +1 start design), "
              "the file's tolerances (xtol_rel 1e-5); gap = (f - f_ref) / f_ref of the exact fluctuation:\n\n");
  std::printf("| configuration | budget | evaluations (FD probes) | best feasible fluctuation | gap | s | status |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const StudyConfig& c : configs) {
    for (std::size_t budget : {25, 50, 100, 200, 400, 800}) {
      const StudyOutcome o = solve_sizing(c, budget);
      std::printf("| %s | %zu | %zu (%zu) | %.6f | %s | %.3f | %s |\n", c.name.c_str(), budget, o.evaluations,
                  o.probes, o.fluctuation, gap_text(o.fluctuation, ref).c_str(), o.seconds, o.status.c_str());
      std::fflush(stdout);
    }
  }

  std::printf("\nFinite differences, forward vs central (budget 2000 per module value, the file's tolerances):\n\n");
  std::printf("| solver | objective | differences | fluctuation | gap | evaluations (FD probes) | s | status |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const bool ks : {false, true}) {
    for (const char* library : {"nlopt", "ipopt"}) {
      for (const bool central : {false, true}) {
        const StudyConfig c{"", library, std::string(library) == "nlopt" ? "LD_SLSQP" : "", central, ks};
        const StudyOutcome o = solve_sizing(c, 2000);
        std::printf("| %s | %s | %s | %.6f | %s | %zu (%zu) | %.3f | %s |\n",
                    std::string(library) == "nlopt" ? "LD_SLSQP" : "Ipopt",
                    ks ? "stiffness_fluctuation_ks(500)" : "stiffness_fluctuation", central ? "central" : "forward",
                    o.fluctuation, gap_text(o.fluctuation, ref).c_str(), o.evaluations, o.probes, o.seconds,
                    o.status.c_str());
        std::fflush(stdout);
      }
    }
  }
  std::printf("\n");
}

// The sizing study's metrics at its designs with the metrics' curve sampled
// at P positions per period, against P = 800; and the shipped optimizer's
// result at each P (its optimum's fluctuation re-evaluated at P = 800).
void metric_sampling_tables() {
  using rackopt::study::StudyProblem;
  constexpr int kReference = 800;
  const std::vector<int> sampling = {8, 12, 16, 24, 32, 50, 100, 200};
  auto spec_at = [](int positions) {
    rackopt::study::StudySpec s = sizing_spec(false);
    s.metric_options.positions_per_period = positions;
    // The fluctuation's parts, each on its own.
    s.report_metrics.push_back(rackopt::metrics::parse_metric_request("max_stiffness"));
    return s;
  };
  // Designs spread over the box of every module value (R_d sequence, as
  // bench/study_bench.cpp's Points).
  const StudyProblem ref_base(spec_at(kReference));
  const std::size_t dim = ref_base.dimension();
  double phi = 2;
  for (int k = 0; k < 50; ++k) phi = std::pow(1 + phi, 1.0 / static_cast<double>(dim + 1));
  std::vector<std::pair<std::size_t, std::vector<double>>> designs;  // (combination, SI design)
  std::vector<double> u(dim, 0.5);
  for (int i = 0; i < 60; ++i) {
    for (std::size_t j = 0; j < dim; ++j)
      u[j] = std::fmod(u[j] + std::fmod(std::pow(1 / phi, static_cast<double>(j + 1)), 1.0), 1.0);
    const std::size_t c = static_cast<std::size_t>(i) % ref_base.num_combinations();
    designs.emplace_back(c, ref_base.for_combination(c).to_design(u));
  }
  const auto& labels = ref_base.metric_labels();
  std::vector<rackopt::study::DesignEvaluation> ref;
  for (const auto& [c, x] : designs) ref.push_back(ref_base.for_combination(c).evaluate_design(x));

  std::printf("Metrics of %zu designs of studies/rack_railway_sizing.yaml (spread over its box, every module "
              "value) with the metrics' curve at P positions per period, against P = %d: the largest relative "
              "error over the designs the reference computes; ms per design (every metric of the study, one "
              "thread, median of 3 passes):\n\n",
              designs.size(), kReference);
  std::printf("| P |");
  std::vector<std::size_t> shown;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    shown.push_back(k);
    std::printf(" %s |", labels[k].c_str());
  }
  std::printf(" ms per design |\n|---|");
  for (std::size_t k = 0; k < shown.size(); ++k) std::printf("---|");
  std::printf("---|\n");
  for (const int P : sampling) {
    const StudyProblem base(spec_at(P));
    std::vector<StudyProblem> views;
    for (std::size_t c = 0; c < base.num_combinations(); ++c) views.push_back(base.for_combination(c));
    std::vector<double> worst(labels.size(), 0.0);
    std::vector<double> passes;
    for (int pass = 0; pass < 3; ++pass) {
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < designs.size(); ++i) {
        const auto e = views[designs[i].first].evaluate_design(designs[i].second);
        for (std::size_t k = 0; k < labels.size(); ++k) {
          if (!ref[i].metric_ok[k]) continue;
          if (!e.metric_ok[k]) {
            worst[k] = INFINITY;
            continue;
          }
          const double r = ref[i].metric_values[k];
          worst[k] = std::max(worst[k], std::abs(e.metric_values[k] - r) / std::max(std::abs(r), 1e-300));
        }
      }
      passes.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() /
                       static_cast<double>(designs.size()));
    }
    std::sort(passes.begin(), passes.end());
    std::printf("| %d |", P);
    for (std::size_t k : shown) std::printf(" %.1e |", worst[k]);
    std::printf(" %.3f |\n", passes[1]);
    std::fflush(stdout);
  }

  std::printf("\nThe shipped optimizer (COBYLA, 3 starts, the file's budget) with the metrics at P positions per "
              "period; its optimum's fluctuation again at P = %d:\n\n", kReference);
  std::printf("| P | optimum (angle, module, span, clearance) | fluctuation at P | at P = %d | evaluations | s |\n",
              kReference);
  std::printf("|---|---|---|---|---|---|\n");
  for (const int P : {12, 24, 50, 100}) {
    const rackopt::study::StudySpec spec = spec_at(P);
    StudyProblem base(spec);
    const auto t0 = std::chrono::steady_clock::now();
    base.set_objective_scales_from(base.evaluate_design(base.start_design()));
    std::size_t evaluations = 1;
    double best = INFINITY;
    std::vector<double> best_x;
    std::size_t best_c = 0;
    for (std::size_t c = 0; c < base.num_combinations(); ++c) {
      StudyProblem q = base.for_combination(c);
      const rackopt::solvers::SolverResult r = rackopt::solvers::minimize(q, q.start_unit(), spec.solver);
      evaluations += r.evaluations;
      if (!r.feasible) continue;
      const std::vector<double> x = q.to_design(r.x);
      const double f = exact_fluctuation(q, q.evaluate_design(x));
      if (f < best) {
        best = f;
        best_x = x;
        best_c = c;
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double at_ref = best_x.empty() ? INFINITY
                                         : exact_fluctuation(ref_base, ref_base.for_combination(best_c).evaluate_design(best_x));
    std::printf("| %d | %s | %.6f | %.6f | %zu | %.2f |\n", P, design_text(best_x).c_str(), best, at_ref, evaluations,
                seconds);
    std::fflush(stdout);
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();
  // First argument "stiffness" or "wear" selects one part; without it, files
  // given are stiffness problems, and no arguments at all runs both parts.
  std::vector<std::string> args(argv + 1, argv + argc);
  bool run_stiffness = true, run_wear = args.empty();
  if (!args.empty() && args[0] == "wear_resolution") {
    try {
      wear_resolution_tables();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accuracy_table: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  if (!args.empty() && args[0] == "wear_order") {
    try {
      wear_order_tables();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accuracy_table: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  if (!args.empty() && args[0] == "wear_points") {
    try {
      wear_points_tables(args.size() > 1 && args[1] == "--detail");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accuracy_table: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  if (!args.empty() && args[0] == "study") {
    if (args.size() > 1) {
      std::fprintf(stderr, "usage: accuracy_table study\n");
      return 2;
    }
    try {
      study_tables();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accuracy_table: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  if (!args.empty() && args[0] == "two_shaping_inputs") {
    try {
      two_shaping_inputs_table(args.size() > 1 ? args[1] : std::string(RACKOPT_SOURCE_DIR) + "/problems/ship_lift.yaml");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accuracy_table: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  if (!args.empty() && args[0] == "metric_sampling") {
    try {
      metric_sampling_tables();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accuracy_table: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  if (!args.empty() && (args[0] == "stiffness" || args[0] == "wear")) {
    run_stiffness = args[0] == "stiffness";
    run_wear = !run_stiffness;
    args.erase(args.begin());
  }
  try {
    if (run_stiffness) {
      std::vector<std::string> files = args;
      if (files.empty()) {
        files = {std::string(RACKOPT_SOURCE_DIR) + "/problems/rack_railway.yaml",
                 std::string(RACKOPT_SOURCE_DIR) + "/problems/ship_lift.yaml"};
      }
      for (const std::string& f : files) {
        const Drive d = rackopt::load_problem(f);
        std::printf("### %s (%s)\n\n", d.name.c_str(), f.substr(f.find_last_of('/') + 1).c_str());
        std::printf("Quadrature order (positions per period %d):\n\n", d.numerics.positions_per_period);
        quadrature_table(d);
        std::printf("Positions per mesh period (quadrature order %d):\n\n", d.numerics.quadrature_order);
        positions_table(d);
      }
    }
    if (run_wear) {
      if (args.size() > 1) {
        std::fprintf(stderr, "usage: accuracy_table wear [problem.yaml]\n");
        return 2;
      }
      wear_tables(args.empty() ? std::string(RACKOPT_SOURCE_DIR) + "/problems/ship_lift.yaml" : args[0]);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accuracy_table: %s\n", e.what());
    return 1;
  }
  return 0;
}
