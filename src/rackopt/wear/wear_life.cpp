#include "rackopt/wear/wear_life.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <span>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>

#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/hertz.hpp"
#include "rackopt/stiffness/pair_compliance.hpp"
#include "rackopt/stiffness/pair_coupling.hpp"
#include "rackopt/wear/band_weights.hpp"
#include "rackopt/wear/contact.hpp"
#include "rackopt/wear/hardness.hpp"

namespace rackopt {
namespace {

// The fractions of the life at which a full life keeps a snapshot.
constexpr std::array<double, 4> kSnapshotFractions{0.25, 0.5, 0.75, 1.0};

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kPinion = 0;
constexpr int kRack = 1;

[[noreturn]] void bad(const std::string& key, const std::string& what) { throw InputError(SourceMark{}, key, what); }

// G(h) = integral_0^h H(t) dt with H piecewise linear between `cells` + 1
// exact nodes on [0, D]. G is then piecewise quadratic and is inverted exactly
// cell by cell. Archard with frozen load, dh/dn = K q / H(h), integrates to
// G(h1) - G(h0) = K q dn exactly for any hardness profile (up to the
// piecewise-linear H, WearOptions::hardness_cells cells over the wear depth).
class HardnessIntegral {
 public:
  HardnessIntegral() = default;
  HardnessIntegral(const HardnessModel& model, double depth_max, int cells)
      : D_(depth_max), dh_(depth_max / cells), H_(cells + 1), G_(cells + 1) {
    for (int k = 0; k <= cells; ++k) H_[k] = model(k * dh_);
    G_[0] = 0;
    for (int k = 1; k <= cells; ++k) G_[k] = G_[k - 1] + 0.5 * (H_[k - 1] + H_[k]) * dh_;
  }
  double total() const { return G_.back(); }
  double G(double h) const {
    if (h <= 0) return 0;
    if (h >= D_) return G_.back();
    const int n = static_cast<int>(H_.size()) - 1;
    const int k = std::min(static_cast<int>(h / dh_), n - 1);
    const double t = h - k * dh_;
    return G_[k] + H_[k] * t + 0.5 * (H_[k + 1] - H_[k]) / dh_ * t * t;
  }
  double inverse(double g) const {
    if (g <= 0) return 0;
    if (g >= G_.back()) return D_;
    const auto it = std::upper_bound(G_.begin(), G_.end(), g);
    return solve_in_cell(static_cast<int>(it - G_.begin()) - 1, g);
  }
  // Same result, faster when a nearby depth is known (the depth before this
  // block): one Newton step gives the cell, a short walk corrects it.
  double inverse_near(double g, double h_hint) const {
    if (g <= 0) return 0;
    if (g >= G_.back()) return D_;
    const int n = static_cast<int>(H_.size()) - 1;
    const double hh = std::clamp(h_hint, 0.0, D_);
    const int kh = std::min(static_cast<int>(hh / dh_), n - 1);
    const double guess = hh + (g - G(hh)) / H_[kh];
    int k = std::clamp(static_cast<int>(guess / dh_), 0, n - 1);
    for (int steps = 0; steps < 8; ++steps) {
      if (G_[k] > g && k > 0) {
        --k;
      } else if (G_[k + 1] <= g && k < n - 1) {
        ++k;
      } else {
        return solve_in_cell(k, g);
      }
    }
    return inverse(g);
  }

 private:
  double solve_in_cell(int k, double g) const {
    const double r = g - G_[k];
    const double beta = (H_[k + 1] - H_[k]) / dh_;
    // 0.5 beta t^2 + H_k t - r = 0, stable root (H > 0).
    const double t = 2.0 * r / (H_[k] + std::sqrt(std::max(H_[k] * H_[k] + 2.0 * beta * r, 0.0)));
    return std::min(k * dh_ + t, D_);
  }

  double D_ = 0, dh_ = 0;
  std::vector<double> H_, G_;
};

// Everything of one realisation that stays fixed while it wears: the path,
// the profile points, the sampled mesh positions with their pair compliances,
// the band weights and the sliding ratios.
struct Path {
  double s_start = 0, eps = 0, clearance = 0;
  int N = 0;
  double ds = 0;
  std::vector<double> s;  // profile points
  // Mesh positions: position k has pairs pos_begin[k] .. pos_begin[k+1]-1 (load nodes).
  std::vector<int> pos_begin;
  std::vector<double> node_c;     // LOA coordinate of each load node
  std::vector<double> node_comp;  // local compliance of that pair [m/N]
  // Cross compliance of that pair and the next of its position (adjacent
  // teeth), 0 for the last pair or without effects.pair_coupling [m/N].
  std::vector<double> node_cross;
  // Load nodes grouped by pair and zone into intervals of the path, sorted along s.
  std::vector<std::vector<int>> intervals;
  // Band-averaging weights per member (CSR): <w>_i = sum_k val[k] P[idx[k]].
  std::array<std::vector<int>, 2> w_begin, w_idx;
  std::array<std::vector<double>, 2> w_val;
  std::array<std::vector<double>, 2> slide;  // |s - s_P| / v_i per point (pinion: exact band window, below)
  // Each point's band on the LOA (build_weights): centre and half-length,
  // half-length 0 where the point reads the pair at its own contact.
  std::array<std::vector<double>, 2> band_c, band_L;
  // The largest |band_c - s| + band_L of each member: a point's band lies
  // within this of its own point (transition_corrections' search).
  std::array<double, 2> band_reach{};
  // Smallest ratio, over the pinion points, of the exact-window sliding to
  // the thin-band law |s - s_P|/s (1 = the thin band holds everywhere).
  double base_circle_window = 1.0;
};

// Sliding of a pinion flank point through the Hertz band, per unit band
// width 2a, with the band's exact window on the involute.
//
// The thin-band law |s - s_P|/s takes the band short against the involute's
// radius of curvature s: the point at s is under load while the contact
// centre c is within a r_b/s of it. Near the base circle the curvature
// radius and the rolling speed v1 = omega s both go to zero, the thin-band
// window and the sliding ratio grow without bound, and a path starting a
// few micrometres above the base circle would wear through at once. The
// exact window follows from the involute arc length (c^2 - s^2)/(2 r_b)
// between the point and the contact centre: the point is in the band while
// |c^2 - s^2| <= 2 a r_b, i.e. for c in [c_lo, c_hi] = [sqrt(max(0, s^2 -
// 2 a r_b)), sqrt(s^2 + 2 a r_b)], during which the contact slides at
// omega |c - s_P| while c advances at omega r_b. The sliding distance is
// (1/r_b) * integral of |c - s_P| over that window: bounded (the window is
// at most sqrt(2 a r_b) long) and equal to 2a |s - s_P|/s to second order
// in a r_b/s^2 where the thin band holds (docs/models/wear.md).
struct InvoluteWindow {
  double lo = 0, hi = 0;  // contact-centre window on the LOA [m]
  double slide = 0;       // sliding distance / (2a)
};
InvoluteWindow involute_band_window(double s, double a, double rb, double s_pitch) {
  const double q = 2 * a * rb;
  const double sc = std::max(s, 0.0);
  InvoluteWindow w;
  w.lo = std::sqrt(std::max(0.0, sc * sc - q));
  w.hi = std::sqrt(sc * sc + q);
  // integral of |c - s_P| dc over [lo, hi]
  auto prim = [&](double c) { return 0.5 * (c - s_pitch) * std::abs(c - s_pitch); };
  w.slide = (prim(w.hi) - prim(w.lo)) / rb / (2 * a);
  return w;
}

}  // namespace

struct WearModel::Impl {
  Drive drive;
  WearOptions opt;
  MeshGeometry geo;
  std::vector<std::string> warnings;

  double a0 = 0, sa = 0, ta = 0, r = 0, rb = 0, sP = 0, s_end = 0, pb = 0;
  double s_start_nom = 0, eps_nom = 0, s_lo = 0, eps_max = 0;
  double b = 0, e_star = 0, force = 0, K = 0;
  double datum_shift = 0;   // x m - h_a2* m: s_A = s_P + (datum_shift + Delta)/sin a0
  double rack_dedendum = 0, rack_height = 0;
  double s_floor = 0;
  double rho_pinion = 1;   // pinion passes per rack pass
  double min_cr = 1;

  // Local compliance tables (rigid rack body): pinion tooth + fillet + Hertz
  // against s; rack tooth against contact height above its root line.
  double cp_lo = 0, cp_ds = 0;
  std::vector<double> cp;
  double cr_dy = 0;
  std::vector<double> cr;
  // The foundations alone (pinion fillet foundation against s, rack tooth
  // foundation against height), for the pairs' coupling.
  std::vector<double> fp, fr;
  bool coupled_pairs = false;  // pairs_coupled(effects), as the mesh model reads it
  std::optional<PairCompliance> pair;

  std::array<HardnessModel, 2> hardness;
  std::array<HardnessIntegral, 2> G;
  std::array<double, 2> limit{};          // failure depth per member [m]
  std::array<bool, 2> limit_is_case{};

  // The start of every life without a sampled contact ratio: the nominal
  // path with its load nodes and compliances (independent of the force), and
  // its unworn load sharing and band weights at the drive's own force. They
  // depend on the design only, so a model builds them once, on first use
  // (std::call_once: life() is called from several threads at once), and a
  // sample that scales only K or the hardness starts from them as they are;
  // one that scales the force reuses the path and redoes the rest. Built by
  // the same code as a sample's own start, so the lives are bit-identical
  // (WearOptions::reuse_nominal_start off rebuilds them per life, for tests).
  // The band weights are built on first use of their own: a life read for
  // its life alone may not need them (bounded_pass_loads).
  struct NominalStart {
    Path path;        // before the load sharing (make_path)
    std::vector<double> margin;  // unworn signed pair margins at that force (solve)
  };
  mutable std::once_flag nominal_once, weighted_once;
  mutable std::optional<NominalStart> nominal_start_;
  mutable std::optional<Path> nominal_weighted_;  // the path with the band weights at the drive's force
  const NominalStart& nominal_start() const {
    std::call_once(nominal_once, [this] {
      NominalStart ns;
      ns.path = make_path(s_start_nom, eps_nom, drive.mounting.clearance);
      const std::vector<double> zero(ns.path.N, 0.0);
      solve(ns.path, zero, zero, force, ns.margin);
      nominal_start_.emplace(std::move(ns));
    });
    return *nominal_start_;
  }
  const Path& nominal_weighted() const {
    std::call_once(weighted_once, [this] {
      const NominalStart& ns = nominal_start();
      Path weighted = ns.path;
      build_weights(weighted, ns.margin);
      nominal_weighted_.emplace(std::move(weighted));
    });
    return *nominal_weighted_;
  }

  // No depth can pass the end of a member's measured hardness data before
  // its limit (a depth never passes the limit): then no life warns of it.
  bool hardness_warnings_impossible() const {
    return hardness[kPinion].first_clamped_depth() >= limit[kPinion] &&
           hardness[kRack].first_clamped_depth() >= limit[kRack];
  }

  Impl(const Drive& d, WearOptions o)
      : drive(d),
        opt(o),
        geo(build_mesh_geometry(d)),
        hardness{HardnessModel(d.wear.pinion_hardness, "wear.pinion_hardness"),
                 HardnessModel(d.wear.rack_hardness, "wear.rack_hardness")} {
    const WearSpec& w = drive.wear;
    if (!(w.coefficient > 0) || !std::isfinite(w.coefficient))
      bad("wear.coefficient", "wear is not configured: the Archard coefficient K must be positive");
    if (!(w.max_depth > 0) || !std::isfinite(w.max_depth)) bad("wear.max_depth", "must be positive and finite");
    if (!std::isfinite(w.min_contact_ratio) || w.min_contact_ratio < 0)
      bad("wear.min_contact_ratio", "must be >= 0 and finite");
    if (w.profile_points < 3) bad("wear.profile_points", "at least 3 points per profile are needed");
    if (!(w.block_fraction > 0 && w.block_fraction <= 1)) bad("wear.block_fraction", "must lie in (0, 1]");
    if (!(drive.duty.rack_meshes_per_year >= 0) || !std::isfinite(drive.duty.rack_meshes_per_year))
      bad("duty.rack_meshes_per_year", "must be >= 0 and finite");
    if (!(drive.duty.pinion_meshes_per_year >= 0) || !std::isfinite(drive.duty.pinion_meshes_per_year))
      bad("duty.pinion_meshes_per_year", "must be >= 0 and finite");
    if (drive.duty.pinion_meshes_per_year > 0 && !(drive.duty.rack_meshes_per_year > 0))
      bad("duty.rack_meshes_per_year", "must be given when duty.pinion_meshes_per_year is");
    if (!(drive.load.force > 0) || !std::isfinite(drive.load.force))
      bad("load.force", "wear needs a positive mesh force");
    if (!(opt.positions_per_point > 0)) bad("", "WearOptions.positions_per_point must be positive");
    if (!(opt.positions_cap > 0)) bad("", "WearOptions.positions_cap must be positive");
    if (opt.hardness_cells < 1) bad("", "WearOptions.hardness_cells must be at least 1");
    if (opt.compliance_intervals < 2) bad("", "WearOptions.compliance_intervals must be at least 2");

    warnings = geo.warnings;
    K = w.coefficient;
    force = drive.load.force;
    min_cr = w.min_contact_ratio;
    a0 = drive.pinion.pressure_angle;
    sa = std::sin(a0);
    ta = std::tan(a0);
    r = geo.pinion.pitch_radius;
    rb = geo.pinion.base_radius;
    sP = geo.path.s_pitch;
    s_end = geo.path.s_end;
    pb = geo.path.base_pitch;
    s_start_nom = geo.path.s_start;
    eps_nom = geo.path.contact_ratio;
    s_floor = 1e-3 * rb;
    if (drive.duty.rack_meshes_per_year > 0 && drive.duty.pinion_meshes_per_year > 0)
      rho_pinion = drive.duty.pinion_meshes_per_year / drive.duty.rack_meshes_per_year;
    const double m = drive.pinion.module;
    datum_shift = (drive.pinion.profile_shift - drive.rack.addendum_coef) * m;
    rack_dedendum = geo.rack.dedendum;
    rack_height = geo.rack.dedendum + geo.rack.addendum;

    // Largest contact ratio: zero clearance, same limits as the geometry.
    const double s_A0 = sP + datum_shift / sa;
    s_lo = s_A0;
    if (drive.effects.interference_limit) {
      if (geo.path.s_form > s_A0 + 1e-4 * pb) s_lo = geo.path.s_form;
      s_lo = std::max(s_lo, 0.0);
    }
    s_lo = std::min(s_lo, s_start_nom);  // the nominal path is always allowed
    eps_max = (s_end - s_lo) / pb;

    const double b_rack = drive.rack.face_width > 0 ? drive.rack.face_width : drive.pinion.face_width;
    b = std::min(drive.pinion.face_width, b_rack);
    e_star = effective_modulus(drive.pinion.material, drive.rack.material);
    build_compliance_tables(b_rack);

    for (int mb = 0; mb < 2; ++mb) {
      limit[mb] = w.max_depth;
      const double cd = hardness[mb].case_depth();
      if (w.stop_at_case_depth && cd > 0 && cd < w.max_depth) {
        limit[mb] = cd;
        limit_is_case[mb] = true;
      }
      G[mb] = HardnessIntegral(hardness[mb], limit[mb], opt.hardness_cells);
    }
  }

  // Tooth compliance tables (rigid rack body) from the pair model the mesh
  // model uses too: pinion tooth + fillet foundation against s, rack tooth
  // + its foundation against the contact height above the rack root line
  // (the clearance moves the rack). The contact term is added per node in
  // make_path, at the node's pair force.
  void build_compliance_tables(double b_rack) {
    (void)b_rack;
    // The wear model's rack body is rigid: its foundation is the one of a
    // rack held under its body (not the local one of a rack on supports).
    Drive rigid = drive;
    rigid.effects.rack_span = RackSpanModel::kRigid;
    pair.emplace(rigid, geo);
    const int n = opt.compliance_intervals;
    cp_lo = std::min(s_lo, s_start_nom);
    cp_ds = (s_end - cp_lo) / n;
    cp.resize(n + 1);
    cr.assign(n + 1, 0.0);
    fp.assign(n + 1, 0.0);
    fr.assign(n + 1, 0.0);
    cr_dy = rack_height / n;
    coupled_pairs = pairs_coupled(drive.effects);
    for (int k = 0; k <= n; ++k) {
      // The top node is evaluated exactly at s_end (the tooth model rejects
      // radii beyond the tip, and rounding could put k*ds past it).
      const double s = k == n ? s_end : cp_lo + k * cp_ds;
      const PairTeeth t = pair->teeth_at(s, k * cr_dy, b);
      cp[k] = t.pinion.total() + t.fillet;
      cr[k] = t.rack.total() + t.rack_foundation;
      fp[k] = t.fillet;
      fr[k] = t.rack_foundation;
    }
  }

  static double lerp_table(const std::vector<double>& t, double lo, double d, double x) {
    const int n = static_cast<int>(t.size()) - 1;
    double u = (x - lo) / d;
    u = std::clamp(u, 0.0, static_cast<double>(n));
    const int k = std::min(static_cast<int>(u), n - 1);
    const double f = u - k;
    return t[k] + f * (t[k + 1] - t[k]);
  }

  double rack_height_at(double s, double clearance) const {
    return rack_dedendum + r * sa * sa - s * sa + drive.pinion.profile_shift * drive.pinion.module + clearance;
  }
  // Tooth compliance of the pair at LOA coordinate s for a rack datum at
  // `clearance` (no contact term).
  double teeth_compliance(double s, double clearance) const {
    return lerp_table(cp, cp_lo, cp_ds, s) + lerp_table(cr, 0.0, cr_dy, rack_height_at(s, clearance));
  }
  double foundations(double s, double clearance) const {
    return lerp_table(fp, cp_lo, cp_ds, s) + lerp_table(fr, 0.0, cr_dy, rack_height_at(s, clearance));
  }

  // The local pair compliances of the pairs in mesh at one position (nodes
  // c[0..n), out) and the cross compliances of neighbours (cross[j] between
  // pairs j and j + 1: the pairs' coupling of the mesh model,
  // stiffness/pair_coupling.hpp), the contact term at each pair's force
  // under the unworn load sharing (rigid rack body). A force-dependent
  // contact term makes that a fixed point: the term moves with ln(force),
  // so each step shrinks the error by a small factor. It starts from `guess`
  // (the shares extrapolated from the previous positions, which leaves one
  // or two steps to converge) or, without one, from equal shares, and writes
  // the converged shares to `shares`. Each pair's term is its contact law
  // (PairCompliance::contact_law, as in the mesh model): one evaluation of
  // the geometry, then one logarithm per step. As the flanks wear the shares
  // move, and the contact term with them only through that logarithm: it is
  // kept at its unworn value.
  void position_compliances(const double* c, int n, double clearance, const double* guess, double* out,
                            double* cross, double* shares) const {
    std::array<double, 16> teeth{}, zero{}, found{};
    std::array<ContactLaw, 16> law{};
    if (n > static_cast<int>(teeth.size())) throw std::runtime_error("wear: more than 16 pairs in mesh");
    for (int j = 0; j < n; ++j) {
      teeth[j] = teeth_compliance(c[j], clearance);
      law[j] = pair->contact_law(c[j], b, rack_height_at(c[j], clearance));
      shares[j] = guess ? guess[j] : force / n;
      out[j] = teeth[j] + law[j].at(shares[j]);
      cross[j] = 0;
      if (coupled_pairs) {
        found[j] = foundations(c[j], clearance);
        if (j > 0) cross[j - 1] = adjacent_pair_coupling(found[j - 1], found[j], a0);
      }
    }
    if (!pair->contact_depends_on_force() || n == 1) {
      if (n == 1) shares[0] = force;
      return;
    }
    for (int it = 0; it < 8; ++it) {
      share_loads(out, cross, zero.data(), n, force, shares);
      double change = 0;
      for (int j = 0; j < n; ++j) {
        const double cj = teeth[j] + law[j].at(shares[j]);
        change = std::max(change, std::abs(cj - out[j]) / cj);
        out[j] = cj;
      }
      if (change < 1e-9) break;
    }
  }

  // Unilateral load sharing of the n pairs of one position: compliances
  // c[j], neighbour cross compliances x[j] (pairs j, j + 1), gaps e[j].
  // f = C^-1 (delta 1 - e) on the active set, sum f = F, f >= 0; returns
  // delta and writes f. Without coupling the active set is a prefix in the
  // order of increasing gap (exact); with it C is tridiagonal and the pair
  // with the most negative force leaves the active set until none is
  // negative, as the mesh model does.
  static double share_loads(const double* c, const double* x, const double* e, int n, double F, double* f) {
    bool any_cross = false;
    for (int j = 0; j + 1 < n; ++j) any_cross = any_cross || x[j] != 0;
    if (!any_cross) {
      std::array<int, 16> order{};
      for (int j = 0; j < n; ++j) order[j] = j;
      std::sort(order.begin(), order.begin() + n, [&](int p, int q) { return e[p] < e[q]; });
      double delta = 0;
      for (int m = n; m >= 1; --m) {
        double sk = 0, se = 0;
        for (int q = 0; q < m; ++q) {
          const double kk = 1.0 / c[order[q]];
          sk += kk;
          se += e[order[q]] * kk;
        }
        delta = (F + se) / sk;
        if (m == 1 || delta > e[order[m - 1]]) break;
      }
      for (int j = 0; j < n; ++j) f[j] = std::max(delta - e[j], 0.0) / c[j];
      return delta;
    }
    std::array<int, 16> act{};
    int m = n;
    for (int j = 0; j < n; ++j) act[j] = j;
    for (;;) {
      // Tridiagonal in the active order: a neighbour is coupled only when
      // the two pairs are neighbours in mesh. Thomas for C u = 1, C v = e;
      // f = delta u - v with sum f = F.
      std::array<double, 16> sub{}, diag{}, sup{}, u{}, v{};
      for (int a = 0; a < m; ++a) {
        diag[a] = c[act[a]];
        sup[a] = a + 1 < m && act[a + 1] == act[a] + 1 ? x[act[a]] : 0.0;
        sub[a] = a > 0 && act[a] == act[a - 1] + 1 ? x[act[a - 1]] : 0.0;
        u[a] = 1;
        v[a] = e[act[a]];
      }
      for (int a = 1; a < m; ++a) {
        const double w = sub[a] / diag[a - 1];
        diag[a] -= w * sup[a - 1];
        u[a] -= w * u[a - 1];
        v[a] -= w * v[a - 1];
      }
      for (int a = m - 1; a >= 0; --a) {
        if (a + 1 < m) {
          u[a] -= sup[a] * u[a + 1];
          v[a] -= sup[a] * v[a + 1];
        }
        u[a] /= diag[a];
        v[a] /= diag[a];
      }
      double su = 0, sv = 0;
      for (int a = 0; a < m; ++a) {
        su += u[a];
        sv += v[a];
      }
      const double delta = (F + sv) / su;
      int worst = -1;
      double worst_f = 0;
      for (int a = 0; a < m; ++a) {
        const double fa = delta * u[a] - v[a];
        if (fa < worst_f) {
          worst_f = fa;
          worst = a;
        }
      }
      if (worst < 0 || m == 1) {
        for (int j = 0; j < n; ++j) f[j] = 0;
        for (int a = 0; a < m; ++a) f[act[a]] = std::max(delta * u[a] - v[a], 0.0);
        return delta;
      }
      for (int a = worst; a + 1 < m; ++a) act[a] = act[a + 1];
      --m;
    }
  }

  double positions_per_point() const {
    const double n = drive.wear.profile_points;
    return std::min(opt.positions_per_point, std::max(1.0, opt.positions_cap / n));
  }

  // ---------------------------------------------------------------- path --
  Path make_path(double s_start, double eps, double clearance) const {
    Path p;
    p.s_start = s_start;
    p.eps = eps;
    p.clearance = clearance;
    p.N = drive.wear.profile_points;
    p.ds = (s_end - s_start) / (p.N - 1);
    p.s.resize(p.N);
    for (int i = 0; i < p.N; ++i) p.s[i] = i == p.N - 1 ? s_end : s_start + i * p.ds;

    // Zones of one period of the reference pair (phase phi in [0, p_b]):
    // piece A [0, frac p_b] with n+1 pairs, piece B [frac p_b, p_b] with n.
    int n = static_cast<int>(std::floor(eps + 1e-9));
    double frac = eps - n;
    if (frac < 1e-9) frac = 0;
    const double dphi = p.ds / positions_per_point();
    struct Piece {
      double lo, hi;
      int pairs;
    };
    std::vector<Piece> pieces;
    if (frac > 0) pieces.push_back({0.0, frac * pb, n + 1});
    pieces.push_back({frac * pb, pb, n});
    p.pos_begin.push_back(0);
    // The unworn shares of the two previous positions of a piece (the same
    // pairs, moved on by one step), extrapolated linearly as the start of
    // the next position's fixed point.
    std::array<double, 16> shares{}, prev{}, prev2{}, guess{};
    for (const Piece& pc : pieces) {
      const int m = std::max(2, static_cast<int>(std::ceil((pc.hi - pc.lo) / dphi)) + 1);
      const int first_pos = static_cast<int>(p.pos_begin.size()) - 1;
      for (int k = 0; k < m; ++k) {
        const double phi = pc.lo + (pc.hi - pc.lo) * k / (m - 1);
        for (int j = 0; j < pc.pairs; ++j) {
          // Snap to the path end: s_start + eps p_b may miss s_end by rounding.
          double c = s_start + phi + j * pb;
          if (c > s_end - 1e-9 * pb) c = s_end;
          p.node_c.push_back(c);
        }
        p.node_comp.resize(p.node_c.size());
        p.node_cross.resize(p.node_c.size());
        const int a = p.pos_begin.back();
        const int np = std::min(pc.pairs, static_cast<int>(guess.size()));
        for (int j = 0; j < np; ++j) {
          const double g = k >= 2 ? 2 * prev[j] - prev2[j] : prev[j];
          guess[j] = g > 0 ? g : prev[j];
        }
        position_compliances(&p.node_c[a], pc.pairs, clearance, k >= 1 ? guess.data() : nullptr, &p.node_comp[a],
                             &p.node_cross[a], shares.data());
        prev2 = prev;
        prev = shares;
        p.pos_begin.push_back(static_cast<int>(p.node_c.size()));
      }
      for (int j = 0; j < pc.pairs; ++j) {
        std::vector<int> iv;
        for (int k = 0; k < m; ++k) iv.push_back(p.pos_begin[first_pos + k] + j);
        p.intervals.push_back(std::move(iv));
      }
    }
    std::sort(p.intervals.begin(), p.intervals.end(),
              [&](const std::vector<int>& x, const std::vector<int>& y) { return p.node_c[x.front()] < p.node_c[y.front()]; });
    // The band weights' search relies on it (band_weights.hpp).
    if (!load_intervals_sorted(p.node_c, p.intervals))
      throw std::runtime_error("wear: load nodes out of order along the path (internal error)");

    const RackPinionSliding kin(sP, s_floor);
    p.slide[kPinion].resize(p.N);
    p.slide[kRack].resize(p.N);
    for (int i = 0; i < p.N; ++i) {
      p.slide[kPinion][i] = kin.pinion_sliding_ratio(p.s[i]);
      p.slide[kRack][i] = kin.rack_sliding_ratio(p.s[i]);
    }
    return p;
  }

  // The Hertz band's half-width at each point from the unworn pair loads P0
  // (signed margins, solve), frozen while it wears (a depends on sqrt(w)
  // only); zeros without the band.
  std::vector<double> half_widths(const Path& p, const std::vector<double>& P0) const {
    std::vector<double> half_width(p.N, 0.0);
    if (!opt.hertz_band) return half_width;
    std::vector<int> pi;
    std::vector<double> pv;
    for (int i = 0; i < p.N; ++i) {
      const double c = p.s[i];
      pi.clear();
      pv.clear();
      pointwise_weights(p.node_c, p.intervals, c, pi, pv);
      double w0 = 0;
      for (std::size_t k = 0; k < pi.size(); ++k) w0 += pv[k] * P0[pi[k]];
      half_width[i] = hertz_line_contact(std::max(w0, 0.0), std::max(c, s_floor), e_star).half_width;
    }
    return half_width;
  }

  // Where point i of member mb sees the pair loads: the band [c - L, c + L]
  // of LOA coordinates (band), or the pair at c alone (!band: no band, or
  // one too thin). The pinion's band is the exact window on the involute,
  // whose sliding replaces the point's thin-band sliding here.
  struct PointBand {
    bool band = false;
    double c = 0, L = 0;
  };
  PointBand point_band(Path& p, int mb, int i, double a) const {
    const double c = p.s[i];
    if (opt.hertz_band) {
      // Surface distance per unit LOA: rack flank tan a0, pinion involute s/r_b.
      if (mb == kRack) {
        const double L = a / ta;
        if (L > 1e-12 * pb) return {true, c, L};
      } else if (a > 1e-12 * pb) {
        const InvoluteWindow win = involute_band_window(c, a, rb, sP);
        if (win.hi - win.lo > 2e-12 * pb) {
          const double thin = p.slide[kPinion][i];
          if (thin > 0) p.base_circle_window = std::min(p.base_circle_window, win.slide / thin);
          p.slide[kPinion][i] = win.slide;
          return {true, 0.5 * (win.lo + win.hi), 0.5 * (win.hi - win.lo)};
        }
      }
    }
    return {false, c, 0.0};
  }
  static void point_weights(const Path& p, const PointBand& pb_, std::vector<int>& idx, std::vector<double>& val) {
    if (pb_.band) {
      band_weights(p.node_c, p.intervals, pb_.c, pb_.L, idx, val);
    } else {
      pointwise_weights(p.node_c, p.intervals, pb_.c, idx, val);
    }
  }

  // The peak probe: one extra flank point of member mb at an arbitrary LOA
  // coordinate c, with its band from the unworn pair loads P0 (signed
  // margins) as a profile point's (half_widths, point_band), frozen while it
  // wears. Its pass load is sum val * load * slide, like a profile point's.
  struct Probe {
    int mb = -1;
    double c = 0, slide = 0;
    double band_c = 0, band_L = 0;  // as Path::band_c, band_L
    std::vector<int> idx;
    std::vector<double> val;
    double g = 0, h = 0, g_prev = 0, rate = 0;  // as the profile points' g, h, g_prev and rate
  };
  void set_probe(const Path& p, const std::vector<double>& P0, int mb, double c, Probe& pr) const {
    pr.mb = mb;
    pr.c = c;
    pr.idx.clear();
    pr.val.clear();
    const RackPinionSliding kin(sP, s_floor);
    pr.slide = mb == kPinion ? kin.pinion_sliding_ratio(c) : kin.rack_sliding_ratio(c);
    PointBand band{false, c, 0.0};
    if (opt.hertz_band) {
      pointwise_weights(p.node_c, p.intervals, c, pr.idx, pr.val);
      double w0 = 0;
      for (std::size_t k = 0; k < pr.idx.size(); ++k) w0 += pr.val[k] * P0[pr.idx[k]];
      pr.idx.clear();
      pr.val.clear();
      const double a = hertz_line_contact(std::max(w0, 0.0), std::max(c, s_floor), e_star).half_width;
      if (mb == kRack) {
        if (a / ta > 1e-12 * pb) band = {true, c, a / ta};
      } else if (a > 1e-12 * pb) {
        const InvoluteWindow win = involute_band_window(c, a, rb, sP);
        if (win.hi - win.lo > 2e-12 * pb) {
          pr.slide = win.slide;
          band = {true, 0.5 * (win.lo + win.hi), 0.5 * (win.hi - win.lo)};
        }
      }
    }
    pr.band_c = band.c;
    pr.band_L = band.band ? band.L : 0.0;
    point_weights(p, band, pr.idx, pr.val);
  }
  static double probe_pass_load(const Probe& pr, const std::vector<double>& margin) {
    double w = 0;
    for (std::size_t k = 0; k < pr.idx.size(); ++k) w += pr.val[k] * std::max(margin[pr.idx[k]], 0.0);
    return w * pr.slide;
  }
  // Places the probe at the largest unworn pass load of member mb between
  // the profile points around point i (golden-section search; the grid
  // point's own load is the start). The wear rate peaks sharply where the
  // sliding is large and the band meets a load step (the pinion root near
  // the base circle, the single-pair zone's ends): a peak narrower than the
  // point spacing falls between points, and the grid's largest rate is then
  // too small by up to the peak's rise over a spacing, the life too long
  // (docs/models/wear.md, "Default: 240 points").
  void place_probe(const Path& p, const std::vector<double>& P0, int mb, int i, Probe& pr) const {
    double lo = p.s[std::max(i - 1, 0)], hi = p.s[std::min(i + 1, p.N - 1)];
    auto load_at = [&](double c) {
      set_probe(p, P0, mb, c, pr);
      return probe_pass_load(pr, P0);
    };
    double best_c = p.s[i], best = load_at(best_c);
    constexpr double kGolden = 0.6180339887498949;
    double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
    double f1 = load_at(x1), f2 = load_at(x2);
    // 24 steps shrink the bracket to 1e-5 of two spacings.
    for (int it = 0; it < 24; ++it) {
      if (f1 > best) best = f1, best_c = x1;
      if (f2 > best) best = f2, best_c = x2;
      if (f1 >= f2) {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - kGolden * (hi - lo);
        f1 = load_at(x1);
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + kGolden * (hi - lo);
        f2 = load_at(x2);
      }
    }
    if (f1 > best) best = f1, best_c = x1;
    if (f2 > best) best = f2, best_c = x2;
    set_probe(p, P0, mb, best_c, pr);
  }

  // Band-averaging weights of both members from the unworn pair loads P0
  // (signed margins, solve).
  void build_weights(Path& p, const std::vector<double>& P0) const {
    const std::vector<double> half_width = half_widths(p, P0);
    for (int mb = 0; mb < 2; ++mb) {
      auto& beg = p.w_begin[mb];
      auto& idx = p.w_idx[mb];
      auto& val = p.w_val[mb];
      beg.assign(1, 0);
      beg.reserve(p.N + 1);
      idx.clear();
      val.clear();
      // A band spans a few tens of nodes (2 without the band): room for that
      // without regrowing (measured: 8 % of a weight build).
      const std::size_t expect = (opt.hertz_band ? 64 : 2) * static_cast<std::size_t>(p.N);
      idx.reserve(expect);
      val.reserve(expect);
      p.band_c[mb].resize(p.N);
      p.band_L[mb].resize(p.N);
      for (int i = 0; i < p.N; ++i) {
        const PointBand band = point_band(p, mb, i, half_width[i]);
        p.band_c[mb][i] = band.c;
        p.band_L[mb][i] = band.band ? band.L : 0.0;
        p.band_reach[mb] = std::max(p.band_reach[mb], std::abs(band.c - p.s[i]) + p.band_L[mb][i]);
        point_weights(p, band, idx, val);
        beg.push_back(static_cast<int>(idx.size()));
      }
    }
  }

  static double interp_profile(const Path& p, const std::vector<double>& h, double c) {
    double u = (c - p.s_start) / p.ds;
    u = std::clamp(u, 0.0, static_cast<double>(p.N - 1));
    const int k = std::min(static_cast<int>(u), p.N - 2);
    const double f = u - k;
    return h[k] + f * (h[k + 1] - h[k]);
  }

  // Unilateral load sharing at every sampled mesh position (rigid rack body,
  // docs/models/wear.md "Load sharing"; share_loads). Writes each pair's signed margin: its load
  // per width f_j / b where it carries load, and where it is open the
  // (negative) approach it lacks over its compliance,
  // (delta - e_j - sum_k x_jk f_k) / (c_j b) [N/m]. Returns the loaded
  // contact ratio (path length over which a pair carries load / p_b).
  double solve(const Path& p, const std::vector<double>& hp, const std::vector<double>& hr, double F,
               std::vector<double>& margin) const {
    margin.resize(p.node_c.size());
    const int npos = static_cast<int>(p.pos_begin.size()) - 1;
    std::array<double, 16> e{}, f{};
    for (int k = 0; k < npos; ++k) {
      const int a = p.pos_begin[k], n = p.pos_begin[k + 1] - a;
      for (int j = 0; j < n; ++j) {
        const double c = p.node_c[a + j];
        e[j] = interp_profile(p, hp, c) + interp_profile(p, hr, c);
      }
      const double* cj = &p.node_comp[a];
      const double* xj = &p.node_cross[a];
      const double delta = share_loads(cj, xj, e.data(), n, F, f.data());
      for (int j = 0; j < n; ++j) {
        if (f[j] > 0) {
          margin[a + j] = f[j] / b;
          continue;
        }
        double carried = 0;  // how far the loaded neighbours carry this contact
        if (j > 0) carried += xj[j - 1] * f[j - 1];
        if (j + 1 < n) carried += xj[j] * f[j + 1];
        margin[a + j] = (delta - e[j] - carried) / (cj[j] * b);
      }
    }
    double loaded = 0;
    for (const auto& iv : p.intervals) {
      for (std::size_t k = 0; k + 1 < iv.size(); ++k) {
        const double L = p.node_c[iv[k + 1]] - p.node_c[iv[k]];
        const double ma = margin[iv[k]], mb = margin[iv[k + 1]];
        if (ma >= 0 && mb >= 0) {
          loaded += L;
        } else if (ma >= 0) {
          loaded += L * margin_zero(p, iv, k, margin);
        } else if (mb >= 0) {
          loaded += L * (1 - margin_zero(p, iv, k, margin));
        }
      }
    }
    return loaded / pb;
  }

  // Where a pair's signed margin crosses zero between nodes k and k + 1 of
  // its interval (the signs differ), as a fraction of that segment. The
  // margin is continuous there but has a kink at its zero: the loaded and the
  // open pair see different active sets, so the common approach changes its
  // slope. A straight line across the kink puts the zero off by a fraction of
  // the segment that depends on where the kink falls, an error of first
  // order in the node spacing. Each side is smooth up to the kink, so the line
  // through the two nodes of one side, extended to zero, is second order.
  // The two sides' zeros are blended with the weights (1 - t, t), t the
  // straight line's zero: near a node the side of that node decides, and its
  // zero goes to the node as the node's margin goes to zero, so the zero
  // moves continuously from one segment to the next (the contact-ratio
  // criterion's root finding needs that). A side without a second node in
  // its zone uses the straight line.
  static double margin_zero(const Path& p, const std::vector<int>& iv, std::size_t k,
                            const std::vector<double>& margin) {
    const double xa = p.node_c[iv[k]], xb = p.node_c[iv[k + 1]], L = xb - xa;
    const double ma = margin[iv[k]], mb = margin[iv[k + 1]];
    const double across = ma / (ma - mb);
    if (!(L > 0)) return across;
    double left = across, right = across;
    if (k >= 1) {
      const double x = p.node_c[iv[k - 1]], m = margin[iv[k - 1]];
      if ((m >= 0) == (ma >= 0) && m != ma && xa > x) left = std::clamp(-ma * (xa - x) / (ma - m) / L, 0.0, 1.0);
    }
    if (k + 2 < iv.size()) {
      const double x = p.node_c[iv[k + 2]], m = margin[iv[k + 2]];
      if ((m >= 0) == (mb >= 0) && m != mb && x > xb) right = std::clamp(1.0 - mb * (x - xb) / (m - mb) / L, 0.0, 1.0);
    }
    return (1 - across) * left + across * right;
  }

  // <w>_i * sliding ratio for each member and point.
  static void pass_loads(const Path& p, const std::vector<double>& margin, std::array<std::vector<double>, 2>& q) {
    thread_local std::vector<double> load;
    load.resize(margin.size());
    for (std::size_t k = 0; k < margin.size(); ++k) load[k] = std::max(margin[k], 0.0);
    for (int mb = 0; mb < 2; ++mb) {
      q[mb].resize(p.N);
      const int* idx = p.w_idx[mb].data();
      const double* val = p.w_val[mb].data();
      for (int i = 0; i < p.N; ++i) {
        double w = 0;
        for (int k = p.w_begin[mb][i]; k < p.w_begin[mb][i + 1]; ++k) w += val[k] * load[idx[k]];
        q[mb][i] = w * p.slide[mb][i];
      }
    }
  }

  // The pair transitions of the worn flanks, added to the pass loads q (and
  // to the probe's, `probe_q`). On the worn flanks a pair opens or closes
  // between two mesh positions (margin_zero), and every pair of those
  // positions has a kink there: the opening pair's load reaches zero, the
  // others take it over. The straight lines between the load samples cut
  // that corner, and the area they miss, about the load's change times the
  // spacing, lands in the pass loads of the points whose band covers it:
  // an error of first order in the spacing, which the wear then carries
  // into the worn profile and the contact ratio. Each pair's load at the
  // transition is taken from both sides (the line through the two samples of
  // a side, extended; the opening pair: 0), and the difference from the
  // straight line, a hat over the segment with its peak at the transition,
  // is integrated over each point's band exactly like the samples
  // (band_weights on the three nodes of the hat).
  void transition_corrections(const Path& p, const std::vector<double>& margin, std::array<std::vector<double>, 2>& q,
                              const Probe* probe, double* probe_q) const {
    const int npos = static_cast<int>(p.pos_begin.size()) - 1;
    auto pairs_at = [&](int k) { return p.pos_begin[k + 1] - p.pos_begin[k]; };
    auto load = [&](int node) { return std::max(margin[node], 0.0); };
    // The same piece: as many pairs, and the reference pair moved on.
    auto same_piece = [&](int k0, int k1) {
      return k0 >= 0 && k1 < npos && pairs_at(k0) == pairs_at(k1) && p.node_c[p.pos_begin[k0]] < p.node_c[p.pos_begin[k1]];
    };
    thread_local std::vector<int> idx;
    thread_local std::vector<double> val;
    const LoadIntervals hat_iv{{0, 1, 2}};
    std::vector<double> hat_c(3);
    for (const auto& iv : p.intervals) {
      for (std::size_t k = 0; k + 1 < iv.size(); ++k) {
        const double ma = margin[iv[k]], mb_ = margin[iv[k + 1]];
        if ((ma >= 0) == (mb_ >= 0)) continue;
        const double t = margin_zero(p, iv, k, margin);
        const int P = static_cast<int>(std::upper_bound(p.pos_begin.begin(), p.pos_begin.end(), iv[k]) - p.pos_begin.begin()) - 1;
        const int j = iv[k] - p.pos_begin[P];
        if (!same_piece(P, P + 1)) continue;
        for (int jj = 0; jj < pairs_at(P); ++jj) {
          const int na = p.pos_begin[P] + jj, nb = p.pos_begin[P + 1] + jj;
          const double xa = p.node_c[na], xb = p.node_c[nb];
          if (!(xb > xa)) continue;
          const double lin = load(na) + t * (load(nb) - load(na));
          // Blended as margin_zero's sides (the straight line where a side
          // has no second sample), so the correction vanishes as the
          // transition reaches a sample.
          double exact = 0;
          if (jj != j) {
            double left = lin, right = lin;
            if (same_piece(P - 1, P)) {
              const int nl = p.pos_begin[P - 1] + jj;
              left = load(na) + (load(na) - load(nl)) * t * (xb - xa) / (xa - p.node_c[nl]);
            }
            if (same_piece(P + 1, P + 2)) {
              const int nr = p.pos_begin[P + 2] + jj;
              right = load(nb) + (load(nb) - load(nr)) * (1 - t) * (xb - xa) / (p.node_c[nr] - xb);
            }
            exact = std::max((1 - t) * left + t * right, 0.0);
          }
          const double d = exact - lin;
          if (d == 0) continue;
          hat_c = {xa, xa + t * (xb - xa), xb};
          auto hat_weight = [&](double c, double L) {
            if (L > 0) {
              if (c + L <= xa || c - L >= xb) return 0.0;
              idx.clear();
              val.clear();
              band_weights(hat_c, hat_iv, c, L, idx, val);
              double w = 0;
              for (std::size_t m = 0; m < idx.size(); ++m)
                if (idx[m] == 1) w += val[m];
              return w;
            }
            if (c < xa || c > xb) return 0.0;
            return c <= hat_c[1] ? (c - xa) / std::max(hat_c[1] - xa, 1e-300) : (xb - c) / std::max(xb - hat_c[1], 1e-300);
          };
          for (int m = 0; m < 2; ++m) {
            // Only the points whose band can reach the hat (band_reach).
            const double reach = p.band_reach[m] + p.ds;
            const int i0 = std::max(0, static_cast<int>(std::floor((xa - reach - p.s_start) / p.ds)));
            const int i1 = std::min(p.N - 1, static_cast<int>(std::ceil((xb + reach - p.s_start) / p.ds)));
            for (int i = i0; i <= i1; ++i) {
              const double w = hat_weight(p.band_c[m][i], p.band_L[m][i]);
              if (w != 0) q[m][i] = std::max(q[m][i] + w * d * p.slide[m][i], 0.0);
            }
          }
          if (probe && probe->mb >= 0 && probe_q) {
            const double w = hat_weight(probe->band_c, probe->band_L);
            if (w != 0) *probe_q = std::max(*probe_q + w * d * probe->slide, 0.0);
          }
        }
      }
    }
  }

  // The probe's share of transition_corrections (the points' are added
  // where the pass loads are computed).
  void transition_corrections_probe(const Path& p, const std::vector<double>& margin, const Probe& probe,
                                    double& probe_q) const {
    thread_local std::array<std::vector<double>, 2> none;
    none[0].assign(p.N, 0.0);
    none[1].assign(p.N, 0.0);
    transition_corrections(p, margin, none, &probe, &probe_q);
  }

  WearProfile profile(const Path& p, int mb, const std::vector<double>& depth) const {
    WearProfile out;
    out.s = p.s;
    out.depth = depth;
    out.position.resize(p.N);
    out.radius_or_height.resize(p.N);
    const double s0 = std::max(p.s_start, 0.0);
    for (int i = 0; i < p.N; ++i) {
      const double s = p.s[i];
      if (mb == kPinion) {
        const double sc = std::max(s, 0.0);
        out.position[i] = (sc * sc - s0 * s0) / (2 * rb);
        out.radius_or_height[i] = std::sqrt(rb * rb + s * s);
      } else {
        out.position[i] = (s_end - s) * ta;
        out.radius_or_height[i] =
            r * sa * sa - s * sa + drive.pinion.profile_shift * drive.pinion.module + p.clearance;
      }
    }
    return out;
  }

  // Path of a sample; returns false (and fills `why`) when its contact ratio
  // is out of range.
  bool sample_path(const WearSample& smp, double& s_start, double& eps, double& clearance, std::string& criterion,
                   std::string& why) const {
    if (!smp.contact_ratio) {
      s_start = s_start_nom;
      eps = eps_nom;
      clearance = drive.mounting.clearance;
    } else {
      eps = *smp.contact_ratio;
      s_start = s_end - eps * pb;
      clearance = (s_start - sP) * sa - datum_shift;
    }
    const double need = std::max(1.0, min_cr);
    std::ostringstream o;
    if (eps < need) {
      criterion = "initial_contact_ratio";
      o << "the sampled contact ratio " << eps << " is below " << (min_cr > 1 ? "wear.min_contact_ratio " : "")
        << need << ": the drive fails at once";
      why = o.str();
      return false;
    }
    if (eps > eps_max * (1 + 1e-12)) {
      criterion = "contact_ratio_above_max";
      o << "the sampled contact ratio " << eps << " exceeds the largest this pair can have, " << eps_max
        << " (zero clearance" << (drive.effects.interference_limit ? ", interference limit" : "")
        << "): the drive fails at once";
      why = o.str();
      return false;
    }
    return true;
  }

  static void check_sample(const WearSample& s) {
    auto pos = [](double v, const char* key) {
      if (!(v > 0) || !std::isfinite(v)) {
        std::ostringstream o;
        o << "must be positive and finite (got " << v << ")";
        bad(key, o.str());
      }
    };
    pos(s.wear_coefficient_scale, "sample.wear_coefficient_scale");
    pos(s.force_scale, "sample.force_scale");
    pos(s.surface_hardness_scale, "sample.surface_hardness_scale");
    if (s.contact_ratio && !std::isfinite(*s.contact_ratio)) bad("sample.contact_ratio", "must be finite");
  }

  // A life read for its life only, without the profile update, is the
  // first block's: the point with the fewest passes to failure
  // G_total / rate and its two neighbours (the parabola's vertex) decide it.
  // A point's pass load is a weighted mean of the pair loads over its band
  // (non-negative weights that sum to at most one) times its sliding, so
  // the largest load of the nodes whose segments meet the band, times the
  // sliding, bounds it from above, and with it the point's passes to failure
  // from below. The points are taken in the order of that bound and their
  // weights built (the same calls and sums as build_weights and pass_loads)
  // until the bound exceeds the fewest passes found: every point that could
  // have as few then has its exact pass load, the others none (0, which the
  // search skips). The bound carries a margin of 1e-6: the rounding of the
  // weights and of their sum is many orders of magnitude smaller.
  struct BoundedSearch {
    std::array<std::vector<PointBand>, 2> band;
    std::array<std::vector<char>, 2> known;
    std::vector<double> load;
    std::vector<int> idx;
    std::vector<double> val;
  };
  double exact_pass_load(const Path& p, BoundedSearch& bs, int mb, int i) const {
    bs.idx.clear();
    bs.val.clear();
    point_weights(p, bs.band[mb][i], bs.idx, bs.val);
    double w = 0;
    for (std::size_t k = 0; k < bs.idx.size(); ++k) w += bs.val[k] * bs.load[bs.idx[k]];
    bs.known[mb][i] = 1;
    return w * p.slide[mb][i];
  }
  // Fills q (exact where known, else 0) for the first block of a life
  // without update; false when a load is not finite (then nothing is
  // bounded: the caller builds every weight).
  bool bounded_pass_loads(Path& p, const std::vector<double>& margin, double Kk, const std::array<double, 2>& rho,
                          double sig, BoundedSearch& bs, std::array<std::vector<double>, 2>& q) const {
    bs.load.resize(margin.size());
    for (std::size_t k = 0; k < margin.size(); ++k) {
      if (!std::isfinite(margin[k])) return false;
      bs.load[k] = std::max(margin[k], 0.0);
    }
    const std::vector<double> half_width = half_widths(p, margin);
    // Range maxima of the loads along each interval: level l holds the
    // maximum of 2^l consecutive nodes (a sparse table).
    std::vector<std::vector<double>> range_max(p.intervals.size());
    for (std::size_t v = 0; v < p.intervals.size(); ++v) {
      const std::vector<int>& iv = p.intervals[v];
      const int M = static_cast<int>(iv.size());
      int L = 1;
      while ((2 << (L - 1)) <= M) ++L;
      std::vector<double>& t = range_max[v];
      t.resize(static_cast<std::size_t>(L) * M);
      for (int j = 0; j < M; ++j) t[j] = bs.load[iv[j]];
      for (int l = 1; l < L; ++l)
        for (int j = 0; j + (1 << l) <= M; ++j)
          t[l * M + j] = std::max(t[(l - 1) * M + j], t[(l - 1) * M + j + (1 << (l - 1))]);
    }
    // The largest load of the nodes of every segment that can meet [c - L, c + L]
    // (one node more at each end than the segments that do: rounding).
    auto band_max = [&](double c, double L) {
      double mx = 0;
      for (std::size_t v = 0; v < p.intervals.size(); ++v) {
        const std::vector<int>& iv = p.intervals[v];
        if (iv.size() < 2) continue;
        if (p.node_c[iv.back()] <= c - L || p.node_c[iv.front()] >= c + L) continue;  // as band_weights: no weight
        const int M = static_cast<int>(iv.size());
        const auto lo = std::partition_point(iv.begin(), iv.end(), [&](int n) { return p.node_c[n] <= c - L; });
        const auto hi = std::partition_point(lo, iv.end(), [&](int n) { return p.node_c[n] < c + L; });
        const int a = std::max(static_cast<int>(lo - iv.begin()) - 2, 0);
        const int z = std::min(static_cast<int>(hi - iv.begin()) + 1, M - 1);
        const int l = std::bit_width(static_cast<unsigned>(z - a + 1)) - 1;
        const std::vector<double>& t = range_max[v];
        mx = std::max({mx, t[l * M + a], t[l * M + z - (1 << l) + 1]});
      }
      return mx;
    };
    const int N = p.N;
    double fewest = kInf;  // passes to failure, the fewest found
    auto passes = [&](int mb, double qi) {
      const double rt = Kk * qi * rho[mb] / sig;  // as the block loop
      if (rt > 0) fewest = std::min(fewest, G[mb].total() / rt);
    };
    std::vector<std::pair<double, int>> order;
    order.reserve(2 * static_cast<std::size_t>(N));
    for (int mb = 0; mb < 2; ++mb) {
      bs.band[mb].resize(N);
      bs.known[mb].assign(N, 0);
      q[mb].assign(N, 0.0);
      for (int i = 0; i < N; ++i) bs.band[mb][i] = point_band(p, mb, i, half_width[i]);
    }
    for (int mb = 0; mb < 2; ++mb) {
      for (int i = 0; i < N; ++i) {
        const PointBand& band = bs.band[mb][i];
        if (!band.band) {  // two weights: exact at once
          q[mb][i] = exact_pass_load(p, bs, mb, i);
          passes(mb, q[mb][i]);
          continue;
        }
        const double upper = band_max(band.c, band.L) * (1 + 1e-6) * p.slide[mb][i];
        if (!(upper > 0)) continue;  // no load or no sliding: the pass load is 0
        order.emplace_back(G[mb].total() / (Kk * upper * rho[mb] / sig), mb * N + i);
      }
    }
    if (order.empty()) return true;
    // The most promising point first; then only the points whose bound
    // reaches its passes need sorting (a few tens of the 2N).
    const auto first = std::min_element(order.begin(), order.end());
    std::swap(*first, order.front());
    {
      const int mb = order.front().second / N, i = order.front().second % N;
      q[mb][i] = exact_pass_load(p, bs, mb, i);
      passes(mb, q[mb][i]);
    }
    const auto rest = std::partition(order.begin() + 1, order.end(),
                                     [&](const std::pair<double, int>& o) { return !(o.first > fewest); });
    std::sort(order.begin() + 1, rest);
    for (auto it = order.begin() + 1; it != rest; ++it) {
      if (it->first > fewest) break;
      const int mb = it->second / N, i = it->second % N;
      q[mb][i] = exact_pass_load(p, bs, mb, i);
      passes(mb, q[mb][i]);
    }
    return true;
  }

  WearLifeResult life(const WearSample& smp, Detail detail) const;
};

WearLifeResult WearModel::Impl::life(const WearSample& smp, Detail detail) const {
  const bool snapshots = detail == Detail::kFull;
  const auto t0 = std::chrono::steady_clock::now();
  check_sample(smp);
  WearLifeResult res;
  const double F = force * smp.force_scale;
  const double Kk = K * smp.wear_coefficient_scale;
  const double sig = smp.surface_hardness_scale;
  const double hmax = drive.wear.max_depth;
  const double per_year = drive.duty.rack_meshes_per_year;
  const std::array<double, 2> rho{rho_pinion, 1.0};

  double s_start = 0, eps0 = 0, clearance = 0;
  std::string why;
  const bool ok = sample_path(smp, s_start, eps0, clearance, res.criterion, why);
  res.initial_contact_ratio = res.final_contact_ratio = eps0;
  if (!ok) {
    res.reason = why;
    const Path local =
        opt.reuse_nominal_start ? Path{} : make_path(s_start_nom, eps_nom, drive.mounting.clearance);
    const Path& p = opt.reuse_nominal_start ? nominal_start().path : local;
    const std::vector<double> zero(p.N, 0.0);
    res.pinion = profile(p, kPinion, zero);
    res.rack = profile(p, kRack, zero);
    if (snapshots)
      for (double f : kSnapshotFractions) res.snapshots.push_back({f, 0, 0, eps0, res.pinion, res.rack});
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  }

  // The unworn start: the path, its load sharing at F and the band weights
  // (NominalStart: from the model's own when the path is the nominal one).
  const bool nominal_path = !smp.contact_ratio && opt.reuse_nominal_start;
  const bool nominal_force = smp.force_scale == 1;
  const bool update = drive.wear.update_profile;
  const double f_blk = drive.wear.block_fraction;
  Path local;
  std::vector<double> margin;
  // The life alone, without the update: the weights of the points that can
  // decide it only (BoundedSearch), their pass loads in q.
  std::array<std::vector<double>, 2> q, rate, g_prev;
  BoundedSearch bs;
  bool bounded = false;
  // Without the depths the hardness warnings are unknown: bounded only
  // where there can be none.
  const bool may_bound =
      detail == Detail::kLifeOnly && !update && opt.bounded_life_search && hardness_warnings_impossible();
  bool weighted_nominal = false;
  if (nominal_path && nominal_force) {
    margin = nominal_start().margin;
    if (may_bound) {
      local = nominal_start().path;  // a copy: the search sets the pinion's band sliding
      bounded = bounded_pass_loads(local, margin, Kk, rho, sig, bs, q);
    }
    weighted_nominal = !bounded;
  } else {
    local = nominal_path ? nominal_start().path : make_path(s_start, eps0, clearance);
    const std::vector<double> zero(local.N, 0.0);
    solve(local, zero, zero, F, margin);
    bounded = may_bound && bounded_pass_loads(local, margin, Kk, rho, sig, bs, q);
    if (!bounded) build_weights(local, margin);
  }
  const Path& p = weighted_nominal ? nominal_weighted() : local;
  const int N = p.N;
  std::array<std::vector<double>, 2> h{std::vector<double>(N, 0.0), std::vector<double>(N, 0.0)};
  std::array<std::vector<double>, 2> g = h;  // G(h) per point (model hardness units)
  long solves = 1;

  // History at block boundaries for the snapshots (G is linear in n inside a block).
  std::vector<double> hist_n{0.0}, hist_eps{eps0};
  std::vector<double> hist_g;
  auto push_hist = [&](double n, double e) {
    if (!snapshots) return;
    hist_n.push_back(n);
    hist_eps.push_back(e);
    for (int mb = 0; mb < 2; ++mb) hist_g.insert(hist_g.end(), g[mb].begin(), g[mb].end());
  };
  if (snapshots)
    for (int mb = 0; mb < 2; ++mb) hist_g.insert(hist_g.end(), g[mb].begin(), g[mb].end());

  double n = 0, eps = eps0;
  int limiting_member = kRack;
  double limiting_s = 0;  // LOA coordinate of the point that reached its limit
  // The peak probe (place_probe): placed in the first block at the largest
  // unworn pass load next to the point that fails first, then worn like a
  // profile point (it does not enter the load sharing: one point).
  Probe probe;
  const bool heun = opt.heun_blocks;
  std::array<std::vector<double>, 2> h_pred;  // Heun's predicted depths
  std::vector<double> margin_pred;
  const long max_blocks = static_cast<long>(2.0 * N / f_blk) + 10;
  for (long blk = 0;; ++blk) {
    if (blk > max_blocks) throw std::runtime_error("wear: block limit exceeded (internal error)");
    if (!bounded) pass_loads(p, margin, q);
    if (update && opt.transition_corrections) transition_corrections(p, margin, q, nullptr, nullptr);
    // dG/dn per rack pass (G in unscaled hardness units: the sample's G is sig G).
    double n_fail = kInf, n_blk = kInf;
    int fm = -1, fi = -1;
    for (int mb = 0; mb < 2; ++mb) {
      rate[mb].resize(N);
      for (int i = 0; i < N; ++i) {
        const double rt = Kk * q[mb][i] * rho[mb] / sig;
        rate[mb][i] = rt;
        if (!(rt > 0)) continue;
        const double nf = (G[mb].total() - g[mb][i]) / rt;
        if (nf < n_fail) {
          n_fail = nf;
          fm = mb;
          fi = i;
        }
        if (update) n_blk = std::min(n_blk, (G[mb].G(std::min(h[mb][i] + f_blk * hmax, limit[mb])) - g[mb][i]) / rt);
      }
    }
    if (fm < 0) throw DesignError("no_wear", "wear: no point of either flank slides under load");
    if (bounded) {
      for (int i : {fi - 1, fi + 1}) {
        if (i < 0 || i >= N || bs.known[fm][i]) continue;
        q[fm][i] = exact_pass_load(p, bs, fm, i);
        rate[fm][i] = Kk * q[fm][i] * rho[fm] / sig;
      }
    }
    if (blk == 0) place_probe(p, margin, fm, fi, probe);
    {
      double pq = probe_pass_load(probe, margin);
      if (update && opt.transition_corrections) transition_corrections_probe(p, margin, probe, pq);
      probe.rate = Kk * pq * rho[probe.mb] / sig;
    }
    if (update && heun) {
      // Heun's predictor-corrector (the trapezoidal rule in the passes): wear
      // the block's length with the rates of its start, re-solve the load
      // sharing there and wear with the mean of the two rates. With the
      // rates of the start alone the depths lag the unloading of the worn
      // flanks by half a block, an error of first order in block_fraction
      // that the contact-ratio criterion turns into several per cent of the
      // life (docs/models/wear.md, "Progression and failure").
      double n_pred = std::min(n_blk, n_fail);
      if (probe.rate > 0) {
        const int mb = probe.mb;
        n_pred = std::min({n_pred, (G[mb].total() - probe.g) / probe.rate,
                           (G[mb].G(std::min(probe.h + f_blk * hmax, limit[mb])) - probe.g) / probe.rate});
      }
      for (int mb = 0; mb < 2; ++mb) {
        h_pred[mb].resize(N);
        for (int i = 0; i < N; ++i) h_pred[mb][i] = G[mb].inverse_near(g[mb][i] + rate[mb][i] * n_pred, h[mb][i]);
      }
      solve(p, h_pred[kPinion], h_pred[kRack], F, margin_pred);
      ++solves;
      pass_loads(p, margin_pred, q);
      double pq = probe_pass_load(probe, margin_pred);
      if (opt.transition_corrections) transition_corrections(p, margin_pred, q, &probe, &pq);
      n_fail = kInf;
      for (int mb = 0; mb < 2; ++mb)
        for (int i = 0; i < N; ++i) {
          const double rt = 0.5 * (rate[mb][i] + Kk * q[mb][i] * rho[mb] / sig);
          rate[mb][i] = rt;
          if (!(rt > 0)) continue;
          const double nf = (G[mb].total() - g[mb][i]) / rt;
          if (nf < n_fail) {
            n_fail = nf;
            fm = mb;
            fi = i;
          }
        }
      probe.rate = 0.5 * (probe.rate + Kk * pq * rho[probe.mb] / sig);
      n_blk = n_pred;
    }
    const bool near_probe = fm == probe.mb && std::abs(p.s[fi] - probe.c) <= p.ds * (1 + 1e-9);
    // The deepest wear lies between profile points in general: take the
    // vertex of the parabola through the passes-to-failure of the first
    // failing point and its neighbours. Without it the life jumps as the
    // peak moves across the grid (a sample's path, hence its grid, changes
    // with its contact ratio), which shows up as clumps in Monte Carlo
    // lives and a failed goodness-of-fit test.
    if (fi > 0 && fi + 1 < N && rate[fm][fi - 1] > 0 && rate[fm][fi + 1] > 0) {
      const double a = (G[fm].total() - g[fm][fi - 1]) / rate[fm][fi - 1];
      const double c = (G[fm].total() - g[fm][fi + 1]) / rate[fm][fi + 1];
      const double curv = a - 2.0 * n_fail + c;
      // Only a smooth peak: the vertex within half a spacing of the point.
      // At a jump or kink of the wear rate (the pointwise law at a change of
      // the number of pairs) a parabola means nothing and the point stands.
      // Next to the probe the probe stands for the peak (it found it).
      if (curv > 0 && std::abs(a - c) <= curv && !near_probe) n_fail -= (a - c) * (a - c) / (8.0 * curv);
    }
    bool probe_fails = false;
    if (probe.rate > 0) {
      const int mb = probe.mb;
      const double nf = (G[mb].total() - probe.g) / probe.rate;
      if (nf <= n_fail) {
        n_fail = nf;
        probe_fails = true;
      }
      if (update && !heun) n_blk = std::min(n_blk, (G[mb].G(std::min(probe.h + f_blk * hmax, limit[mb])) - probe.g) / probe.rate);
    }
    res.blocks = static_cast<int>(blk + 1);
    if (n_fail <= n_blk) {
      for (int mb = 0; mb < 2 && !bounded; ++mb)  // bounded: no profiles
        for (int i = 0; i < N; ++i) {
          g[mb][i] += rate[mb][i] * n_fail;
          h[mb][i] = G[mb].inverse_near(g[mb][i], h[mb][i]);
        }
      n += n_fail;
      // Finish exactly at the threshold.
      if (probe_fails) {
        probe.g = G[probe.mb].total();
        probe.h = limit[probe.mb];
        limiting_member = probe.mb;
        limiting_s = probe.c;
      } else {
        g[fm][fi] = G[fm].total();
        h[fm][fi] = limit[fm];
        probe.g += probe.rate * n_fail;
        probe.h = G[probe.mb].inverse_near(probe.g, probe.h);
        limiting_member = fm;
        limiting_s = p.s[fi];
      }
      res.criterion = limit_is_case[limiting_member] ? "case_depth" : "max_depth";
      if (update) {
        eps = solve(p, h[kPinion], h[kRack], F, margin);
        ++solves;
      }
      push_hist(n, eps);
      break;
    }
    g_prev = g;  // (buffers reused: no allocation per block)
    for (int mb = 0; mb < 2; ++mb)
      for (int i = 0; i < N; ++i) {
        g[mb][i] += rate[mb][i] * n_blk;
        h[mb][i] = G[mb].inverse_near(g[mb][i], h[mb][i]);
      }
    probe.g_prev = probe.g;
    probe.g += probe.rate * n_blk;
    probe.h = G[probe.mb].inverse_near(probe.g, probe.h);
    const double eps_new = solve(p, h[kPinion], h[kRack], F, margin);
    ++solves;
    if (eps_new < min_cr) {
      // Regula falsi (Illinois) on the fraction t of this block where the
      // loaded contact ratio reaches the allowable value.
      auto state_at = [&](double t) {
        for (int mb = 0; mb < 2; ++mb)
          for (int i = 0; i < N; ++i) {
            g[mb][i] = g_prev[mb][i] + rate[mb][i] * n_blk * t;
            h[mb][i] = G[mb].inverse_near(g[mb][i], h[mb][i]);
          }
        probe.g = probe.g_prev + probe.rate * n_blk * t;
        probe.h = G[probe.mb].inverse_near(probe.g, probe.h);
        ++solves;
        return solve(p, h[kPinion], h[kRack], F, margin) - min_cr;
      };
      double ta_ = 0, fa = eps - min_cr, tb = 1, fb = eps_new - min_cr, t = 1, ft = fb;
      int side = 0;
      for (int it = 0; it < 60 && tb - ta_ > 1e-13; ++it) {
        t = (ta_ * fb - tb * fa) / (fb - fa);
        if (!(t > ta_ && t < tb)) t = 0.5 * (ta_ + tb);
        ft = state_at(t);
        if (std::abs(ft) < 1e-12) break;
        if (ft >= 0) {
          ta_ = t;
          fa = ft;
          if (side == -1) fb *= 0.5;
          side = -1;
        } else {
          tb = t;
          fb = ft;
          if (side == 1) fa *= 0.5;
          side = 1;
        }
      }
      if (ft >= 0 && std::abs(ft) >= 1e-12) ft = state_at(t = tb);  // end on the failed side
      n += n_blk * t;
      eps = ft + min_cr;
      res.criterion = "contact_ratio";
      push_hist(n, eps);
      break;
    }
    n += n_blk;
    eps = eps_new;
    push_hist(n, eps);
  }

  // ------------------------------------------------------------ results --
  res.life_cycles = n;
  res.life_pinion_cycles = n * rho_pinion;
  res.life_years = per_year > 0 ? n / per_year : 0.0;
  res.final_contact_ratio = eps;
  if (!bounded) {  // bounded: the depths were not integrated
    res.pinion = profile(p, kPinion, h[kPinion]);
    res.rack = profile(p, kRack, h[kRack]);
  }
  double best = bounded ? 0 : -1;
  for (int mb = 0; mb < 2 && !bounded; ++mb)
    for (int i = 0; i < N; ++i)
      if (h[mb][i] > best) {
        best = h[mb][i];
        res.max_depth_member = mb == kPinion ? Member::kPinion : Member::kRack;
        res.max_depth_s = p.s[i];
        res.max_depth_position = (mb == kPinion ? res.pinion : res.rack).position[i];
      }
  if (!bounded && probe.h > best) {
    best = probe.h;
    res.max_depth_member = probe.mb == kPinion ? Member::kPinion : Member::kRack;
    res.max_depth_s = probe.c;
    const double s0 = std::max(p.s_start, 0.0), sc = std::max(probe.c, 0.0);
    res.max_depth_position = probe.mb == kPinion ? (sc * sc - s0 * s0) / (2 * rb) : (s_end - probe.c) * ta;
  }
  res.max_depth = best;
  if (res.criterion == "contact_ratio") {
    limiting_member = res.max_depth_member == Member::kPinion ? kPinion : kRack;
  }
  res.limiting_member = limiting_member == kPinion ? Member::kPinion : Member::kRack;
  {
    std::ostringstream o;
    const char* who = limiting_member == kPinion ? "pinion" : "rack";
    if (res.criterion == "contact_ratio") {
      o << "the loaded contact ratio fell to " << eps << " (allowable " << min_cr << ") after " << n
        << " rack passes; deepest wear " << best * 1e3 << " mm on the " << who;
    } else {
      o << "the " << who << " flank wore to " << limit[limiting_member] * 1e3 << " mm"
        << (res.criterion == "case_depth" ? " (the hardened case depth)" : " (wear.max_depth)") << " at s = "
        << limiting_s * 1e3 << " mm after " << n << " rack passes";
    }
    res.reason = o.str();
  }

  // Snapshots at 25/50/75/100 % of the life (none when not asked for).
  // Each snapshot's depths start the next one's cell search (the cell is
  // the same as a search from scratch: same depths, bit for bit); the last
  // snapshot is the final state itself.
  const std::size_t W = 2 * static_cast<std::size_t>(N);
  std::array<std::vector<double>, 2> hs;
  if (snapshots) hs = {std::vector<double>(N, 0.0), std::vector<double>(N, 0.0)};
  for (double frac : std::span(kSnapshotFractions).first(snapshots ? kSnapshotFractions.size() : 0)) {
    const double nt = frac * n;
    std::size_t k = 0;
    while (k + 2 < hist_n.size() && hist_n[k + 1] < nt) ++k;
    const double span = hist_n[k + 1] - hist_n[k];
    const double t = span > 0 ? std::clamp((nt - hist_n[k]) / span, 0.0, 1.0) : 1.0;
    if (frac == 1.0) {
      hs = h;
    } else {
      for (int mb = 0; mb < 2; ++mb)
        for (int i = 0; i < N; ++i) {
          const double g0 = hist_g[k * W + mb * N + i], g1 = hist_g[(k + 1) * W + mb * N + i];
          hs[mb][i] = G[mb].inverse_near(g0 + t * (g1 - g0), hs[mb][i]);
        }
    }
    WearSnapshot sn;
    sn.fraction = frac;
    sn.cycles = nt;
    sn.years = per_year > 0 ? nt / per_year : 0.0;
    sn.contact_ratio = hist_eps[k] + t * (hist_eps[k + 1] - hist_eps[k]);
    sn.pinion = profile(p, kPinion, hs[kPinion]);
    sn.rack = profile(p, kRack, hs[kRack]);
    res.snapshots.push_back(std::move(sn));
  }

  // Warnings.
  for (int mb = 0; mb < 2 && !bounded; ++mb) {
    const double deepest = *std::max_element(h[mb].begin(), h[mb].end());
    const HardnessModel& hm = hardness[mb];
    if (deepest > hm.first_clamped_depth()) {
      std::ostringstream o;
      o << (mb == kPinion ? "wear.pinion_hardness" : "wear.rack_hardness") << ": wear reached "
        << deepest * 1e3 << " mm, beyond the measured hardness data (clamped from "
        << hm.first_clamped_depth() * 1e3 << " mm on to the core hardness " << hm.core() / kPaPerHB << " HB)";
      res.warnings.push_back(o.str());
    }
  }
  if (!(per_year > 0))
    res.warnings.push_back("duty.rack_meshes_per_year not given: life in years not computed (0)");
  if (s_start < s_floor && !opt.hertz_band)
    res.warnings.push_back("path starts at or below the pinion base circle: pinion rolling speed floored at 1e-3 r_b");
  if (p.base_circle_window < 0.9) {
    std::ostringstream o;
    o << "contact starts near the pinion base circle (s = " << s_start * 1e3
      << " mm): the Hertz band reaches across the involute's small curvature radius there; its sliding is "
         "integrated over the band's exact window on the involute, "
      << std::lround(100 * (1 - p.base_circle_window))
      << " % below the thin-band law at the first point (docs/models/wear.md)";
    res.warnings.push_back(o.str());
  }

  res.load_solves = solves;
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

WearModel::WearModel(const Drive& drive, WearOptions options) : impl_(std::make_unique<Impl>(drive, options)) {}
WearModel::~WearModel() = default;
WearModel::WearModel(WearModel&&) noexcept = default;
WearModel& WearModel::operator=(WearModel&&) noexcept = default;

WearLifeResult WearModel::life(const WearSample& sample) const { return impl_->life(sample, Detail::kFull); }
WearLifeResult WearModel::life(const WearSample& sample, Detail detail) const {
  return impl_->life(sample, detail);
}

WearModel::PassWear WearModel::initial_wear_per_pass(const WearSample& smp) const {
  const Impl& m = *impl_;
  Impl::check_sample(smp);
  double s_start = 0, eps = 0, clearance = 0;
  std::string crit, why;
  if (!m.sample_path(smp, s_start, eps, clearance, crit, why)) throw DesignError(crit, why);
  Path p = m.make_path(s_start, eps, clearance);
  const double F = m.force * smp.force_scale;
  std::vector<double> zero(p.N, 0.0), margin;
  PassWear out;
  out.contact_ratio = m.solve(p, zero, zero, F, margin);
  m.build_weights(p, margin);
  std::array<std::vector<double>, 2> q;
  Impl::pass_loads(p, margin, q);
  std::array<std::vector<double>, 2> dh{std::vector<double>(p.N), std::vector<double>(p.N)};
  for (int mb = 0; mb < 2; ++mb)
    for (int i = 0; i < p.N; ++i)
      dh[mb][i] = m.K * smp.wear_coefficient_scale * q[mb][i] /
                  (smp.surface_hardness_scale * m.hardness[mb](0.0));
  out.pinion = m.profile(p, kPinion, dh[kPinion]);
  out.rack = m.profile(p, kRack, dh[kRack]);
  out.load_per_width.resize(p.N);
  for (int i = 0; i < p.N; ++i) out.load_per_width[i] = q[kRack][i] / std::max(p.slide[kRack][i], 1e-300);
  // At the pitch point the sliding ratio is 0: recompute <w> directly there.
  for (int i = 0; i < p.N; ++i) {
    if (p.slide[kRack][i] > 0) continue;
    double w = 0;
    for (int k = p.w_begin[kRack][i]; k < p.w_begin[kRack][i + 1]; ++k)
      w += p.w_val[kRack][k] * std::max(margin[p.w_idx[kRack][k]], 0.0);
    out.load_per_width[i] = w;
  }
  return out;
}

const MeshGeometry& WearModel::geometry() const { return impl_->geo; }
double WearModel::nominal_contact_ratio() const { return impl_->eps_nom; }
double WearModel::max_contact_ratio() const { return impl_->eps_max; }
const std::vector<std::string>& WearModel::warnings() const { return impl_->warnings; }

}  // namespace rackopt
