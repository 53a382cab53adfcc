#include "rackopt/fe/fe_comparison.hpp"

#include "rackopt/core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "rackopt/core/interrupt.hpp"
#include "rackopt/fe/gmsh_library.hpp"
#include "rackopt/fe/rack_span_fe.hpp"
#include "rackopt/stiffness/supported_rack.hpp"

namespace rackopt::fe {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Mean wall time of one model.at(X): one call takes microseconds, so it is
// repeated until a millisecond has passed (at most 1000 calls).
double time_analytic_position(const MeshStiffnessModel& model, double travel) {
  const auto t0 = Clock::now();
  int calls = 0;
  double elapsed = 0;
  do {
    const MeshState s = model.at(travel);
    if (s.stiffness < 0) throw std::logic_error("negative stiffness");  // keeps the call from being dropped
    ++calls;
    elapsed = seconds_since(t0);
  } while (elapsed < 1e-3 && calls < 1000);
  return elapsed / calls;
}

void check_positive(double v, const std::string& what, double travel) {
  if (!(v > 0) || !std::isfinite(v)) {
    throw std::runtime_error("the FE " + what + " at travel X = " + std::to_string(travel) +
                             " m is not a positive number (" + std::to_string(v) + ")");
  }
}

// One solve of the comparison: the mesh position of row `row`, or the
// single-tooth compliance of `member` for pair `pair` of that row.
struct Job {
  int row = 0;
  int pair = -1;  // -1: the mesh position
  ToothMember member = ToothMember::kPinion;
};

}  // namespace

Drive fe_reference_drive(const Drive& drive) {
  Drive d = drive;
  d.effects.rack_span = RackSpanModel::kRigid;
  d.effects.spalling = false;
  d.spalls.clear();
  d.pinion.tip_relief = ProfileRelief{};
  d.pinion.root_relief = ProfileRelief{};
  d.rack.tip_relief = ProfileRelief{};
  d.rack.root_relief = ProfileRelief{};
  return d;
}

Drive fe_reference_drive(const Drive& drive, const FeOptions& fe) {
  const Drive d = fe_reference_drive(drive);
  return fe.rack_on_supports ? rack_on_supports_drive(d, fe) : d;
}

std::vector<double> fe_positions(const MeshStiffnessModel& model, int positions, double* period_start) {
  if (positions < 1 || positions > kMaxFePositions) {
    throw std::invalid_argument("FE positions " + std::to_string(positions) + " is out of range; allowed: 1.." +
                                std::to_string(kMaxFePositions));
  }
  const double p = model.geometry().rack.pitch;
  const double mid = 0.5 * model.drive().rack.span;
  double x0 = mid;
  double best = std::numeric_limits<double>::infinity();
  for (double b : model.breakpoints(mid - p, mid + p)) {
    if (model.at(b, +1).pairs.size() <= model.at(b, -1).pairs.size()) continue;  // not an entry
    if (std::abs(b - mid) < best) {
      best = std::abs(b - mid);
      x0 = b;
    }
  }
  if (period_start) *period_start = x0;
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(positions));
  for (int i = 0; i < positions; ++i) out.push_back(x0 + (i + 0.5) * p / positions);
  return out;
}

double relative_error(double analytic, double fe) {
  if (!(fe > 0) || !std::isfinite(fe)) return std::numeric_limits<double>::quiet_NaN();
  return (analytic - fe) / fe;
}

FeCalls real_fe_calls() {
  FeCalls c;
  c.mesh_position = [](const Drive& d, double x, const FeOptions& o) { return fe_mesh_position(d, x, o); };
  c.tooth_compliance = [](const Drive& d, ToothMember m, double s, const FeOptions& o) {
    return fe_tooth_compliance(d, m, s, o);
  };
  return c;
}

FeComparison compare_with_fe(const Drive& drive, const FeComparisonOptions& options) {
  const auto t_start = Clock::now();
  check_fe_options(options.fe);
  FeCalls calls = options.calls;
  if (!calls.mesh_position || !calls.tooth_compliance) {
    const FeCalls real = real_fe_calls();
    if (!calls.mesh_position) calls.mesh_position = real.mesh_position;
    if (!calls.tooth_compliance) calls.tooth_compliance = real.tooth_compliance;
    (void)find_ccx(options.fe.ccx);  // a missing ccx or Gmsh is reported before any work
    (void)gmsh_api();
  }

  FeComparison out;
  out.fe = options.fe;
  const Drive ref = fe_reference_drive(drive, options.fe);
  const auto t_model = Clock::now();
  const MeshStiffnessModel model(ref);  // DesignError here, before any FE work
  out.summary.analytic_model_seconds = seconds_since(t_model);
  out.pitch = model.geometry().rack.pitch;
  out.contact_ratio = model.geometry().path.contact_ratio;
  out.slots = static_cast<int>(std::floor(out.contact_ratio)) + 1;
  out.travels = fe_positions(model, options.positions, &out.period_start);
  out.notes = {
      options.fe.rack_on_supports
          ? "rack on its hinged supports in both codes: the analytic model with the coupled rack-span beam of the FE "
            "body's section, the FE rack the whole span held at the neutral axis of its end faces"
          : "rack body rigid in the analytic model (the FE rack segment's base is fixed)",
      "spalls and profile relief left out of both codes (the FE bodies carry neither)",
      "only the theoretical pairs are compared; FE pairs in extended contact are listed apart",
      "pinion compliance = tooth + fillet foundation; rack compliance = tooth; Hertz only in K",
      "errors: (analytic - FE) / FE for K and compliances; analytic - FE for load shares",
  };

  // The analytic side first: the pairs each FE solve needs come from it.
  std::vector<MeshState> states;
  for (double x : out.travels) {
    ComparedPosition row;
    row.travel = x;
    const MeshState s = model.at(x);
    row.k_analytic = s.stiffness;
    row.analytic_seconds = time_analytic_position(model, x);
    for (const PairState& p : s.pairs) {
      ComparedPair c;
      c.rack_tooth = p.rack_tooth;
      c.pinion_tooth = p.pinion_tooth;
      c.slot = p.slot;
      c.s = p.s;
      c.share_analytic = p.load_share;
      c.pinion_analytic = p.pinion.total() + p.fillet;
      c.pinion_compared = pinion_contact_on_involute(model.geometry(), p.s);
      // The FE single-tooth solve holds the segment's base: on supports the
      // model's rack foundation is the local one, so the held one is compared.
      c.rack_analytic = supported_rack_applies(model.drive().effects)
                            ? analytic_tooth_compliance(model.drive(), ToothMember::kRack, p.s)
                            : p.rack.total() + p.rack_foundation;
      row.pairs.push_back(c);
    }
    out.rows.push_back(std::move(row));
  }
  {
    const double x0 = out.period_start, x1 = x0 + out.pitch;
    constexpr int kSamples = 200;
    std::vector<std::pair<double, int>> at;  // travel, side
    for (int i = 0; i <= kSamples; ++i) at.emplace_back(x0 + (x1 - x0) * i / kSamples, 0);
    for (double b : model.breakpoints(x0, x1)) {
      at.emplace_back(b, -1);
      at.emplace_back(b, +1);
    }
    std::stable_sort(at.begin(), at.end(), [](const auto& a, const auto& b) {
      return a.first < b.first || (a.first == b.first && a.second < b.second);
    });
    for (const auto& [x, side] : at) out.analytic_curve.emplace_back(x, model.stiffness(x, side));
  }

  int off_involute = 0;
  for (const ComparedPosition& row : out.rows) {
    for (const ComparedPair& c : row.pairs) off_involute += c.pinion_compared ? 0 : 1;
  }
  if (off_involute > 0) {
    out.notes.push_back(std::to_string(off_involute) + " pair" + (off_involute == 1 ? "'s" : "s'") +
                        " pinion contact lies off the involute (below the form circle, or s <= 0 where the path of "
                        "contact starts below the base circle's tangent point): no FE single-tooth solve can load it, so "
                        "the pinion compliance is not compared there (the mesh solve and the rack tooth are)");
  }

  // The FE solves, as independent jobs in position order.
  std::vector<Job> jobs;
  for (int r = 0; r < static_cast<int>(out.rows.size()); ++r) {
    jobs.push_back({r, -1, ToothMember::kPinion});
    for (int k = 0; k < static_cast<int>(out.rows[r].pairs.size()); ++k) {
      if (out.rows[r].pairs[static_cast<std::size_t>(k)].pinion_compared) jobs.push_back({r, k, ToothMember::kPinion});
      jobs.push_back({r, k, ToothMember::kRack});
    }
  }
  std::vector<FePosition> positions(out.rows.size());
  std::vector<ToothComplianceFe> teeth(jobs.size());
  auto stopped = [&] { return options.stop && options.stop(); };
  unsigned threads = resolve_threads(options.threads);
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, jobs.size()));
  out.threads = std::max(1u, threads);
  ParallelControl control;
  control.stop = stopped;
  control.progress = options.progress;
  try {
    parallel_for(jobs.size(), out.threads, [&](std::size_t i) {
      const Job& job = jobs[i];
      const ComparedPosition& row = out.rows[static_cast<std::size_t>(job.row)];
      if (job.pair < 0) {
        positions[static_cast<std::size_t>(job.row)] = calls.mesh_position(ref, row.travel, options.fe);
      } else {
        teeth[i] = calls.tooth_compliance(ref, job.member, row.pairs[static_cast<std::size_t>(job.pair)].s, options.fe);
      }
    }, control);
  } catch (...) {
    // A stop ends the solves under way as failures: it is the stop that is reported.
    if (stopped()) throw Interrupted("FE comparison: stopped by " + stop_reason());
    throw;  // the first failure in position order, whatever the thread count
  }
  if (stopped()) throw Interrupted("FE comparison: stopped by " + stop_reason());

  // Assembly and errors.
  FeComparisonSummary& sum = out.summary;
  double mesh_s = 0, fe_s = 0, analytic_s = 0;
  for (std::size_t r = 0; r < out.rows.size(); ++r) {
    ComparedPosition& row = out.rows[r];
    const FePosition& fp = positions[r];
    check_positive(fp.stiffness, "mesh stiffness", row.travel);
    row.k_fe = fp.stiffness;
    row.k_error = relative_error(row.k_analytic, row.k_fe);
    row.fe_force = fp.force;
    row.nodes = fp.nodes;
    row.elements = fp.elements;
    row.fe_mesh_seconds = fp.seconds;
    row.shape = fp.shape;
    for (const FePair& q : fp.pairs) {
      auto it = std::find_if(row.pairs.begin(), row.pairs.end(), [&](const ComparedPair& c) {
        return c.rack_tooth == q.rack_tooth && c.pinion_tooth == q.pinion_tooth;
      });
      if (q.theoretical && it != row.pairs.end()) {
        it->carried_in_fe = true;
        it->share_fe = q.load_share;
      } else {
        row.extended_pairs.push_back(q);
        row.extended_share_fe += q.load_share;
      }
    }
    sum.max_k_error = std::max(sum.max_k_error, std::abs(row.k_error));
    for (ComparedPair& c : row.pairs) {
      c.share_error = c.share_analytic - c.share_fe;
      sum.max_share_error = std::max(sum.max_share_error, std::abs(c.share_error));
    }
  }
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Job& job = jobs[i];
    if (job.pair < 0) continue;
    ComparedPosition& row = out.rows[static_cast<std::size_t>(job.row)];
    ComparedPair& c = row.pairs[static_cast<std::size_t>(job.pair)];
    const ToothComplianceFe& t = teeth[i];
    const bool pinion = job.member == ToothMember::kPinion;
    check_positive(t.compliance, pinion ? "pinion tooth compliance" : "rack tooth compliance", row.travel);
    row.fe_tooth_seconds += t.seconds;
    if (pinion) {
      c.pinion_fe = t.compliance;
      c.pinion_error = relative_error(c.pinion_analytic, c.pinion_fe);
      c.pinion_seconds = t.seconds;
      sum.max_pinion_error = std::max(sum.max_pinion_error, std::abs(c.pinion_error));
    } else {
      c.rack_fe = t.compliance;
      c.rack_error = relative_error(c.rack_analytic, c.rack_fe);
      c.rack_seconds = t.seconds;
      sum.max_rack_error = std::max(sum.max_rack_error, std::abs(c.rack_error));
    }
  }
  for (const ComparedPosition& row : out.rows) {
    mesh_s += row.fe_mesh_seconds;
    fe_s += row.fe_mesh_seconds + row.fe_tooth_seconds;
    analytic_s += row.analytic_seconds;
  }
  const double n = static_cast<double>(out.rows.size());
  sum.fe_mesh_seconds_per_position = mesh_s / n;
  sum.fe_seconds_per_position = fe_s / n;
  sum.analytic_seconds_per_position = analytic_s / n;
  sum.time_ratio = analytic_s > 0 ? fe_s / analytic_s : 0.0;
  sum.wall_seconds = seconds_since(t_start);
  return out;
}

}  // namespace rackopt::fe
