// The time stepper of the drive dynamics (docs/models/dynamics.md, "Numerics").
#include "rackopt/dynamics/drive_stepper.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace rackopt::detail {
namespace {

// A step may not exceed this many steps per excitation period: beyond it
// the speed is too low for a dynamic analysis to mean anything (the
// response is the static one) and the work would look like a hang.
constexpr double kMaxStepsPerPeriod = 2e7;

void fail(const std::string& m) { throw std::invalid_argument(m); }

// Interval for the end of a step at X: the left limit at a jump.
int end_interval(const MeshForceLaw& law, double X) {
  int i = interval_of(law, X, -1);
  while (i > 0 && law.travel[i] >= X) --i;
  return i;
}

// Cubic Hermite of a quantity with values y0, y1 and slopes (per step) s0, s1 at fraction t.
double hermite(double y0, double y1, double s0, double s1, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * s0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * s1;
}

}  // namespace

DriveStepper::DriveStepper(const DriveTrain& train, const MeshForceLaw& law, double speed, double static_force,
                           const DynamicsOptions& o)
    : law_(law) {
  law.validate();
  if (!(std::isfinite(speed) && speed > 0)) fail("speed must be finite and > 0 [m/s]");
  if (!(std::isfinite(static_force) && static_force >= 0)) fail("static_force must be finite and >= 0 [N]");
  if (!(std::isfinite(o.damping_ratio) && o.damping_ratio >= 0)) fail("damping_ratio must be finite and >= 0");
  if (o.steps_per_mesh_period < 1) fail("steps_per_mesh_period must be >= 1");
  if (o.steps_per_natural_period < 1) fail("steps_per_natural_period must be >= 1");
  if (!(std::isfinite(o.periodic_tolerance) && o.periodic_tolerance > 0)) fail("periodic_tolerance must be > 0");
  if (o.max_periods < 1) fail("max_periods must be >= 1");
  if (o.history_points < 2) fail("history_points must be >= 2");
  const ReducedSystem r = reduce(train);
  n_ = train.degrees_of_freedom();
  rb_ = train.base_radius;
  speed_ = speed;
  fs_ = static_force;
  period_s_ = law.period / speed;
  const Eigen::MatrixXd G = r.mass.inverse();
  g00_ = G(0, 0);
  if (n_ == 2) {
    g01_ = G(0, 1);
    g11_ = G(1, 1);
    kd_ = train.drive_stiffness;
    // Critical damping of the drive spring on its own mass (the mesh free).
    cd_ = 2 * o.damping_ratio * std::sqrt(kd_ / g11_);
  }
  const double k_mean = law.mean_stiffness();
  cm_ = 2 * o.damping_ratio * std::sqrt(k_mean * r.mesh_mass);
  omega_max_ = 2 * M_PI * natural_frequencies_hz(train, k_mean).back();
  d_scale_ = static_force > 0 ? static_force / k_mean : 1e-6 * law.mesh_pitch;
  double max_gap = 0;
  for (double g : law.gap) max_gap = std::max(max_gap, g);
  limit_ = 1e3 * d_scale_ + max_gap + (std::isfinite(law.backlash) ? law.backlash : 0.0);

  // Uniform steps, plus every jump of the law as a step boundary so that no
  // step straddles a discontinuity of the stiffness (RK4 keeps its order).
  const double want = std::max(o.steps_per_mesh_period * law.period / law.mesh_pitch,
                               o.steps_per_natural_period * omega_max_ / (2 * M_PI) * period_s_);
  if (!(want <= kMaxStepsPerPeriod))
    fail("speed: " + std::to_string(speed) + " m/s needs " + std::to_string(want) +
         " time steps per excitation period (limit 2e7); the response at this speed is the static one");
  const int N = std::max(1, static_cast<int>(std::ceil(want)));
  // (travel, is a jump): a uniform point within rounding of a jump becomes
  // the jump itself, so the step after it starts on the jump's right limit
  // (a point one ulp short of it would read the left limit and cost RK4 its
  // order at every tooth change).
  std::vector<std::pair<double, bool>> grid;
  grid.reserve(N + 1 + law.travel.size() / 2);
  for (int i = 0; i <= N; ++i) grid.emplace_back(i == N ? law.period : law.period * i / N, false);
  for (size_t i = 0; i + 1 < law.travel.size(); ++i)
    if (law.travel[i] == law.travel[i + 1]) grid.emplace_back(law.travel[i], true);
  std::sort(grid.begin(), grid.end());
  const double eps = 1e-9 * law.period / N;
  for (const auto& [x, jump] : grid) {
    if (grid_.empty() || x - grid_.back() > eps) {
      grid_.push_back(x);
    } else if (jump && grid_.size() > 1) {
      grid_.back() = x;
    }
  }
  if (grid_.back() < law.period) grid_.back() = law.period;

  // Slots at each stage point of each step (start, middle, end).
  const int S = steps();
  off_.reserve(3 * S + 1);
  off_.assign(1, 0);
  k_.reserve(3 * S * law.slots);
  g_.reserve(3 * S * law.slots);
  idx_.reserve(3 * S * law.slots);
  kt_.resize(3 * S);
  ds_.resize(3 * S);
  MeshAt m;
  int hint = -1;
  for (int s = 0; s < S; ++s) {
    const double xa = grid_[s], xb = grid_[s + 1], xm = 0.5 * (xa + xb);
    for (int j = 0; j < 3; ++j) {
      const double x = j == 0 ? xa : (j == 1 ? xm : xb);
      const int i = j == 2 ? end_interval(law, x) : (hint = interval_of(law, x, hint));
      slots_at(law, x, i, m);
      k_.insert(k_.end(), m.k.begin(), m.k.end());
      g_.insert(g_.end(), m.g.begin(), m.g.end());
      idx_.insert(idx_.end(), m.idx.begin(), m.idx.end());
      off_.push_back(static_cast<int>(k_.size()));
      const int p = 3 * s + j;
      if (m.k.empty()) fail("mesh force law: no slot touches at travel " + std::to_string(x));
      ds_[p] = m.view().approach(fs_, &kt_[p]);
    }
  }
}

double DriveStepper::total_force(const SlotsView& s, double delta, double rate) const {
  bool t;
  const double fe = s.front(delta, t);
  if (t) return std::max(0.0, fe + cm_ * rate);
  if (std::isfinite(law_.backlash)) {
    const double fb = s.back(delta, law_.backlash, t);
    if (t) return std::min(0.0, -fb + cm_ * rate);
  }
  return 0;
}

double DriveStepper::mesh_force(double X, double delta, double rate) const {
  MeshAt m;
  slots_at(law_, X, interval_of(law_, X, -1), m);
  return total_force(m.view(), delta, rate);
}

void DriveStepper::deriv(const SlotsView& s, const State& z, State& dz) const {
  const double q0 = fs_ - total_force(s, z[0], z[2]);
  if (n_ == 1) {
    dz = {z[2], 0, g00_ * q0, 0};
    return;
  }
  const double q1 = rb_ * fs_ - kd_ * z[1] - cd_ * z[3];
  dz = {z[2], z[3], g00_ * q0 + g01_ * q1, g01_ * q0 + g11_ * q1};
}

State DriveStepper::rk4(const State& z, double h, const SlotsView& a, const SlotsView& m,
                        const SlotsView& b) const {
  State k1, k2, k3, k4, t;
  deriv(a, z, k1);
  for (int i = 0; i < 4; ++i) t[i] = z[i] + 0.5 * h * k1[i];
  deriv(m, t, k2);
  for (int i = 0; i < 4; ++i) t[i] = z[i] + 0.5 * h * k2[i];
  deriv(m, t, k3);
  for (int i = 0; i < 4; ++i) t[i] = z[i] + h * k3[i];
  deriv(b, t, k4);
  State out;
  for (int i = 0; i < 4; ++i) out[i] = z[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  return out;
}

double DriveStepper::crossing(const SlotsView& a, const SlotsView& b, const State& z0, const State& z1,
                              double h) const {
  State d0, d1;
  deriv(a, z0, d0);
  deriv(b, z1, d1);
  auto delta = [&](double t) { return hermite(z0[0], z1[0], h * z0[2], h * z1[2], t); };
  auto rate = [&](double t) { return hermite(z0[2], z1[2], h * d0[2], h * d1[2], t); };
  // Slots at both ends (matched by index) with their gap linear over the step.
  struct Pair { double ka, kb, ga, gb; };
  Pair pairs[32];
  int np = 0;
  for (int i = 0, j = 0; (i < a.n || j < b.n) && np < 32;) {
    if (j >= b.n || (i < a.n && a.idx[i] < b.idx[j])) { pairs[np++] = {a.k[i], 0, a.g[i], a.g[i]}; ++i; }
    else if (i >= a.n || b.idx[j] < a.idx[i]) { pairs[np++] = {0, b.k[j], b.g[j], b.g[j]}; ++j; }
    else { pairs[np++] = {a.k[i], b.k[j], a.g[i], b.g[j]}; ++i; ++j; }
  }
  const double bl = law_.backlash;
  // The switching functions: each slot closing (front and back), and the
  // contact force (elastic + damping) reaching zero while touching.
  const int nf = 2 * np + 1;
  auto fn = [&](int f, double t) {
    const double d = delta(t);
    if (f < 2 * np) {
      const Pair& p = pairs[f / 2];
      const double g = (1 - t) * p.ga + t * p.gb;
      return f % 2 == 0 ? d - g : -d - bl - g;
    }
    double fe = 0, fb = 0;
    bool front = false, back = false;
    for (int i = 0; i < np; ++i) {
      const Pair& p = pairs[i];
      const double k = (1 - t) * p.ka + t * p.kb, g = (1 - t) * p.ga + t * p.gb;
      if (k <= 0) continue;
      if (d > g) { fe += k * (d - g); front = true; }
      else if (-d - bl - g > 0) { fb += k * (-d - bl - g); back = true; }
    }
    if (front) return fe + cm_ * rate(t);
    if (back) return -(-fb + cm_ * rate(t));  // positive while the back flank pushes
    return 0.0;
  };
  double best = -1;
  for (int f = 0; f < nf; ++f) {
    if (f < 2 * np && f % 2 == 1 && !std::isfinite(bl)) continue;
    double t0 = 0, t1 = 1, v0 = fn(f, 0), v1 = fn(f, 1);
    if (f == 2 * np) {
      // Separation: the force reached zero while the same flank touched at both ends.
      if (!(v0 > 0 && v1 <= 0)) continue;
    } else if ((v0 > 0) == (v1 > 0)) {
      continue;
    }
    // Illinois regula falsi on the Hermite interpolant.
    int side = 0;
    for (int it = 0; it < 40 && t1 - t0 > 1e-10; ++it) {
      const double t = (t0 * v1 - t1 * v0) / (v1 - v0);
      const double v = fn(f, t);
      if ((v > 0) == (v0 > 0)) {
        t0 = t; v0 = v;
        if (side == -1) v1 *= 0.5;
        side = -1;
      } else {
        t1 = t; v1 = v;
        if (side == 1) v0 *= 0.5;
        side = 1;
      }
    }
    const double t = t1;  // just past the switch
    if (best < 0 || t < best) best = t;
  }
  return best;
}

void DriveStepper::substep(State& z, double xa, double xb, int depth, std::vector<Sample>* record,
                           PeriodOutcome& out, const SlotsView* cached) const {
  const double h = (xb - xa) / speed_;
  // Split steps interpolate the law at their own travels, into per-depth
  // scratch kept across calls (no allocation per event once warm).
  thread_local MeshAt scratch[5][3];
  SlotsView a, m, b;
  if (cached) {
    a = cached[0]; m = cached[1]; b = cached[2];
  } else {
    MeshAt& ma = scratch[depth][0];
    MeshAt& mm = scratch[depth][1];
    MeshAt& mb = scratch[depth][2];
    const double xm = 0.5 * (xa + xb);
    slots_at(law_, xa, interval_of(law_, xa, -1), ma);
    slots_at(law_, xm, interval_of(law_, xm, -1), mm);
    slots_at(law_, xb, end_interval(law_, xb), mb);
    a = ma.view(); m = mm.view(); b = mb.view();
  }
  const State z1 = rk4(z, h, a, m, b);
  if (!std::isfinite(z1[0]) || !std::isfinite(z1[2]) || std::abs(z1[0]) > limit_) {
    out.unbounded = true;
    z = z1;
    return;
  }
  if (depth < 4 && signature(a, z) != signature(b, z1)) {
    const double t = crossing(a, b, z, z1, h);
    if (t > 1e-6 && t < 1 - 1e-6) {
      const double xc = xa + t * (xb - xa);
      substep(z, xa, xc, depth + 1, record, out, nullptr);
      if (!out.unbounded) substep(z, xc, xb, depth + 1, record, out, nullptr);
      return;
    }
  }
  if (record) record->push_back({xb, z1[0], z1[2], 0.0});
  z = z1;
}

std::uint64_t DriveStepper::signature(const SlotsView& s, const State& z) const {
  // Bit per law slot: front closed (low half), back closed (high half); bit
  // 63: the contact force is positive while a flank touches.
  std::uint64_t sig = 0;
  bool front = false, back = false;
  double fe = 0, fb = 0;
  const double d = z[0], bl = law_.backlash;
  for (int i = 0; i < s.n; ++i) {
    const int j = s.idx[i] % 31;
    if (d > s.g[i]) { sig |= std::uint64_t{1} << j; front = true; fe += s.k[i] * (d - s.g[i]); }
    else if (-d - bl - s.g[i] > 0) { sig |= std::uint64_t{1} << (31 + j); back = true; fb += s.k[i] * (-d - bl - s.g[i]); }
  }
  if ((front && fe + cm_ * z[2] > 0) || (!front && back && -fb + cm_ * z[2] < 0)) sig |= std::uint64_t{1} << 63;
  return sig;
}

void DriveStepper::analyze(std::vector<Sample>& rec, PeriodOutcome& out) const {
  // Force at each recorded point; a step between switches has one contact
  // state, which its middle (cubic Hermite in delta) tells.
  MeshAt m;
  int hint = -1;
  for (size_t i = 0; i < rec.size(); ++i) {
    Sample& s = rec[i];
    const double x = std::min(s.x, std::nextafter(law_.period, 0.0));
    slots_at(law_, x, hint = interval_of(law_, x, hint), m);
    s.force = total_force(m.view(), s.delta, s.rate);
    if (s.force < 0) out.back_flank = true;
    if (i == 0) continue;
    const Sample& a = rec[i - 1];
    const double h = (s.x - a.x) / speed_, xm = 0.5 * (a.x + s.x);
    const double dm = hermite(a.delta, s.delta, h * a.rate, h * s.rate, 0.5);
    slots_at(law_, xm, interval_of(law_, xm, hint), m);
    if (total_force(m.view(), dm, 0.5 * (a.rate + s.rate)) == 0) out.no_load_time += h;
  }
}

PeriodOutcome DriveStepper::nonlinear_period(State& z, std::vector<Sample>* record) const {
  PeriodOutcome out;
  if (record) {
    record->clear();
    record->push_back({0.0, z[0], z[2], 0.0});
  }
  SlotsView v[3];
  for (int s = 0; s < steps() && !out.unbounded; ++s) {
    for (int j = 0; j < 3; ++j) v[j] = stage(3 * s + j);
    substep(z, grid_[s], grid_[s + 1], 0, record, out, v);
  }
  return out;
}

void DriveStepper::linear_period(Eigen::MatrixXd& phi, Eigen::VectorXd& zp) const {
  // Linearised about the static state: the mesh force F_s + k_t(X) (delta - delta_s(X)),
  // contact damping always on. Columns 0..2n-1 homogeneous (Phi), column 2n particular.
  const int m = 2 * n_, cols = m + 1;
  const int map[4] = {0, n_ == 1 ? 2 : 1, 2, 3};  // first-order index -> State index
  std::vector<State> Z(cols, State{0, 0, 0, 0});
  for (int c = 0; c < m; ++c) Z[c][map[c]] = 1;
  auto lin = [&](int p, const State& z, bool particular, State& dz) {
    const double q0 = -kt_[p] * (z[0] - (particular ? ds_[p] : 0.0)) - cm_ * z[2];
    if (n_ == 1) { dz = {z[2], 0, g00_ * q0, 0}; return; }
    const double q1 = (particular ? rb_ * fs_ : 0.0) - kd_ * z[1] - cd_ * z[3];
    dz = {z[2], z[3], g00_ * q0 + g01_ * q1, g01_ * q0 + g11_ * q1};
  };
  State k1, k2, k3, k4, t;
  for (int s = 0; s < steps(); ++s) {
    const double h = (grid_[s + 1] - grid_[s]) / speed_;
    for (int c = 0; c < cols; ++c) {
      const bool part = c == m;
      State& z = Z[c];
      lin(3 * s, z, part, k1);
      for (int i = 0; i < 4; ++i) t[i] = z[i] + 0.5 * h * k1[i];
      lin(3 * s + 1, t, part, k2);
      for (int i = 0; i < 4; ++i) t[i] = z[i] + 0.5 * h * k2[i];
      lin(3 * s + 1, t, part, k3);
      for (int i = 0; i < 4; ++i) t[i] = z[i] + h * k3[i];
      lin(3 * s + 2, t, part, k4);
      for (int i = 0; i < 4; ++i) z[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
  }
  phi.resize(m, m);
  zp.resize(m);
  for (int c = 0; c < m; ++c)
    for (int r = 0; r < m; ++r) phi(r, c) = Z[c][map[r]];
  for (int r = 0; r < m; ++r) zp(r) = Z[m][map[r]];
}

}  // namespace rackopt::detail
