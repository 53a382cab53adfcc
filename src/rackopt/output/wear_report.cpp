#include "rackopt/output/wear_report.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "rackopt/output/json_writer.hpp"
#include "rackopt/output/plot.hpp"

namespace rackopt {
namespace {

std::string g(double v, const char* f = "%.9g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

const char* member_name(Member m) { return m == Member::kPinion ? "pinion" : "rack"; }

const char* status_name(statistics::SampleResult::Status s) {
  switch (s) {
    case statistics::SampleResult::Status::kOk: return "ok";
    case statistics::SampleResult::Status::kDesignError: return "design_error";
    case statistics::SampleResult::Status::kInputError: return "input_error";
    case statistics::SampleResult::Status::kFailed: return "failed";
  }
  return "failed";
}

std::vector<double> ok_lives_years(const WearReliabilityResult& r) {
  std::vector<double> v;
  for (const auto& s : r.lives) {
    if (s.ok()) v.push_back(s.value / kSecondsPerYear);
  }
  return v;
}

const statistics::Distribution* chosen_distribution(const WearReliabilityResult& r) {
  const statistics::CandidateFit* c = r.summary.chosen_fit();
  return (c && c->fit) ? &c->fit->distribution : nullptr;
}

void append_profile(std::string& out, const char* member, const WearSnapshot& snap, const WearProfile& p) {
  for (std::size_t i = 0; i < p.s.size(); ++i) {
    out += std::string(member) + "," + g(snap.fraction) + "," + g(snap.years) + "," + g(snap.contact_ratio) + "," +
           g(p.s[i]) + "," + g(p.position[i]) + "," + g(p.radius_or_height[i]) + "," + g(p.depth[i]) + "\n";
  }
}

}  // namespace

std::string wear_profile_csv(const WearLifeResult& n) {
  std::string out = "member,fraction_of_life,years,contact_ratio,s_m,position_m,radius_or_height_m,depth_m\n";
  for (const WearSnapshot& s : n.snapshots) {
    append_profile(out, "pinion", s, s.pinion);
    append_profile(out, "rack", s, s.rack);
  }
  return out;
}

std::string life_samples_csv(const WearReliabilityResult& r) {
  std::string out = "sample";
  for (const std::string& k : r.input_keys) out += "," + k;
  out += ",life_years,status,criterion,message\n";
  for (std::size_t i = 0; i < r.lives.size(); ++i) {
    out += std::to_string(i);
    // A value outside its input's domain that is not even finite (an
    // overflowing quantile) is left empty: the status and message say why.
    for (double x : r.input_values[i]) out += "," + (std::isfinite(x) ? g(x) : std::string(""));
    const auto& s = r.lives[i];
    std::string msg = s.message;
    std::replace(msg.begin(), msg.end(), ',', ';');
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    out += "," + (s.ok() ? g(s.value / kSecondsPerYear) : std::string("")) + "," + status_name(s.status) + "," +
           r.criteria[i] + "," + msg + "\n";
  }
  return out;
}

std::string reliability_csv(const Drive& drive, const WearReliabilityResult& r) {
  std::vector<double> lives = ok_lives_years(r);
  std::vector<double> grid;
  if (!lives.empty()) {
    const auto [mn, mx] = std::minmax_element(lives.begin(), lives.end());
    const double lo = std::max(0.0, *mn - 0.2 * (*mx - *mn)), hi = *mx + 0.2 * (*mx - *mn) + 1e-9;
    for (int i = 0; i <= 200; ++i) grid.push_back(lo + (hi - lo) * i / 200.0);
  }
  for (double t : drive.reliability.times) grid.push_back(t / kSecondsPerYear);
  std::sort(grid.begin(), grid.end());
  const statistics::Distribution* d = chosen_distribution(r);
  std::vector<double> lives_s;
  for (const auto& s : r.lives) {
    if (s.ok()) lives_s.push_back(s.value);
  }
  // The fit describes the positive lives; samples that failed at once
  // (life 0) scale it, as in the summary: R(t) = (1 - p0) S(t).
  const double p0 = r.summary.samples_total > r.summary.failed_evaluations
                        ? static_cast<double>(r.summary.immediate_failures) /
                              static_cast<double>(r.summary.samples_total - r.summary.failed_evaluations)
                        : 0.0;
  std::string out = "t_years,R_fit,R_empirical\n";
  for (double t : grid) {
    const double ts = t * kSecondsPerYear;
    out += g(t) + "," + (d ? g((1.0 - p0) * statistics::reliability_at(*d, ts)) : std::string("")) + "," +
           (lives_s.empty() ? std::string("") : g(statistics::empirical_reliability(lives_s, ts))) + "\n";
  }
  return out;
}

std::string life_histogram_csv(const WearReliabilityResult& r, int bins) {
  std::vector<double> lives = ok_lives_years(r);
  std::string out = "bin_left_years,bin_right_years,count,fit_count\n";
  if (lives.empty()) return out;
  const auto [mn, mx] = std::minmax_element(lives.begin(), lives.end());
  const double lo = *mn, hi = *mx > *mn ? *mx : *mn + 1.0;
  const double w = (hi - lo) / bins;
  std::vector<long> count(static_cast<std::size_t>(bins), 0);
  for (double v : lives) {
    const int b = std::min(bins - 1, static_cast<int>((v - lo) / w));
    ++count[static_cast<std::size_t>(b)];
  }
  const statistics::Distribution* d = chosen_distribution(r);
  const double n = static_cast<double>(lives.size());
  for (int b = 0; b < bins; ++b) {
    const double a = lo + b * w, c = a + w;
    double fit = 0;
    if (d) fit = n * (d->cdf(c * kSecondsPerYear) - d->cdf(a * kSecondsPerYear));
    out += g(a) + "," + g(c) + "," + std::to_string(count[static_cast<std::size_t>(b)]) + "," +
           (d ? g(fit) : std::string("")) + "\n";
  }
  return out;
}

static std::string gp_header(const std::string& title, const std::string& png) {
  return "set datafile separator ','\n" + gnuplot_terminal(png + ".tmp", 1200, 750) + "set title " +
         gnuplot_quote(title) + "\nset grid\nset key outside right\n";
}

std::string wear_profile_gnuplot(const std::string& title, const WearLifeResult& nominal) {
  // The CSV's value (its %.9g digits parsed) in mm, as gnuplot computed it
  // from wear_profile.csv, written to parse back to that double.
  const auto mm = [](double v) {
    const std::string digits = g(v);
    double parsed = 0;
    std::from_chars(digits.data(), digits.data() + digits.size(), parsed);
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, parsed * 1e3);
    return std::string(buf, r.ptr);
  };
  const double fractions[] = {0.25, 0.5, 0.75, 1.0};
  std::ostringstream o;
  o << "# Generated by rackopt: wear along the profiles (wear_profile.csv, docs/output.md), its points below in mm\n";
  for (const char* member : {"rack", "pinion"}) {
    for (int k = 0; k < 4; ++k) {
      o << "$rackopt_" << member << "_" << k << " << EOD\n";
      bool first = true;
      for (const WearSnapshot& snap : nominal.snapshots) {
        const double fraction = std::strtod(g(snap.fraction).c_str(), nullptr);
        if (!(std::abs(fraction - fractions[k]) < 1e-6)) continue;
        if (!first) o << "\n";  // another snapshot at this fraction: a line of its own
        first = false;
        const WearProfile& p = std::string(member) == "rack" ? snap.rack : snap.pinion;
        for (std::size_t i = 0; i < p.s.size(); ++i) o << mm(p.position[i]) << "," << mm(p.depth[i]) << "\n";
      }
      o << "EOD\n";
    }
  }
  o << gp_header(title + ": wear along the flanks", "wear_profile.png") << "set multiplot layout 2,1\n";
  const auto panel = [&](const char* member) {
    o << "plot ";
    for (int k = 0; k < 4; ++k) {
      o << (k == 0 ? "" : ", \\\n     ") << "$rackopt_" << member << "_" << k << " using 1:2 with lines lw 2 title '"
        << member << ", " << static_cast<int>(fractions[k] * 100) << " % of life'";
    }
    o << "\n";
  };
  o << "set xlabel 'rack flank: distance from the point that meets the pinion tip [mm]'\n"
    << "set ylabel 'wear depth [mm]'\n";
  panel("rack");
  o << "set xlabel 'pinion flank: distance from the start of the active profile [mm]'\n";
  panel("pinion");
  o << "unset multiplot\n";
  return o.str();
}

std::string life_histogram_gnuplot(const std::string& title) {
  std::ostringstream o;
  o << "# Generated by rackopt: life histogram with the fitted density (life_histogram.csv)\n"
    << gp_header(title + ": wear life samples", "life_histogram.png")
    << "set xlabel 'wear life [years]'\nset ylabel 'samples per bin'\nset style fill solid 0.4\n"
    << "plot 'life_histogram.csv' using (($1+$2)/2):3:($2-$1) with boxes title 'Monte Carlo', \\\n"
    << "     '' using (($1+$2)/2):4 with linespoints lw 2 title 'fitted distribution'\n";
  return o.str();
}

std::string reliability_gnuplot(const std::string& title) {
  std::ostringstream o;
  o << "# Generated by rackopt: reliability R(t) (reliability.csv)\n"
    << gp_header(title + ": reliability", "reliability.png")
    << "set xlabel 't [years]'\nset ylabel 'R(t)'\nset yrange [0:1.02]\n"
    << "plot 'reliability.csv' using 1:2 with lines lw 2 title 'fit', "
       "'' using 1:3 with steps title 'empirical'\n";
  return o.str();
}

std::string wear_summary(const Drive& d, const WearReliabilityResult& r) {
  std::ostringstream o;
  const WearLifeResult& n = r.nominal;
  o << "  wear life (nominal drive): " << g(n.life_years, "%.3f") << " years = " << g(n.life_cycles, "%.4g")
    << " rack passes, ended by " << n.criterion << " (" << n.reason << ")\n";
  o << "    deepest wear " << g(n.max_depth * 1e3, "%.4f") << " mm on the " << member_name(n.max_depth_member)
    << " at s = " << g(n.max_depth_s * 1e3, "%.2f") << " mm; contact ratio " << g(n.initial_contact_ratio, "%.4f")
    << " -> " << g(n.final_contact_ratio, "%.4f") << "\n";
  if (!r.lives.empty()) {
    const auto& s = r.summary;
    o << "  Monte Carlo: " << r.lives.size() << " samples (" << (d.reliability.sobol ? "Sobol" : "pseudo-random")
      << ", seed " << r.seed_used << ", " << r.threads_used << " threads"
      << (r.processes_used > 1 ? " on each of " + std::to_string(r.processes_used) + " MPI ranks" : std::string())
      << "), " << s.failed_evaluations
      << " failed evaluations, " << s.immediate_failures << " immediate failures\n";
    if (const statistics::CandidateFit* c = s.chosen_fit()) {
      o << "    life distribution: " << c->fit->distribution.describe() << " (s), KS D = "
        << g(c->ks.statistic, "%.4f") << " vs critical " << g(c->ks.critical_value, "%.4f") << " at "
        << d.reliability.ks_level << ": " << (c->ks.accepted ? "accepted" : "REJECTED") << "\n";
    }
    for (const auto& l : s.life) {
      o << "    life at R = " << l.reliability << ": ";
      if (l.fit) {
        o << g(l.fit->estimate / kSecondsPerYear, "%.2f") << " y (fit, " << g(l.fit->confidence * 100, "%.0f")
          << "% CI " << g(l.fit->lower / kSecondsPerYear, "%.2f") << ".." << g(l.fit->upper / kSecondsPerYear, "%.2f")
          << "), ";
      }
      o << g(l.empirical.estimate / kSecondsPerYear, "%.2f") << " y (empirical)\n";
    }
    for (const auto& t : s.reliability) {
      o << "    R(" << g(t.t / kSecondsPerYear, "%.1f") << " y) = ";
      if (t.fit) o << g(*t.fit, "%.4f") << " (fit), ";
      o << g(t.empirical, "%.4f") << " (empirical)\n";
    }
    if (s.life.empty() && !d.reliability.reliabilities.empty()) {
      o << "    life at R: none (no sample could be evaluated)\n";
    }
    if (r.exact.available) {
      o << "    exact (one monotone random input, " << r.exact.input << "):";
      for (std::size_t i = 0; i < r.exact.life_at_R_years.size(); ++i) {
        o << " life at R=" << d.reliability.reliabilities[i] << ": " << g(r.exact.life_at_R_years[i], "%.2f") << " y;";
      }
      o << "\n";
    }
    for (const std::string& w : s.warnings) o << "  warning: " << w << "\n";
  }
  for (const std::string& w : n.warnings) o << "  warning: " << w << "\n";
  for (const std::string& w : r.warnings) o << "  warning: " << w << "\n";
  return o.str();
}

std::string wear_json(const Drive& d, const WearReliabilityResult& r, const WearFiles& f, double total_ms) {
  JsonWriter j;
  const WearLifeResult& n = r.nominal;
  j.begin_object();
  j.key("problem").value(d.source_file);
  j.key("life_cycles").value(n.life_cycles);
  j.key("life_pinion_cycles").value(n.life_pinion_cycles);
  j.key("life_years").value(n.life_years);
  j.key("criterion").value(n.criterion);
  j.key("reason").value(n.reason);
  j.key("max_depth").value(n.max_depth);
  j.key("max_depth_member").value(member_name(n.max_depth_member));
  j.key("max_depth_s").value(n.max_depth_s);
  j.key("contact_ratio_initial").value(n.initial_contact_ratio);
  j.key("contact_ratio_final").value(n.final_contact_ratio);
  const statistics::ReliabilitySummary& s = r.summary;
  j.key("samples").value(static_cast<long>(r.lives.size()));
  if (r.status) j.key("status").value(std::string(to_string(*r.status)));
  j.key("seed").value(static_cast<long>(r.seed_used));
  j.key("failed_evaluations").value(static_cast<long>(s.failed_evaluations));
  j.key("immediate_failures").value(static_cast<long>(s.immediate_failures));
  j.key("life_at_R").begin_object();
  for (const auto& l : s.life) {
    j.key(g(l.reliability, "%g")).value((l.fit ? l.fit->estimate : l.empirical.estimate) / kSecondsPerYear);
  }
  j.end_object();
  j.key("life_at_R_detail").begin_array();
  for (const auto& l : s.life) {
    j.begin_object().key("R").value(l.reliability);
    if (l.fit) {
      j.key("fit_years").value(l.fit->estimate / kSecondsPerYear);
      j.key("fit_lower_years").value(l.fit->lower / kSecondsPerYear);
      j.key("fit_upper_years").value(l.fit->upper / kSecondsPerYear);
    }
    j.key("empirical_years").value(l.empirical.estimate / kSecondsPerYear);
    j.key("empirical_lower_years").value(l.empirical.lower / kSecondsPerYear);
    j.key("empirical_upper_years").value(l.empirical.upper / kSecondsPerYear);
    j.key("confidence").value(l.empirical.confidence);
    j.end_object();
  }
  j.end_array();
  j.key("reliability").begin_array();
  for (const auto& t : s.reliability) {
    j.begin_object().key("t_years").value(t.t / kSecondsPerYear);
    j.key("R").value(t.fit ? *t.fit : t.empirical);
    j.key("R_empirical").value(t.empirical);
    j.end_object();
  }
  j.end_array();
  j.key("fit");
  if (const statistics::CandidateFit* c = s.chosen_fit()) {
    j.begin_object();
    j.key("family").value(statistics::family_name(c->family));
    j.key("first").value(c->fit->distribution.first());
    j.key("second").value(c->fit->distribution.second());
    j.key("description").value(c->fit->distribution.describe());
    j.key("mean_years").value(c->fit->distribution.mean() / kSecondsPerYear);
    j.key("sd_years").value(c->fit->distribution.standard_deviation() / kSecondsPerYear);
    j.key("ks_statistic").value(c->ks.statistic);
    j.key("ks_critical").value(c->ks.critical_value);
    j.key("ks_p_value").value(c->ks.p_value);
    j.key("accepted").value(c->ks.accepted);
    j.end_object();
  } else {
    j.null();
  }
  j.key("candidates").begin_array();
  for (const auto& c : s.candidates) {
    j.begin_object().key("family").value(statistics::family_name(c.family));
    if (c.fit) {
      j.key("description").value(c.fit->distribution.describe());
      j.key("aic").value(c.fit->aic);
      j.key("ks_statistic").value(c.ks.statistic);
      j.key("ks_critical").value(c.ks.critical_value);
      j.key("accepted").value(c.ks.accepted);
    } else {
      j.key("error").value(c.error);
    }
    j.end_object();
  }
  j.end_array();
  if (r.exact.available) {
    j.key("exact").begin_object();
    j.key("input").value(r.exact.input);
    // Probability of a sample outside [max(1, [eps]), eps_max]: fails at t = 0.
    j.key("failed_at_start").value(r.exact.failed_at_start);
    // Probability of a value outside the input's domain (excluded: R is conditional on a valid sample).
    j.key("outside_domain").value(r.exact.outside_domain);
    j.key("life_at_R").begin_object();
    for (std::size_t i = 0; i < r.exact.life_at_R_years.size(); ++i) {
      j.key(g(d.reliability.reliabilities[i], "%g")).value(r.exact.life_at_R_years[i]);
    }
    j.end_object();
    j.key("reliability").begin_array();
    for (std::size_t i = 0; i < r.exact.R_at_times.size(); ++i) {
      j.begin_object().key("t_years").value(d.reliability.times[i] / kSecondsPerYear);
      j.key("R").value(r.exact.R_at_times[i]).end_object();
    }
    j.end_array();
    j.end_object();
  }
  j.key("warnings").begin_array();
  for (const std::string& w : n.warnings) j.value(w);
  for (const std::string& w : s.warnings) j.value(w);
  for (const std::string& w : r.warnings) j.value(w);
  j.end_array();
  j.key("files").begin_object();
  auto file = [&](const char* k, const std::string& v) {
    j.key(k);
    if (v.empty()) {
      j.null();
    } else {
      j.value(v);
    }
  };
  file("wear_profile_csv", f.wear_profile_csv);
  file("life_samples_csv", f.life_samples_csv);
  file("reliability_csv", f.reliability_csv);
  file("life_histogram_csv", f.histogram_csv);
  file("wear_profile_png", f.wear_profile_png);
  file("life_histogram_png", f.histogram_png);
  file("reliability_png", f.reliability_png);
  j.end_object();
  j.key("timings").begin_object();
  j.key("nominal_ms").value(r.nominal_ms);
  j.key("samples_ms").value(r.samples_ms);
  j.key("fit_ms").value(r.fit_ms);
  j.key("total_ms").value(total_ms);
  j.key("threads").value(static_cast<int>(r.threads_used));
  j.key("processes").value(static_cast<int>(r.processes_used));
  j.end_object();
  j.end_object();
  return j.str();
}

}  // namespace rackopt
