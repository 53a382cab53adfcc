#include "rackopt/dynamics/mesh_force_law_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rackopt {

namespace {

double involute(double alpha) { return std::tan(alpha) - alpha; }

// The approach at which a pinion corner at radius R_c (on the involute, LOA
// image s_c = sqrt(R_c^2 - r_b^2)) touches the straight rack flank whose
// rigid-body position is LOA coordinate s. Frame: n from the pinion centre O
// to T, d along the line of action; a point is (a, b) = a n + b d, its LOA
// coordinate b. The flank of a pair at s is the line b = s (its normal is the
// line of action), rack material at b > s. The corner sits on the involute
// whose LOA point is s: polar angle psi_c = s/r_b - inv(alpha_c) from n. The
// pinion turned on by Delta puts it at b = R_c sin(psi_c + Delta): it touches
// at sin(psi_c + Delta) = s / R_c, and delta = r_b Delta.
double pinion_corner_gap(double r_b, double R_c, double s) {
  const double alpha_c = std::acos(std::clamp(r_b / R_c, -1.0, 1.0));
  return r_b * std::asin(std::clamp(s / R_c, -1.0, 1.0)) - s + r_b * involute(alpha_c);
}


}  // namespace

std::optional<double> corner_gap(const MeshGeometry& g, double s) {
  const ContactPath& path = g.path;
  if (s > path.s_start && s < path.s_end) return std::nullopt;
  const double r_b = g.pinion.base_radius;
  const double a0 = g.pressure_angle;
  const double ca = std::cos(a0), sa = std::sin(a0);
  const double tol = 1e-9 * g.rack.pitch;
  // Pinion tip side: the tip corner on the rack flank. Where the touching
  // point would lie in the rack's root round the flank line is taken as
  // extended (the gap stays continuous and growing; docs/models/dynamics.md,
  // limits).
  if (s >= path.s_end) {
    const double R_c = g.pinion.tip_radius;
    if (!(std::abs(s) < R_c)) return std::nullopt;
    return std::max(0.0, pinion_corner_gap(r_b, R_c, s));
  }
  // Root side: the rack tip corner K against the pinion involute, and, on an
  // undercut pinion, its form corner against the rack flank; the gap is the
  // smaller of the two that can touch. Where one stops touching (K reaches
  // the form corner; the form corner reaches the rack tip) the two meet:
  // corner on corner, the same gap.
  const bool start_at_rack_tip = path.start_limited_by == "rack_tip";
  const bool form_corner = g.pinion.undercut && path.start_limited_by == "form_circle";
  // A start behind the base circle (interference ignored on purpose) is no
  // physical contact: no corner there either.
  if ((!start_at_rack_tip && !form_corner) || path.s_start < 0) return std::nullopt;
  std::optional<double> gap;
  // The rack tip corner of the flank at s: on the line b = s at the rack tip
  // depth, which at s = s_A is the LOA point (r_b, s_A).
  const double a_k = r_b + (path.s_rack_tip - s) * sa / ca;
  const double R_k = std::hypot(a_k, s);
  // The involute runs from the form circle (at a start on the rack tip the
  // form circle may lie up to 1e-4 p_b beyond it: build_mesh_geometry) to the tip.
  const double r_low = start_at_rack_tip ? std::min(g.pinion.form_radius, std::hypot(r_b, path.s_start))
                                         : g.pinion.form_radius;
  if (R_k >= r_low - tol && R_k <= g.pinion.tip_radius + tol) {
    const double alpha_k = std::acos(std::clamp(r_b / R_k, -1.0, 1.0));
    const double psi_k = std::atan2(s, a_k);
    // On the pinion flank whose LOA point is s, psi + inv(alpha) = s / r_b;
    // K lies psi_k + inv(alpha_k) - s / r_b ahead of it (outside the tooth).
    gap = std::max(0.0, r_b * (psi_k + involute(alpha_k)) - s);
  }
  if (form_corner) {
    const double R_c = g.pinion.form_radius;
    if (std::abs(s) < R_c) {
      // It touches the flank line at (sqrt(R_c^2 - s^2), s); the rack flank
      // is there when that point lies below the rack tip (depth along
      // cos(a0) n + sin(a0) d, perpendicular to the rack).
      const double depth = std::sqrt(R_c * R_c - s * s) * ca + s * sa;
      const double depth_tip = r_b * ca + path.s_rack_tip * sa;
      if (depth >= depth_tip - tol) {
        const double gc = std::max(0.0, pinion_corner_gap(r_b, R_c, s));
        gap = gap ? std::min(*gap, gc) : gc;
      }
    }
  }
  return gap;
}

namespace {

// What a corner slot takes from its pair at the path end.
struct PathEnd {
  // The stiffness the mesh gains there when the pair touches: K with the pair
  // (the limit from inside the path) minus K without it (from outside) [N/m].
  // With independent pairs this is the pair's own k; with pairs coupled by
  // the rack body it is less, since the body's compliance is in series with
  // every pair: adding the pair's own k would overcount it.
  double stiffness = 0;
  double relief = 0;     // the gap of its slot inside the path there [m]
  // K_local / K there: the teeth's share of the approach is K / K_local, so a
  // corner gap g is closed at the approach g K_local / K.
  double gap_scale = 1;
};

struct Builder {
  Builder(const Drive& d, const MeshStiffnessModel& m, const MeshGeometry& geo) : drive(d), model(m), g(geo) {}
  const Drive& drive;
  const MeshStiffnessModel& model;
  const MeshGeometry& g;
  double pb = 0, ca = 0;
  double A0 = 0;  // s of rack tooth j at travel X is A0 + j p_b - X cos(alpha)
  int S = 0;      // the curve's slots
  int slots = 0;
  // The corner slots are kept for s in (s_end, s_tip_reach] and [s_root_reach, s_start).
  double s_tip_reach = 0, s_root_reach = 0;
  bool tip_corner = false, root_corner = false;
  std::map<std::pair<int, int>, PathEnd> ends;  // (rack tooth, +1 tip side / -1 root side)

  double s_of(int j, double X) const { return A0 + j * pb - X * ca; }
  double travel_at(int j, double s) const { return (A0 + j * pb - s) / ca; }

  // The slot stiffness and gap of a pair of a static state.
  std::pair<double, double> slot_of(const MeshState& st, const PairState& p) const {
    const double k = st.stiffness * p.stiffness_share;
    if (k > 0) return {k, p.relief};
    if (p.relief > 0) {
      // A relieved pair that carries no load at load.force: its own
      // stiffness, engaging once the approach closes its relief, and not
      // before the static approach (the rack body's coupling can hold it
      // open beyond its relief, which a law of independent slots cannot).
      const double c = p.local() + p.body;
      if (c > 0) return {1.0 / c, std::max(p.relief, st.approach)};
    }
    return {0.0, 0.0};
  }

  const PathEnd& end_of(int j, int side) {
    const auto key = std::make_pair(j, side);
    if (auto it = ends.find(key); it != ends.end()) return it->second;
    // Tip side: the pair enters at s_end as X grows, inside to the right of
    // its breakpoint; root side: it leaves at s_start, inside to the left.
    const double s_lim = side > 0 ? g.path.s_end : g.path.s_start;
    const double X = travel_at(j, s_lim);
    const MeshState in = model.at(X, side > 0 ? +1 : -1);
    PathEnd e;
    for (const PairState& p : in.pairs) {
      if (p.rack_tooth != j) continue;
      const auto [k, gap] = slot_of(in, p);
      e.relief = gap;
      if (p.stiffness_share > 0) {
        const MeshState out = model.at(X, side > 0 ? -1 : +1);
        e.stiffness = std::max(0.0, in.stiffness - out.stiffness);
      } else {
        e.stiffness = k;  // open (relieved) at load: its own stiffness, as inside the path
      }
    }
    if (in.stiffness > 0 && in.local_stiffness > 0) e.gap_scale = std::max(1.0, in.local_stiffness / in.stiffness);
    return ends.emplace(key, e).first->second;
  }

  // Largest reach of a corner slot: where its gap reaches `limit`, or the
  // corner stops touching, within half a base pitch of the path end.
  double reach(double s_end_side, double direction, double limit) const {
    auto inside = [&](double s) {
      const std::optional<double> gap = corner_gap(g, s);
      return gap && *gap <= limit;
    };
    double lo = 0, hi = 0.5 * pb;  // distances from the path end
    if (!inside(s_end_side + direction * 1e-12 * pb)) return s_end_side;
    if (inside(s_end_side + direction * hi)) return s_end_side + direction * hi;
    for (int it = 0; it < 200 && hi - lo > 1e-12 * pb; ++it) {
      const double mid = 0.5 * (lo + hi);
      (inside(s_end_side + direction * mid) ? lo : hi) = mid;
    }
    return s_end_side + direction * lo;
  }

  enum class Corner { kAuto, kOn, kOff };

  // One row of the law from a static state at X; `tip`, `root` force a corner
  // slot on or off (the two limits where it starts or stops).
  void add_row(MeshForceLaw& law, const MeshState& st, double X, Corner tip, Corner root) {
    law.travel.push_back(X);
    const std::size_t base = law.stiffness.size();
    law.stiffness.resize(base + static_cast<std::size_t>(slots), 0.0);
    law.gap.resize(base + static_cast<std::size_t>(slots), 0.0);
    for (const PairState& p : st.pairs) {
      const auto [k, gap] = slot_of(st, p);
      law.stiffness[base + static_cast<std::size_t>(p.slot)] = k;
      law.gap[base + static_cast<std::size_t>(p.slot)] = k > 0 ? gap : 0.0;
    }
    if (slots == S || st.pairs.empty()) return;
    auto corner = [&](int slot, int j, int side, Corner mode) {
      if (mode == Corner::kOff) return;
      const bool enabled = side > 0 ? tip_corner : root_corner;
      if (!enabled) return;
      // The pair's s outside the path (rounding at the path end clamped).
      double s = s_of(j, X);
      s = side > 0 ? std::max(s, g.path.s_end) : std::min(s, g.path.s_start);
      if (mode == Corner::kAuto && (side > 0 ? s > s_tip_reach : s < s_root_reach)) return;
      const std::optional<double> gap = corner_gap(g, std::clamp(s, s_root_reach, s_tip_reach));
      if (!gap) return;
      const PathEnd& e = end_of(j, side);
      if (!(e.stiffness > 0)) return;
      law.stiffness[base + static_cast<std::size_t>(slot)] = e.stiffness;
      law.gap[base + static_cast<std::size_t>(slot)] = e.relief + e.gap_scale * *gap;
    };
    // Pairs are ordered by s descending: the tip-side neighbour is the next
    // rack tooth after the first, the root-side one the tooth before the last.
    corner(S, st.pairs.front().rack_tooth + 1, +1, tip);
    corner(S + 1, st.pairs.back().rack_tooth - 1, -1, root);
  }
};

}  // namespace

MeshForceLaw build_mesh_force_law(const Drive& drive, const MeshStiffnessModel& model, int positions_per_period,
                                  const MeshForceLawOptions& options) {
  const double F = drive.load.force;
  if (!(F > 0) || !std::isfinite(F)) {
    throw std::invalid_argument("mesh force law: load.force must be > 0 (the law is the static model at that load)");
  }
  if (!(options.corner_reach > 0) || !std::isfinite(options.corner_reach)) {
    throw std::invalid_argument("mesh force law: corner_reach must be > 0");
  }
  if (drive.load.force != model.drive().load.force || drive.mounting.clearance != model.drive().mounting.clearance ||
      drive.rack.span != model.drive().rack.span) {
    throw std::invalid_argument("mesh force law: `drive` is not the stiffness model's drive");
  }
  const MeshGeometry& g = model.geometry();
  const StiffnessCurve curve = model.curve(CurveDetail::kFull, positions_per_period);
  if (curve.samples.empty()) throw std::invalid_argument("mesh force law: the stiffness curve has no samples");

  Builder b(drive, model, g);
  b.pb = g.path.base_pitch;
  b.ca = std::cos(g.pressure_angle);
  b.S = std::max(curve.max_pairs, 1);
  b.slots = b.S + (options.corner_contact ? 2 : 0);

  MeshForceLaw law;
  law.period = drive.rack.span;
  law.mesh_pitch = g.rack.pitch;
  law.slots = b.slots;
  // The normal backlash: the circumferential 2 Delta tan(alpha) on the pitch
  // line along the line of action. 0 (clearance 0): the back flank touches
  // as soon as the approach turns negative.
  law.backlash = g.backlash * b.ca;

  // Rack tooth j's LOA coordinate is A0 + j p_b - X cos(alpha): A0 from a pair
  // strictly inside the path (at the path ends s is clamped).
  bool have_a0 = false;
  double k_local_min = 0;
  for (const MeshState& st : curve.samples) {
    if (st.local_stiffness > 0) k_local_min = k_local_min > 0 ? std::min(k_local_min, st.local_stiffness) : st.local_stiffness;
    for (const PairState& p : st.pairs) {
      if (!have_a0 && p.s > g.path.s_start && p.s < g.path.s_end) {
        b.A0 = p.s + st.travel * b.ca - p.rack_tooth * b.pb;
        have_a0 = true;
      }
    }
  }
  // (X, (side, rack tooth)) where a corner slot starts or stops inside the period.
  std::vector<std::pair<double, std::pair<int, int>>> limits;
  if (options.corner_contact && have_a0 && k_local_min > 0) {
    std::vector<double> travels;
    travels.reserve(curve.samples.size());
    for (const MeshState& st : curve.samples) travels.push_back(st.travel);
    const double limit = options.corner_reach * F / k_local_min;
    b.s_tip_reach = b.reach(g.path.s_end, +1, limit);
    b.s_root_reach = b.reach(g.path.s_start, -1, limit);
    b.tip_corner = b.s_tip_reach > g.path.s_end;
    b.root_corner = b.s_root_reach < g.path.s_start;
    // The travel where each rack tooth's corner slot reaches its limit, inside the period.
    for (int side : {+1, -1}) {
      if (!(side > 0 ? b.tip_corner : b.root_corner)) continue;
      const double s_lim = side > 0 ? b.s_tip_reach : b.s_root_reach;
      const int j_lo = static_cast<int>(std::floor((s_lim - b.A0) / b.pb)) - 1;
      const int j_hi = static_cast<int>(std::ceil((s_lim + law.period * b.ca - b.A0) / b.pb)) + 1;
      for (int j = j_lo; j <= j_hi; ++j) {
        double X = b.travel_at(j, s_lim);
        // Not onto a curve sample: a travel holds at most two samples (one
        // jump). Moved 1e-9 p towards the side where the slot is off instead.
        const double tol = 1e-9 * law.mesh_pitch;
        const auto near = std::lower_bound(travels.begin(), travels.end(), X - tol);
        if (near != travels.end() && *near <= X + tol) X = *near + (side > 0 ? -tol : tol);
        if (X > 0 && X < law.period) limits.push_back({X, {side, j}});
      }
    }
    std::sort(limits.begin(), limits.end());
  } else {
    b.slots = b.S;
    law.slots = b.S;
  }

  const std::size_t rows = curve.samples.size() + 2 * limits.size();
  law.travel.reserve(rows);
  law.stiffness.reserve(rows * static_cast<std::size_t>(b.slots));
  law.gap.reserve(rows * static_cast<std::size_t>(b.slots));
  using Corner = Builder::Corner;
  std::size_t next_limit = 0;
  auto add_limits_before = [&](double X) {
    for (; next_limit < limits.size() && limits[next_limit].first < X; ++next_limit) {
      const double Xl = limits[next_limit].first;
      const int side = limits[next_limit].second.first;
      const MeshState st = model.at(Xl);
      // Tip side: the slot is on to the right of its limit (s falls as X
      // grows); root side: on to the left.
      const Corner left = side > 0 ? Corner::kOff : Corner::kOn;
      const Corner right = side > 0 ? Corner::kOn : Corner::kOff;
      b.add_row(law, st, Xl, side > 0 ? left : Corner::kAuto, side < 0 ? left : Corner::kAuto);
      b.add_row(law, st, Xl, side > 0 ? right : Corner::kAuto, side < 0 ? right : Corner::kAuto);
    }
  };
  for (const MeshState& st : curve.samples) {
    add_limits_before(st.travel);
    b.add_row(law, st, st.travel, Corner::kAuto, Corner::kAuto);
  }
  add_limits_before(std::numeric_limits<double>::infinity());
  return law;
}

}  // namespace rackopt
