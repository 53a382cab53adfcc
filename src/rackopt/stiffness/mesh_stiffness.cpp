#include "rackopt/stiffness/mesh_stiffness.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <cmath>
#include <cstdint>
#include <memory>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "rackopt/core/error.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/stiffness/curve_numerics.hpp"
#include "rackopt/stiffness/loaded_contact.hpp"
#include "rackopt/stiffness/pair_compliance.hpp"
#include "rackopt/stiffness/pair_coupling.hpp"
#include "rackopt/stiffness/pinion_tooth.hpp"
#include "rackopt/stiffness/profile_relief.hpp"
#include "rackopt/stiffness/rack_span.hpp"
#include "rackopt/stiffness/rack_tooth.hpp"
#include "rackopt/stiffness/supported_rack.hpp"

namespace rackopt {
namespace {

// A spall mapped onto the geometry of its member.
struct MappedSpall {
  Member member = Member::kPinion;
  int tooth = 0;
  SpallBand band;
  double s_lo = 0, s_hi = 0;  // LOA interval on which the contact lies inside the spall
  double width = 0;
};

// Tooth-level compliance of one pair without the contact term (which
// depends on the effective width and, for Weber-Banaschek, on the pair force).
struct LocalParts {
  PairTeeth teeth;
  ContactLaw contact;     // the local contact term against the pair force
  double contact_at_load = 0;  // contact.at(load.force): every sample starts from it
  double face_width = 0;  // effective contact width (reduced inside a spall)
  bool spalled = false;
};

struct CacheKey {
  std::int64_t s_key;
  int pinion_spall;  // -1 or index of the pinion tooth carrying a spall
  int rack_spall;    // -1 or global rack tooth index carrying a spall
  bool operator==(const CacheKey& o) const {
    return s_key == o.s_key && pinion_spall == o.pinion_spall && rack_spall == o.rack_spall;
  }
};
struct CacheKeyHash {
  std::size_t operator()(const CacheKey& k) const {
    std::uint64_t h = static_cast<std::uint64_t>(k.s_key) * 0x9E3779B97F4A7C15ULL;
    h ^= static_cast<std::uint64_t>(k.pinion_spall + 7) * 0xC2B2AE3D27D4EB4FULL;
    h ^= static_cast<std::uint64_t>(k.rack_spall + 1000003) * 0x165667B19E3779F9ULL;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
// The tooth parts of one curve by position: an open-addressing table of
// indices into chunks of 64 values (which stay put, so a reference handed
// out survives later insertions, as with std::unordered_map). Every pair of
// every sample looks a position up; the map's node allocation and bucket
// arithmetic were 4-6 % of a curve.
class LocalCache {
 public:
  explicit LocalCache(std::size_t expected) {
    std::size_t n = 16;
    while (n < 2 * expected) n *= 2;
    slots_.assign(n, Slot{});
  }
  const LocalParts* find(const CacheKey& key) const {
    for (std::size_t i = home(key);; i = (i + 1) & (slots_.size() - 1)) {
      const Slot& sl = slots_[i];
      if (sl.index < 0) return nullptr;
      if (sl.key == key) return &value(static_cast<std::size_t>(sl.index));
    }
  }
  // key must not be in the table.
  const LocalParts& insert(const CacheKey& key, LocalParts value) {
    if (2 * (count_ + 1) > slots_.size()) grow();
    if (count_ % kChunk == 0) chunks_.push_back(std::make_unique<LocalParts[]>(kChunk));
    LocalParts& stored = this->value(count_);
    stored = std::move(value);
    place(key, static_cast<std::int32_t>(count_));
    ++count_;
    return stored;
  }

 private:
  struct Slot {
    CacheKey key{0, 0, 0};
    std::int32_t index = -1;  // into the chunks; -1: empty
  };
  std::size_t home(const CacheKey& key) const { return CacheKeyHash{}(key) & (slots_.size() - 1); }
  void place(const CacheKey& key, std::int32_t index) {
    std::size_t i = home(key);
    while (slots_[i].index >= 0) i = (i + 1) & (slots_.size() - 1);
    slots_[i] = Slot{key, index};
  }
  void grow() {
    std::vector<Slot> old(2 * slots_.size(), Slot{});
    old.swap(slots_);
    for (const Slot& sl : old) {
      if (sl.index >= 0) place(sl.key, sl.index);
    }
  }
  static constexpr std::size_t kChunk = 64;
  LocalParts& value(std::size_t index) const { return chunks_[index / kChunk][index % kChunk]; }
  std::vector<Slot> slots_;
  std::vector<std::unique_ptr<LocalParts[]>> chunks_;
  std::size_t count_ = 0;
};

// Where the two-pair Newton of the next sample starts: the first pair's
// force at the last one or two samples with the same two pairs in mesh.
// Consecutive samples of a curve are close, so the start extrapolated from
// them is far nearer the solution than the linear solution at half the load
// (about 1e-4 F against 1e-2 F): one or two steps instead of three or four.
// The converged forces then depend on the start in their last bits only.
class LoadShareHint {
 public:
  // A start for the pair on rack tooth `first_rack_tooth` at travel X, or
  // nothing when the last sample had other pairs.
  std::optional<double> start(int first_rack_tooth, double X) const {
    if (count_ == 0 || rack_tooth_ != first_rack_tooth) return std::nullopt;
    if (count_ == 1 || x_[0] == x_[1]) return f1_[0];
    // Linear extrapolation, not beyond twice the last spacing (the extreme
    // refinement and the breakpoints jump about).
    const double h = x_[0] - x_[1], d = X - x_[0];
    if (std::abs(d) > 2.0 * std::abs(h)) return f1_[0];
    return f1_[0] + (f1_[0] - f1_[1]) * (d / h);
  }
  void record(int first_rack_tooth, double X, double f1) {
    if (count_ > 0 && rack_tooth_ == first_rack_tooth) {
      x_[1] = x_[0];
      f1_[1] = f1_[0];
      count_ = 2;
    } else {
      count_ = 1;
    }
    rack_tooth_ = first_rack_tooth;
    x_[0] = X;
    f1_[0] = f1;
  }
  void forget() { count_ = 0; }

 private:
  int rack_tooth_ = 0;
  int count_ = 0;
  std::array<double, 2> x_{}, f1_{};  // the last sample first
};

int floor_div_int(double v) { return static_cast<int>(std::floor(v)); }

// std::llround(v) (halves away from zero) without the library call, for
// |v| < 2^62: v - trunc(v) is exact there. The cache key below is computed
// for every pair of every sample.
std::int64_t round_to_int64(double v) {
  auto t = static_cast<std::int64_t>(v);  // towards zero
  const double frac = v - static_cast<double>(t);
  if (frac >= 0.5) ++t;
  if (frac <= -0.5) --t;
  return t;
}

// A drive built in code skips the loader's check: a rigid mesh has no finite
// stiffness, so refuse it rather than return inf.
const Drive& checked(const Drive& drive) {
  if (!drive.effects.any_compliance()) {
    throw InputError(SourceMark{drive.source_file.empty() ? "<drive>" : drive.source_file, 0, 0}, "effects",
                     "every compliance is switched off: the mesh would be rigid (infinite stiffness)");
  }
  return drive;
}

}  // namespace

struct MeshStiffnessModel::Impl {
  Drive drive;
  MeshGeometry geo;
  std::vector<std::string> warnings;

  PairCompliance pair;
  std::optional<RackSpanCompliance> span_model;
  std::optional<ReliefOnPath> relief;  // only when the drive has a profile relief

  double a0 = 0, ca = 0, sa = 0;
  double pitch = 0, pb = 0, s_p = 0, s_start = 0, s_end = 0;
  double A0 = 0;       // s of the pair on rack tooth 0 at X = 0
  double span = 0;
  double contact_width = 0;
  double neutral_axis_depth = 0;
  double e_at_s0 = 0;
  int z = 0;
  int slots = 1;
  std::vector<MappedSpall> spalls;

  explicit Impl(const Drive& d) : Impl(d, build_mesh_geometry(d)) {}
  Impl(const Drive& d, MeshGeometry g) : drive(d), geo(std::move(g)), pair(checked(d), geo) {
    warnings = geo.warnings;
    warnings.insert(warnings.end(), pair.warnings().begin(), pair.warnings().end());
    const Effects& fx = drive.effects;
    a0 = drive.pinion.pressure_angle;
    ca = std::cos(a0);
    sa = std::sin(a0);
    pitch = M_PI * drive.pinion.module;
    pb = geo.path.base_pitch;
    s_p = geo.path.s_pitch;
    s_start = geo.path.s_start;
    s_end = geo.path.s_end;
    span = drive.rack.span;
    z = drive.pinion.teeth;
    contact_width = pair.contact_width();
    // The beam under the pairs: with effects.supported_rack the section
    // carries its tooth layer (supported_rack.hpp).
    const RackSpec beam = rack_beam(drive);
    neutral_axis_depth = beam.section.neutral_axis_depth;
    // The contact height is affine in s (slope -sin a0): its value at s = 0.
    e_at_s0 = neutral_axis_depth + geo.rack.dedendum + geo.contact_height_above_datum(0.0);
    slots = static_cast<int>(std::floor(geo.path.contact_ratio)) + 1;

    // Rack tooth j has its centre at x_t = offset + j p. Its -x flank carries
    // the contact; solving x_contact(s) = x_t - w(h(s)) for s gives
    // s = cos a0 [x_t - X - p/4 + (x m + Delta) tan a0] + s_P (docs/models/mesh.md).
    const double offset = drive.rack.tooth_offset >= 0 ? drive.rack.tooth_offset : 0.5 * pitch;
    const double shift = drive.pinion.profile_shift * drive.pinion.module + drive.mounting.clearance;
    A0 = ca * (offset - 0.25 * pitch + shift * std::tan(a0)) + s_p;

    if (fx.rack_span != RackSpanModel::kRigid) span_model.emplace(beam, a0, fx);
    if (std::string w = supported_rack_range_warning(drive); !w.empty()) warnings.push_back(std::move(w));
    if (fx.spalling) map_spalls();
    if (ReliefOnPath r(drive, geo); r.any()) relief.emplace(r);
  }

  void map_spalls() {
    const double rb = geo.pinion.base_radius;
    for (const Spall& sp : drive.spalls) {
      MappedSpall m;
      m.member = sp.member;
      m.tooth = sp.tooth;
      m.width = sp.width;
      const std::string label = sp.name.empty() ? std::string("spall") : sp.name;
      if (sp.width >= contact_width) {
        std::ostringstream msg;
        msg << label << ": width " << sp.width * 1e3 << " mm is not less than the face width "
            << contact_width * 1e3 << " mm";
        throw DesignError("spall_too_wide", msg.str());
      }
      if (sp.member == Member::kPinion) {
        if (sp.tooth < 0 || sp.tooth >= z) {
          throw DesignError("spall_off_profile",
                            label + ": pinion tooth " + std::to_string(sp.tooth) + " outside 0.." +
                                std::to_string(z - 1));
        }
        const double r_low_active = geo.pinion_contact_radius(std::max(s_start, 0.0));
        m.band.low = r_low_active + sp.start;
        m.band.high = m.band.low + sp.length;
        const double r_tip = geo.pinion.tip_radius;
        if (sp.start < 0 || m.band.high > r_tip * (1 + 1e-12)) {
          std::ostringstream msg;
          msg << label << ": pinion band " << (m.band.low - r_low_active) * 1e3 << ".."
              << (m.band.high - r_low_active) * 1e3
              << " mm above the start of the active profile leaves the active profile (height "
              << (r_tip - r_low_active) * 1e3 << " mm)";
          throw DesignError("spall_off_profile", msg.str());
        }
        m.band.high = std::min(m.band.high, r_tip);
        m.s_lo = std::sqrt(std::max(m.band.low * m.band.low - rb * rb, 0.0));
        m.s_hi = std::sqrt(std::max(m.band.high * m.band.high - rb * rb, 0.0));
      } else {
        // Rack flank: heights above the root line. Lowest active point meets the pinion tip.
        const double ded = geo.rack.dedendum;
        const double y_low_active = ded + geo.contact_height_above_datum(s_end);
        const double y_high_active = ded + geo.contact_height_above_datum(s_start);
        m.band.low = y_low_active + sp.start;
        m.band.high = m.band.low + sp.length;
        if (sp.start < 0 || m.band.high > y_high_active * (1 + 1e-12)) {
          std::ostringstream msg;
          msg << label << ": rack band " << sp.start * 1e3 << ".." << (sp.start + sp.length) * 1e3
              << " mm above the lowest active point leaves the active flank (height "
              << (y_high_active - y_low_active) * 1e3 << " mm)";
          throw DesignError("spall_off_profile", msg.str());
        }
        m.band.high = std::min(m.band.high, y_high_active);
        // y(s) decreases with s.
        m.s_hi = s_of_rack_height(m.band.low);
        m.s_lo = s_of_rack_height(m.band.high);
      }
      m.band.width = sp.width;
      m.band.depth = sp.depth;
      spalls.push_back(m);
      // Let the tooth models check depth against the local thickness now,
      // rather than in the middle of a curve.
      if (m.member == Member::kPinion && pair.pinion_tooth()) {
        (void)pair.pinion_tooth()->at(s_end, &spalls.back().band);
      }
      if (m.member == Member::kRack && pair.rack_tooth()) {
        (void)pair.rack_tooth()->at(s_start, &spalls.back().band);
      }
    }
  }

  double s_of_rack_height(double y_above_root) const {
    const double h = y_above_root - geo.rack.dedendum;  // above datum
    const double r = geo.pinion.pitch_radius;
    return (r * sa * sa + geo.profile_shift_length + geo.clearance - h) / sa;
  }

  // j mod z in 0..z-1 (one integer division, not two: per pair and sample).
  int pinion_tooth_of(int rack_j) const {
    const int r = rack_j % z;
    return r < 0 ? r + z : r;
  }

  const MappedSpall* spall_for(Member member, int tooth) const {
    for (const MappedSpall& m : spalls) {
      if (m.member == member && m.tooth == tooth) return &m;
    }
    return nullptr;
  }

  // Tooth parts at LOA coordinate s for the pair (pinion tooth i, rack tooth j).
  LocalParts local_parts(double s, int i, int j) const {
    LocalParts out;
    out.face_width = contact_width;
    const MappedSpall* ps = spalls.empty() ? nullptr : spall_for(Member::kPinion, i);
    const MappedSpall* rs = spalls.empty() ? nullptr : spall_for(Member::kRack, j);
    double lost_width = 0;
    if (ps && s >= ps->s_lo && s <= ps->s_hi) lost_width = std::max(lost_width, ps->width);
    if (rs && s >= rs->s_lo && s <= rs->s_hi) lost_width = std::max(lost_width, rs->width);
    out.face_width = contact_width - lost_width;
    out.spalled = lost_width > 0;
    out.teeth = pair.teeth(s, ps ? &ps->band : nullptr, rs ? &rs->band : nullptr, out.face_width);
    out.contact = pair.contact_law(s, out.face_width);
    out.contact_at_load = out.contact.at(drive.load.force);
    if ((ps || rs) && !out.spalled) {
      const PairTeeth healthy = pair.teeth(s, nullptr, nullptr, out.face_width);
      out.spalled = healthy.pinion.total() != out.teeth.pinion.total() ||
                    healthy.rack.total() != out.teeth.rack.total();
    }
    return out;
  }

  const LocalParts& cached_parts(LocalCache& cache, double s, int i, int j) const {
    const bool ps = !spalls.empty() && spall_for(Member::kPinion, i) != nullptr;
    const bool rs = !spalls.empty() && spall_for(Member::kRack, j) != nullptr;
    // Samples on the uniform grid land on s = A0 + k pb/N up to rounding; a
    // key on a 1e-9 p_b grid merges those and nothing physically distinct.
    const double grid = s / (pb * 1e-9);
    const std::int64_t s_key =
        std::abs(grid) < 0x1p62 ? round_to_int64(grid) : static_cast<std::int64_t>(std::llround(grid));
    CacheKey key{s_key, ps ? i : -1, rs ? j : -1};
    if (const LocalParts* hit = cache.find(key)) return *hit;
    return cache.insert(key, local_parts(s, i, j));
  }

  // Whether adjacent pairs load each other beyond the rack beam
  // (effects.pair_coupling; not in the papers' per-pair method).
  bool coupled_pairs() const { return pairs_coupled(drive.effects); }

  // Off-diagonal compliance between pairs j and k: the rack beam's
  // influence (coupled body, same segment) plus the pairs' own coupling
  // through the foundations of adjacent teeth (pair_coupling.hpp).
  double cross_compliance(const PairState& pj, const PairState& pk) const {
    double c = 0;
    if (drive.effects.rack_span == RackSpanModel::kCoupled && span_model && pj.segment == pk.segment) {
      c += span_model->influence(pj.a, pj.e, pk.a, pk.e);
    }
    if (coupled_pairs() && std::abs(pj.rack_tooth - pk.rack_tooth) == 1) {
      c += adjacent_pair_coupling(pj.fillet + pj.rack_foundation, pk.fillet + pk.rack_foundation, a0);
    }
    return c;
  }

  // s of the pair on rack tooth j at travel X.
  double s_of(int j, double X) const { return A0 + j * pb - X * ca; }
  // Rack-fixed abscissa of that contact.
  double x_of(int j, double X) const { return X + (s_of(j, X) - s_p) * ca; }

  // Pairs in mesh at X (membership decided at X + side*eps so that the left
  // and right limits at a discontinuity can both be asked for).
  template <class Parts>
  MeshState state(double X, int side, Parts&& parts_of, LoadShareHint* hint = nullptr) const {
    MeshState st;
    st.pairs.reserve(static_cast<std::size_t>(slots) + 1);
    state_into(st, X, side, parts_of, hint);
    return st;
  }

  // The same into `st`, whose pairs' storage is reused: a curve computes
  // every sample into one scratch state and so allocates nothing per sample
  // once the scratch holds the most pairs in mesh.
  template <class Parts>
  void state_into(MeshState& st, double X, int side, Parts&& parts_of, LoadShareHint* hint = nullptr) const {
    st.travel = X;
    st.stiffness = 0;
    st.approach = 0;
    st.local_stiffness = 0;
    std::array<ContactLaw, 2> law2{};
    const double eps_x = 1e-9 * pitch;
    const double xm = X + (side < 0 ? -eps_x : eps_x);
    const int j_lo = static_cast<int>(std::ceil((s_start + xm * ca - A0) / pb));
    const int j_hi = static_cast<int>(std::floor((s_end + xm * ca - A0) / pb));
    const double rb_tol = 1e-12 * pb;
    // The pairs already in `st` are overwritten field by field: resize()
    // value-initialises only pairs it adds (the storage of a reused scratch
    // state mostly has them), and building each pair apart and copying it
    // in stalled on the copy's loads (both were the sample assembly's
    // slowest instructions).
    static_assert(sizeof(PairState) == 168, "write every field of PairState below");
    st.pairs.resize(static_cast<std::size_t>(std::max(j_hi - j_lo + 1, 0)));
    std::size_t k = 0;
    for (int j = j_hi; j >= j_lo; --j, ++k) {  // descending s: the pair nearest the pinion tip first
      PairState& p = st.pairs[k];
      p.rack_tooth = j;
      p.pinion_tooth = pinion_tooth_of(j);
      p.slot = j % slots;
      if (p.slot < 0) p.slot += slots;
      p.s = std::clamp(std::clamp(s_of(j, X), s_start - rb_tol, s_end + rb_tol), s_start, s_end);
      p.x = x_of(j, X);
      p.segment = floor_div_int(x_of(j, xm) / span);
      p.a = std::clamp(p.x - p.segment * span, 0.0, span);
      p.e = e_at_s0 - p.s * sa;  // neutral_axis_depth + h_f2 + contact height above the datum
      const LocalParts& lp = parts_of(p.s, p.pinion_tooth, j);
      p.pinion = lp.teeth.pinion;
      p.fillet = lp.teeth.fillet;
      p.hertz = lp.contact_at_load;
      p.rack = lp.teeth.rack;
      p.rack_foundation = lp.teeth.rack_foundation;
      p.body = 0;
      p.spalled = lp.spalled;
      p.relief = relief ? relief->at(p.s) : 0.0;
      p.load_share = 0;
      p.stiffness_share = 0;
      if (k < 2) law2[k] = lp.contact;
    }
    if (pair.contact_depends_on_force() && st.pairs.size() == 2 && st.pairs[0].relief <= 0 &&
        st.pairs[1].relief <= 0 && two_pairs_load_dependent(st, law2, hint)) {
      return;
    }
    if (hint) hint->forget();
    solve(st);
    if (pair.contact_depends_on_force() && st.pairs.size() > 1) load_dependent_contact(st, parts_of);
  }

  // The double-pair zone with a load-dependent contact term and no relief
  // gap, the common case of every curve: the same fixed point as
  // load_dependent_contact, solved as one equation in the first pair's
  // force. With d_j(f) = (a_j + c_j(f)) f the approach of pair j alone (a_j
  // its force-independent compliance, body included) and x the pairs' cross
  // compliance, both pairs see the same approach when
  //   g(f1) = d_1(f1) - d_2(F - f1) + x (F - 2 f1) = 0,
  // and g rises with f1 (g' = t_1 + t_2 - 2x, the tangent compliances, > 0
  // for a positive definite pair). g(0) >= 0 means the first pair opens,
  // g(F) <= 0 the second. Newton from the linear solution, kept inside its
  // bracket, or from the hint's extrapolation of the previous samples. Returns
  // false (the caller takes the general path) when the pair matrix is not
  // positive definite.
  bool two_pairs_load_dependent(MeshState& st, const std::array<ContactLaw, 2>& law, LoadShareHint* hint) const {
    PairState& p1 = st.pairs[0];
    PairState& p2 = st.pairs[1];
    const double F = drive.load.force;
    const bool rigid = drive.effects.rack_span == RackSpanModel::kRigid || !span_model;
    p1.body = rigid ? 0.0 : span_model->self(p1.a, p1.e);
    p2.body = rigid ? 0.0 : span_model->self(p2.a, p2.e);
    const double x = cross_compliance(p1, p2);
    const double a1 = p1.local() - p1.hertz + p1.body, a2 = p2.local() - p2.hertz + p2.body;
    // state() left each contact term at the whole force F.
    const double c1F = p1.hertz, c2F = p2.hertz;
    // g(0) = x F - d_2(F), g(F) = d_1(F) - x F.
    const double g0 = x * F - (a2 + c2F) * F, gF = (a1 + c1F) * F - x * F;
    if (!(gF > g0)) return false;
    double f1;
    // The last terms evaluated and their forces (none yet: NaN).
    double f1_known = std::numeric_limits<double>::quiet_NaN(), c1_known = 0, c2_known = 0;
    if (g0 >= 0) {
      f1 = 0;
    } else if (gF <= 0) {
      f1 = F;
    } else {
      const std::optional<double> warm = hint ? hint->start(p1.rack_tooth, st.travel) : std::nullopt;
      if (warm && *warm > 0 && *warm < F) {
        f1 = *warm;
      } else {
        // Start: the linear solution with each term at half the load, which
        // the law puts ln 2 times its slope above the term at F.
        const double c1 = a1 + c1F + law[0].slope_at(0.5 * F) * std::numbers::ln2;
        const double c2 = a2 + c2F + law[1].slope_at(0.5 * F) * std::numbers::ln2;
        const double den = c1 + c2 - 2 * x;
        if (!(den > 0)) return false;
        f1 = std::clamp(F * (c2 - x) / den, 0.0, F);
      }
      double lo = 0, hi = F;
      for (int it = 0; it < 60; ++it) {
        const double f2 = F - f1;
        // Floored below law.floor; after the first step from the last terms.
        const double c1f = it == 0 ? law[0].at(f1) : law[0].at_near(f1, f1_known, c1_known);
        const double c2f = it == 0 ? law[1].at(f2) : law[1].at_near(f2, F - f1_known, c2_known);
        f1_known = f1;
        c1_known = c1f;
        c2_known = c2f;
        const double gv = (a1 + c1f) * f1 - (a2 + c2f) * f2 + x * (F - 2 * f1);
        if (gv < 0) lo = f1;
        else hi = f1;
        const double s1 = law[0].slope_at(f1), s2 = law[1].slope_at(f2);
        const double slope = a1 + c1f - s1 + a2 + c2f - s2 - 2 * x;
        const bool newton = slope > 0;
        double next = newton ? f1 - gv / slope : 0.5 * (lo + hi);
        const bool in_bracket = next >= lo && next <= hi;
        if (!in_bracket) next = 0.5 * (lo + hi);  // keep the bracket
        const double step = std::abs(next - f1);
        f1 = next;
        // Newton's error squares each step: a step of 1e-9 F leaves about
        // 1e-18 F (as load_dependent_contact). Sooner: the error after a
        // Newton step is about |g''| / (2 g') step^2, with g'' = -s_1/f_1 +
        // s_2/f_2; once that is below 1e-18 F the next step would not move
        // f1 (saves the step that only confirmed convergence).
        if (step <= 1e-9 * F) break;
        // (|s_2 f_1 - s_1 f_2| / (f_1 f_2) written without its divisions.)
        if (newton && in_bracket &&
            std::abs(s2 * f1_known - s1 * f2) * step * step <= 2e-18 * F * slope * f1_known * f2) {
          break;
        }
      }
    }
    const double f2 = F - f1;
    if (f1 > 0 && f1 < F) {
      p1.hertz = law[0].at_near(f1, f1_known, c1_known);
      p2.hertz = law[1].at_near(f2, F - f1_known, c2_known);
      if (hint) hint->record(p1.rack_tooth, st.travel, f1);
    } else {
      p1.hertz = law[0].at(f1);
      p2.hertz = law[1].at(f2);
      if (hint) hint->forget();
    }
    // The common approach, from the loaded pair(s).
    const double approach = f1 > 0 ? (a1 + p1.hertz) * f1 + x * f2 : (a2 + p2.hertz) * f2 + x * f1;
    if (!(approach > 0) || !std::isfinite(approach)) return false;
    st.approach = approach;
    st.stiffness = F / approach;
    p1.load_share = f1 / F;
    p2.load_share = f2 / F;
    p1.stiffness_share = p1.load_share;  // no relief here: the secant shares
    p2.stiffness_share = p2.load_share;
    st.local_stiffness = 1.0 / p1.local() + 1.0 / p2.local();
    return true;
  }

  // The contact term depends on each pair's force, and the forces on the
  // contact terms. Newton on the pair forces: the approach of pair j's
  // contact, f c_j(f) with c_j = A_j - B_j ln f, is linearised at the current
  // f_j as (c_j - B_j) f + B_j f_j, which is the loaded-contact problem with
  // compliances c_j - B_j and gaps B_j f_j (plus any relief); it converges
  // quadratically, in 2-4 solves. At the solution the last linearised
  // solve is the secant one: K = F / approach. With relief the loaded state
  // is solved once more with the secant terms at the final forces, for its
  // tangent stiffness (solve_relieved).
  template <class Parts>
  void load_dependent_contact(MeshState& st, Parts&& parts_of) const {
    const std::size_t n = st.pairs.size();
    const double F = drive.load.force;
    std::array<double, 64> C{};
    std::array<double, 8> gap{}, f{};
    std::array<ContactLaw, 8> law{};
    if (n > 8) throw std::runtime_error("more than 8 pairs in mesh: not supported");
    for (std::size_t j = 0; j < n; ++j) {
      f[j] = F * st.pairs[j].load_share;
      law[j] = parts_of(st.pairs[j].s, st.pairs[j].pinion_tooth, st.pairs[j].rack_tooth).contact;
    }
    // The body's coupling does not change with the forces: once.
    for (std::size_t j = 0; j < n; ++j) {
      const PairState& pj = st.pairs[j];
      for (std::size_t k = j + 1; k < n; ++k) {
        const double ck = cross_compliance(pj, st.pairs[k]);
        C[j * n + k] = ck;
        C[k * n + j] = ck;
      }
    }
    using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 8, 8>;
    using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 8, 1>;
    double approach = 0;
    for (int it = 0; it < 12; ++it) {
      for (std::size_t j = 0; j < n; ++j) {
        const PairState& pj = st.pairs[j];
        const double slope = law[j].slope_at(f[j]);
        C[j * n + j] = pj.local() - pj.hertz + law[j].at(f[j]) - slope + pj.body;
        gap[j] = pj.relief + slope * f[j];
      }
      // Every pair loaded (the usual case): two solves with one
      // factorisation, f = delta u - v with (C) u = 1, (C) v = gap and
      // sum f = F. A pair that would pull goes to the unilateral solver.
      Mat M(n, n);
      Vec g(n);
      for (std::size_t a = 0; a < n; ++a) {
        g[a] = gap[a];
        for (std::size_t b = 0; b < n; ++b) M(a, b) = C[a * n + b];
      }
      const Eigen::LLT<Mat> llt(M);
      std::array<double, 8> next{};
      bool all_loaded = llt.info() == Eigen::Success;
      double delta = 0;
      if (all_loaded) {
        const Vec u = llt.solve(Vec::Ones(n)), v = llt.solve(g);
        delta = (F + v.sum()) / u.sum();
        for (std::size_t a = 0; a < n; ++a) {
          next[a] = delta * u[a] - v[a];
          all_loaded = all_loaded && next[a] >= 0 && std::isfinite(next[a]);
        }
      }
      if (!all_loaded) {
        LoadedContact lc;
        try {
          lc = solve_loaded_contact(std::span<const double>(C.data(), n * n), std::span<const double>(gap.data(), n), F);
        } catch (const std::runtime_error&) {
          throw std::runtime_error("mesh flexibility matrix is not positive definite at X = " +
                                   std::to_string(st.travel));
        }
        for (std::size_t a = 0; a < n; ++a) next[a] = lc.force[a];
        delta = lc.approach;
      }
      double change = 0;
      for (std::size_t a = 0; a < n; ++a) {
        change = std::max(change, std::abs(next[a] - f[a]));
        f[a] = next[a];
      }
      approach = delta;
      // Newton's error squares each step: a step that moved the forces by
      // 1e-9 F leaves them about 1e-18 F from the solution.
      if (change <= 1e-9 * F) break;
    }
    for (std::size_t j = 0; j < n; ++j) st.pairs[j].hertz = law[j].at(f[j]);
    if (relief) {
      solve(st);  // the loaded state's tangent stiffness
      return;
    }
    // At the fixed point the last linearised solve is the secant one: its
    // approach carries F, and the forces are the shares.
    st.stiffness = F / approach;
    st.approach = approach;
    st.local_stiffness = 0;
    for (std::size_t j = 0; j < n; ++j) {
      st.pairs[j].load_share = f[j] / F;
      st.pairs[j].stiffness_share = st.pairs[j].load_share;
      st.local_stiffness += 1.0 / st.pairs[j].local();
    }
  }

  void solve(MeshState& st) const {
    // Also fills each pair's body compliance, which solve_relieved reads.
    solve_without_relief(st);
    // Without relief the loaded solution is the linear one: delta = F/K.
    if (st.stiffness > 0) st.approach = drive.load.force / st.stiffness;
    if (relief) {
      for (const PairState& p : st.pairs) {
        if (p.relief > 0) {
          solve_relieved(st);
          break;
        }
      }
    }
  }

  // Pairs with relief: the loaded solution of (C + diag c) f = delta 1 - e,
  // f >= 0, sum f = F on the same compliance matrix as solve_without_relief.
  void solve_relieved(MeshState& st) const {
    const std::size_t n = st.pairs.size();
    std::vector<double> C(n * n, 0.0), gap(n);
    const bool coupled = drive.effects.rack_span == RackSpanModel::kCoupled && span_model;
    for (std::size_t j = 0; j < n; ++j) {
      const PairState& pj = st.pairs[j];
      gap[j] = pj.relief;
      C[j * n + j] = pj.local() + pj.body;
      if (!coupled && !coupled_pairs()) continue;
      for (std::size_t k = j + 1; k < n; ++k) {
        const double c = cross_compliance(pj, st.pairs[k]);
        C[j * n + k] = c;
        C[k * n + j] = c;
      }
    }
    const double F = drive.load.force;
    LoadedContact lc;
    try {
      lc = solve_loaded_contact(C, gap, F);
    } catch (const std::runtime_error&) {
      throw std::runtime_error("mesh flexibility matrix is not positive definite at X = " +
                               std::to_string(st.travel));
    }
    st.stiffness = lc.tangent_stiffness;
    st.approach = lc.approach;
    // The rigid-body reference counts the same pairs as K: those that carry load.
    st.local_stiffness = 0;
    for (std::size_t j = 0; j < n; ++j) {
      st.pairs[j].load_share = F > 0 ? lc.force[j] / F : 0.0;
      st.pairs[j].stiffness_share = 0;
      if (lc.loaded[j]) st.local_stiffness += 1.0 / st.pairs[j].local();
    }
    // Each loaded pair's part of the tangent stiffness, u = C_A^-1 1 on the
    // loaded set A (the forces are f = delta u - C_A^-1 e there, so
    // sum_A u_i (delta - e_i) = F with C symmetric).
    using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 8, 8>;
    using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 8, 1>;
    std::array<std::size_t, 8> active{};
    std::size_t m = 0;
    for (std::size_t j = 0; j < n && m < 8; ++j) {
      if (lc.loaded[j]) active[m++] = j;
    }
    if (m > 0 && st.stiffness > 0) {
      Mat CA(m, m);
      for (std::size_t a = 0; a < m; ++a) {
        for (std::size_t b = 0; b < m; ++b) CA(a, b) = C[active[a] * n + active[b]];
      }
      const Vec u = CA.llt().solve(Vec::Ones(m));
      for (std::size_t a = 0; a < m; ++a) st.pairs[active[a]].stiffness_share = u[a] / st.stiffness;
    }
  }

  void solve_without_relief(MeshState& st) const {
    const std::size_t n = st.pairs.size();
    st.local_stiffness = 0;
    for (const PairState& p : st.pairs) st.local_stiffness += 1.0 / p.local();
    if (n == 0) {
      st.stiffness = 0;
      return;
    }
    const RackSpanModel mode = drive.effects.rack_span;
    const bool rigid = mode == RackSpanModel::kRigid || !span_model;
    if (rigid && (n == 1 || !coupled_pairs())) {
      for (PairState& p : st.pairs) {
        p.body = 0;
        p.load_share = (1.0 / p.local()) / st.local_stiffness;
        p.stiffness_share = p.load_share;
      }
      st.stiffness = st.local_stiffness;
      return;
    }
    for (PairState& p : st.pairs) p.body = rigid ? 0.0 : span_model->self(p.a, p.e);
    if (mode == RackSpanModel::kPerPair) {
      // The rack railway paper: the body compliance inside each pair, pairs in parallel.
      double k = 0;
      for (const PairState& p : st.pairs) k += 1.0 / (p.local() + p.body);
      for (PairState& p : st.pairs) p.stiffness_share = p.load_share = (1.0 / (p.local() + p.body)) / k;
      st.stiffness = k;
      return;
    }
    if (n == 1) {
      // One pair in mesh (every single-pair zone): K = 1 / c, correctly
      // rounded. (The Cholesky solve below gives (1 / sqrt(c)) / sqrt(c),
      // within an ulp of it, through a square root and a second dependent
      // division.)
      PairState& p = st.pairs[0];
      const double c = p.local() + p.body;
      if (c > 0) {
        const double K = 1.0 / c;
        if (K > 0 && std::isfinite(K)) {
          st.stiffness = K;
          p.load_share = 1.0;
          p.stiffness_share = 1.0;
          return;
        }
      }
    }
    // One beam shared by all pairs, and the pairs' own coupling:
    // C = diag(c_j) + C_b + C_pairs; K = 1^T C^-1 1.
    // Contact is unilateral (docs/models/mesh.md): the beam can carry a contact
    // away from the pinion faster than the common approach, and that pair
    // then opens. Solve on the active set, dropping the most negative share
    // until all shares are >= 0 (at most n - 1 drops; one pair always stays).
    using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 8, 8>;
    using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 8, 1>;
    if (n > 8) throw std::runtime_error("more than 8 pairs in mesh: not supported");
    Mat C_full(n, n);
    for (std::size_t j = 0; j < n; ++j) {
      const PairState& pj = st.pairs[j];
      C_full(j, j) = pj.local() + pj.body;
      for (std::size_t k = j + 1; k < n; ++k) {
        const double c = cross_compliance(pj, st.pairs[k]);
        C_full(j, k) = c;
        C_full(k, j) = c;
      }
    }
    std::array<std::size_t, 8> active{};
    std::size_t m = n;
    for (std::size_t j = 0; j < n; ++j) active[j] = j;
    for (;;) {
      Mat C(m, m);
      for (std::size_t a = 0; a < m; ++a) {
        for (std::size_t b = 0; b < m; ++b) C(a, b) = C_full(active[a], active[b]);
      }
      const Vec f = C.llt().solve(Vec::Ones(m));
      const double K = f.sum();
      if (!(K > 0) || !std::isfinite(K)) {
        throw std::runtime_error("mesh flexibility matrix is not positive definite at X = " +
                                 std::to_string(st.travel));
      }
      std::size_t worst = m;
      for (std::size_t a = 0; a < m; ++a) {
        if (f[a] < -1e-14 * K && (worst == m || f[a] < f[worst])) worst = a;
      }
      if (worst == m || m == 1) {
        st.stiffness = K;
        for (PairState& p : st.pairs) p.stiffness_share = p.load_share = 0;
        for (std::size_t a = 0; a < m; ++a) {
          PairState& p = st.pairs[active[a]];
          p.stiffness_share = p.load_share = std::max(f[a], 0.0) / K;
        }
        return;
      }
      for (std::size_t a = worst; a + 1 < m; ++a) active[a] = active[a + 1];
      --m;
    }
  }

  std::vector<double> breakpoints(double lo, double hi) const {
    std::vector<double> out;
    const int j_lo = static_cast<int>(std::floor((s_start + lo * ca - A0) / pb)) - 1;
    const int j_hi = static_cast<int>(std::ceil((s_end + hi * ca - A0) / pb)) + 1;
    const double tol = 1e-12 * std::max(span, pitch);
    auto in_range = [&](double X) { return X >= lo - tol && X <= hi + tol; };
    for (int j = j_lo; j <= j_hi; ++j) {
      // Pair j enters/leaves where s_j = s_start or s_end.
      for (double s_lim : {s_start, s_end}) {
        const double X = (A0 + j * pb - s_lim) / ca;
        if (in_range(X)) out.push_back(std::clamp(X, lo, hi));
      }
      // Pair j crosses a support where x_j = k * span, while in mesh.
      if (span_model) {
        const double x_lo = x_of(j, lo), x_hi = x_of(j, hi);
        const int k_lo = static_cast<int>(std::ceil(std::min(x_lo, x_hi) / span - 1e-12));
        const int k_hi = static_cast<int>(std::floor(std::max(x_lo, x_hi) / span + 1e-12));
        for (int k = k_lo; k <= k_hi; ++k) {
          // x_j(X) = X sin^2 a0 + (A_j - s_P) cos a0.
          const double X = (k * span - (A0 + j * pb - s_p) * ca) / (sa * sa);
          if (!in_range(X)) continue;
          const double s = s_of(j, X);
          if (s >= s_start - tol && s <= s_end + tol) out.push_back(std::clamp(X, lo, hi));
        }
      }
    }
    std::sort(out.begin(), out.end());
    std::vector<double> unique;
    for (double X : out) {
      if (unique.empty() || X - unique.back() > 1e-9 * pitch) unique.push_back(X);
    }
    return unique;
  }
};

MeshStiffnessModel::MeshStiffnessModel(const Drive& drive) : impl_(std::make_unique<Impl>(drive)) {}
MeshStiffnessModel::MeshStiffnessModel(const Drive& drive, MeshGeometry geometry)
    : impl_(std::make_unique<Impl>(drive, std::move(geometry))) {}
MeshStiffnessModel::~MeshStiffnessModel() = default;
MeshStiffnessModel::MeshStiffnessModel(MeshStiffnessModel&&) noexcept = default;
MeshStiffnessModel& MeshStiffnessModel::operator=(MeshStiffnessModel&&) noexcept = default;

const Drive& MeshStiffnessModel::drive() const { return impl_->drive; }
const MeshGeometry& MeshStiffnessModel::geometry() const { return impl_->geo; }
const std::vector<std::string>& MeshStiffnessModel::warnings() const { return impl_->warnings; }

MeshState MeshStiffnessModel::at(double travel, int side) const {
  const Impl& im = *impl_;
  return im.state(
      travel, side, [&](double s, int i, int j) { return im.local_parts(s, i, j); });
}

double MeshStiffnessModel::stiffness(double travel, int side) const { return at(travel, side).stiffness; }

std::vector<double> MeshStiffnessModel::breakpoints(double lo, double hi) const {
  return impl_->breakpoints(lo, hi);
}

StiffnessCurve MeshStiffnessModel::curve(CurveDetail detail, int positions_per_period) const {
  const Impl& im = *impl_;
  StiffnessCurve out;
  out.warnings = im.warnings;
  out.max_pairs = im.slots;
  const double l = im.span;
  if (positions_per_period != 0 && (positions_per_period < kPositionsPerPeriodLimit.lo ||
                                    positions_per_period > kPositionsPerPeriodLimit.hi))
    throw std::invalid_argument("curve: positions_per_period must be 0 (the drive's) or " +
                                range_text(kPositionsPerPeriodLimit) + ", got " + std::to_string(positions_per_period));
  const int N = positions_per_period > 0 ? positions_per_period : im.drive.numerics.positions_per_period;
  const double dX = im.pitch / N;
  LocalCache cache(static_cast<std::size_t>(4 * N + 64));
  auto parts = [&](double s, int i, int j) -> const LocalParts& { return im.cached_parts(cache, s, i, j); };

  out.breakpoints = im.breakpoints(0.0, l);
  // Interior discontinuities give two samples (left and right limit); the
  // span ends give one each.
  struct Probe {
    double X;
    int side;
  };
  std::vector<Probe> probes;
  const int n_uniform = static_cast<int>(std::floor(l / dX + 1e-9));
  probes.reserve(static_cast<std::size_t>(n_uniform) + 2 * out.breakpoints.size() + 4);
  const double tol = 1e-9 * im.pitch;
  // Asked in increasing X: a cursor instead of a binary search per probe
  // (the first breakpoint >= X - tol, as std::lower_bound would find).
  auto next_break = out.breakpoints.begin();
  auto near_break = [&](double X) {
    while (next_break != out.breakpoints.end() && *next_break < X - tol) ++next_break;
    return next_break != out.breakpoints.end() && *next_break <= X + tol;
  };
  for (int i = 0; i <= n_uniform; ++i) {
    const double X = std::min(i * dX, l);
    if (!near_break(X)) probes.push_back({X, X >= l - tol ? -1 : +1});
  }
  if (l - n_uniform * dX > tol && !near_break(l)) probes.push_back({l, -1});
  // The uniform probes and those at the (sorted, distinct) breakpoints are
  // each in order already: merge them (sorting the whole list cost 9 % of a
  // curve).
  std::vector<Probe> at_breaks;
  at_breaks.reserve(2 * out.breakpoints.size());
  for (double xb : out.breakpoints) {
    if (xb > tol) at_breaks.push_back({xb, -1});
    if (xb < l - tol) at_breaks.push_back({xb, +1});
  }
  const auto probe_less = [](const Probe& a, const Probe& c) {
    return a.X < c.X || (a.X == c.X && a.side < c.side);
  };
  {
    std::vector<Probe> merged(probes.size() + at_breaks.size());
    std::merge(probes.begin(), probes.end(), at_breaks.begin(), at_breaks.end(), merged.begin(), probe_less);
    probes = std::move(merged);
  }

  // One scratch state for every evaluation of this curve (its pairs'
  // storage is reused). With relief the bisection below compares the pairs
  // of neighbouring samples, so those keep them until the end.
  MeshState scratch;
  scratch.pairs.reserve(static_cast<std::size_t>(im.slots) + 1);
  const bool keep_pairs = detail == CurveDetail::kFull || im.relief;
  out.samples.reserve(probes.size());
  // The same hints in both details, so that they keep the same values.
  LoadShareHint sweep;
  for (const Probe& pr : probes) {
    // Computed in the sample itself with the scratch's pairs lent to it
    // and taken back: copying the sample's values out of the scratch
    // stalled on loads of what the solve had just stored.
    MeshState& sample = out.samples.emplace_back();
    sample.pairs.swap(scratch.pairs);
    im.state_into(sample, pr.X, pr.side, parts, &sweep);
    sample.pairs.swap(scratch.pairs);
    // A kept sample's pairs in storage of their own size: room for the most
    // pairs in mesh plus one in every sample tripled a long curve's memory.
    if (keep_pairs) sample.pairs.assign(scratch.pairs.begin(), scratch.pairs.end());
  }

  if (im.relief) {
    // With relief the tangent stiffness jumps where a relieved pair starts or
    // stops carrying load (delta only has a kink there). Those positions
    // depend on the solution: bisect each sample interval whose loaded set
    // changes down to the break tolerance and add both limits, so extremes
    // and mean stay exact as at the geometric breakpoints.
    auto loaded_set = [](const MeshState& st) {
      std::vector<std::pair<int, bool>> out_set;
      for (const PairState& p : st.pairs) out_set.emplace_back(p.rack_tooth, p.load_share > 0);
      return out_set;
    };
    auto same_pairs = [](const MeshState& a, const MeshState& b) {
      if (a.pairs.size() != b.pairs.size()) return false;
      for (std::size_t k = 0; k < a.pairs.size(); ++k) {
        if (a.pairs[k].rack_tooth != b.pairs[k].rack_tooth) return false;
      }
      return true;
    };
    std::vector<Probe> extra_probes;
    std::vector<MeshState> extra_samples;
    for (std::size_t i = 0; i + 1 < out.samples.size(); ++i) {
      if (probes[i + 1].X - probes[i].X <= tol || !same_pairs(out.samples[i], out.samples[i + 1])) continue;
      const auto right_set = loaded_set(out.samples[i + 1]);
      double lo = probes[i].X;
      auto lo_set = loaded_set(out.samples[i]);
      // Each pass finds the first switch in (lo, right end); more than one
      // switch between two samples is handled by the next pass.
      for (int pass = 0; pass < 8 && lo_set != right_set; ++pass) {
        double hi = probes[i + 1].X;
        std::optional<MeshState> lo_state, hi_state;
        while (hi - lo > 0.5 * tol) {
          const double mid = 0.5 * (lo + hi);
          MeshState m = im.state(mid, 0, parts);
          if (loaded_set(m) == lo_set) {
            lo = mid;
            lo_state = std::move(m);
          } else {
            hi = mid;
            hi_state = std::move(m);
          }
        }
        // A limit that stayed on a sample is that sample: mark it instead of
        // adding a second sample at the same travel.
        if (lo_state) {
          extra_probes.push_back({lo, -1});
          extra_samples.push_back(*lo_state);
        } else if (lo == probes[i].X) {
          probes[i].side = -1;
        }
        if (hi_state) {
          extra_probes.push_back({hi, +1});
          extra_samples.push_back(*hi_state);
          lo_set = loaded_set(*hi_state);
        } else {
          lo_set = right_set;  // the switch sits just before sample i + 1
        }
        out.breakpoints.push_back(0.5 * (lo + hi));
        lo = hi;
      }
    }
    if (!extra_probes.empty()) {
      std::vector<std::size_t> order(probes.size() + extra_probes.size());
      std::vector<Probe> all_probes = probes;
      all_probes.insert(all_probes.end(), extra_probes.begin(), extra_probes.end());
      std::vector<MeshState> all_samples = std::move(out.samples);
      for (MeshState& st : extra_samples) all_samples.push_back(std::move(st));
      for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) {
        return all_probes[a].X < all_probes[c].X;
      });
      probes.clear();
      out.samples.clear();
      for (std::size_t k : order) {
        probes.push_back(all_probes[k]);
        out.samples.push_back(std::move(all_samples[k]));
      }
      std::sort(out.breakpoints.begin(), out.breakpoints.end());
    }
  }

  // Smooth pieces: a left-limit sample closes a piece.
  const std::size_t n = out.samples.size();
  std::vector<int> piece(n, 0);
  for (std::size_t i = 1; i < n; ++i) {
    const bool split = probes[i - 1].side < 0 && probes[i].X - probes[i - 1].X <= tol;
    piece[i] = piece[i - 1] + (split ? 1 : 0);
  }

  // Mean: piecewise cubic interpolation within each smooth piece.
  double integral = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (piece[i] != piece[i + 1]) continue;
    double xs[4], ys[4];
    int m = 0;
    const std::size_t first = (i > 0 && piece[i - 1] == piece[i]) ? i - 1 : i;
    const std::size_t last = (i + 2 < n && piece[i + 2] == piece[i]) ? i + 2 : i + 1;
    for (std::size_t k = first; k <= last; ++k) {
      xs[m] = out.samples[k].travel;
      ys[m] = out.samples[k].stiffness;
      ++m;
    }
    integral += interval_integral(xs, ys, m, out.samples[i].travel, out.samples[i + 1].travel);
  }
  out.k_mean = integral / l;

  // Min and max: every one-sided limit is a sample; interior extrema are refined.
  std::size_t i_min = 0, i_max = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (out.samples[i].stiffness < out.samples[i_min].stiffness) i_min = i;
    if (out.samples[i].stiffness > out.samples[i_max].stiffness) i_max = i;
  }
  out.k_min = out.samples[i_min].stiffness;
  out.travel_at_min = out.samples[i_min].travel;
  out.k_max = out.samples[i_max].stiffness;
  out.travel_at_max = out.samples[i_max].travel;
  LoadShareHint refine;
  auto k_at = [&](double X) {
    im.state_into(scratch, X, 0, parts, &refine);
    return scratch.stiffness;
  };
  const double x_tol = 1e-7 * im.pitch;
  auto refine_min = [&](double lo, double hi) {
    auto [x, k] = golden_min(k_at, lo, hi, x_tol);
    if (k < out.k_min) {
      out.k_min = k;
      out.travel_at_min = x;
    }
  };
  auto refine_max = [&](double lo, double hi) {
    auto [x, k] = golden_min([&](double X) { return -k_at(X); }, lo, hi, x_tol);
    if (-k > out.k_max) {
      out.k_max = -k;
      out.travel_at_max = x;
    }
  };
  // Candidates are those whose sampled value is close to the current extreme.
  const auto near_min = [&](double k) { return k <= out.k_min * (1 + 1e-3); };
  const auto near_max = [&](double k) { return k >= out.k_max * (1 - 1e-3); };
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (piece[i - 1] != piece[i] || piece[i + 1] != piece[i]) continue;
    const double k0 = out.samples[i - 1].stiffness, k1 = out.samples[i].stiffness,
                 k2 = out.samples[i + 1].stiffness;
    const double lo = out.samples[i - 1].travel, hi = out.samples[i + 1].travel;
    if (k1 <= k0 && k1 <= k2 && near_min(k1)) refine_min(lo, hi);
    if (k1 >= k0 && k1 >= k2 && near_max(k1)) refine_max(lo, hi);
  }
  // An extreme between a piece's end and its next sample has no sampled
  // local extreme around it: right after a second pair enters, the
  // stiffness may rise for a fraction of a sample step and then fall, so
  // the end's limit is the largest sample while the peak lies inside. The
  // parabola through the end and its two neighbours in the piece tells:
  // its slope at the end pointing into the piece towards larger values
  // (smaller, for the minimum) while the next sample is not larger means
  // an interior peak in the first step. A piece of two samples has no such
  // neighbours; its midpoint tells instead.
  std::size_t first = 0;
  while (first < n) {
    std::size_t last = first;
    while (last + 1 < n && piece[last + 1] == piece[first]) ++last;
    if (last == first + 1) {
      const double x0 = out.samples[first].travel, x1 = out.samples[last].travel;
      const double k0 = out.samples[first].stiffness, k1 = out.samples[last].stiffness;
      if (x1 > x0 && (near_min(std::min(k0, k1)) || near_max(std::max(k0, k1)))) {
        const double km = k_at(0.5 * (x0 + x1));
        if (km < std::min(k0, k1) && near_min(km)) refine_min(x0, x1);
        if (km > std::max(k0, k1) && near_max(km)) refine_max(x0, x1);
      }
    } else if (last >= first + 2) {
      for (const bool at_start : {true, false}) {
        const std::size_t e = at_start ? first : last, a = at_start ? first + 1 : last - 1,
                          b = at_start ? first + 2 : last - 2;
        const double xe = out.samples[e].travel, xa = out.samples[a].travel, xb = out.samples[b].travel;
        const double ke = out.samples[e].stiffness, ka = out.samples[a].stiffness, kb = out.samples[b].stiffness;
        if (xa == xe || xb == xa) continue;
        // Slope of the parabola at the end, measured into the piece.
        const double s_ea = (ka - ke) / (xa - xe), s_ab = (kb - ka) / (xb - xa);
        const double curvature = (s_ab - s_ea) / (xb - xe);
        const double slope_in = (s_ea - curvature * (xa - xe)) * (at_start ? 1.0 : -1.0);
        const double lo = std::min(xe, xa), hi = std::max(xe, xa);
        if (slope_in > 0 && ka <= ke && near_max(ke)) refine_max(lo, hi);
        if (slope_in < 0 && ka >= ke && near_min(ke)) refine_min(lo, hi);
      }
    }
    first = last + 1;
  }
  out.k_fluctuation = out.k_mean > 0 ? (out.k_max - out.k_min) / out.k_mean : 0.0;
  if (detail == CurveDetail::kSummary && im.relief) {
    for (MeshState& st : out.samples) std::vector<PairState>().swap(st.pairs);
  }
  return out;
}

}  // namespace rackopt
