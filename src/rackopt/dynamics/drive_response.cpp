// Steady response, Floquet multipliers and speed sweeps of the rack drive
// (docs/models/dynamics.md, "Numerics").
#include "rackopt/dynamics/drive_response.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

#include "rackopt/dynamics/drive_stepper.hpp"
#include "rackopt/dynamics/drive_transient.hpp"

namespace rackopt {
namespace {

using detail::DriveStepper;
using detail::Sample;
using detail::State;

State to_state(const Eigen::VectorXd& y, int n) {
  return n == 1 ? State{y(0), 0, y(1), 0} : State{y(0), y(1), y(2), y(3)};
}

// The periodic solution of the linearised drive: (I - Phi) y0 = y_p. When
// the linearised drive is parametrically unstable that solution exists but
// is never observed: it is disturbed by 1e-3 static approaches so that the
// march shows what the drive does instead (grows, or settles on an orbit
// with contact loss).
std::optional<State> linear_periodic_start(const DriveStepper& st) {
  Eigen::MatrixXd phi;
  Eigen::VectorXd zp;
  st.linear_period(phi, zp);
  const double radius = Eigen::EigenSolver<Eigen::MatrixXd>(phi, false).eigenvalues().cwiseAbs().maxCoeff();
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(phi.rows(), phi.cols()) - phi;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  if (!lu.isInvertible()) return std::nullopt;  // a multiplier exactly 1: no unique periodic solution
  const Eigen::VectorXd y0 = lu.solve(zp);
  if (!y0.allFinite()) return std::nullopt;
  State z = to_state(y0, st.dof());
  if (radius > 1) z[0] += 1e-3 * st.approach_scale();
  return z;
}

// Distance of two states in the periodicity test's units (static approach and its rate).
double periodic_error(const DriveStepper& st, const State& a, const State& b) {
  const double d = st.approach_scale(), w = st.omega_max(), r = st.base_radius();
  double e = std::max(std::abs(a[0] - b[0]) / d, std::abs(a[2] - b[2]) / (d * w));
  if (st.dof() == 2) e = std::max({e, std::abs(a[1] - b[1]) * r / d, std::abs(a[3] - b[3]) * r / (d * w)});
  return e;
}

// Mesh force and approach over the recorded period, resampled on history_points travels.
void summarize(const DriveStepper& st, const MeshForceLaw& law, std::vector<Sample>& rec,
               detail::PeriodOutcome& po, const DynamicsOptions& o, SteadyResponse& r) {
  st.analyze(rec, po);
  r.mesh_force_max = r.dte_max = -std::numeric_limits<double>::infinity();
  r.mesh_force_min = r.dte_min = std::numeric_limits<double>::infinity();
  auto take = [&](double f, double d) {
    r.mesh_force_max = std::max(r.mesh_force_max, f);
    r.mesh_force_min = std::min(r.mesh_force_min, f);
    r.dte_max = std::max(r.dte_max, d);
    r.dte_min = std::min(r.dte_min, d);
  };
  for (size_t i = 0; i < rec.size(); ++i) {
    take(rec[i].force, rec[i].delta);
    if (i == 0) continue;
    // Extremes inside a step: where the step's cubic Hermite in delta has
    // zero slope (the step ends alone would cut peaks by O(h^2)).
    const Sample& a = rec[i - 1];
    const Sample& b = rec[i];
    const double h = (b.x - a.x) / r.speed;
    if (!(h > 0)) continue;
    const double m0 = h * a.rate, m1 = h * b.rate;
    const double qa = 6 * a.delta + 3 * m0 - 6 * b.delta + 3 * m1;
    const double qb = -6 * a.delta - 4 * m0 + 6 * b.delta - 2 * m1;
    const double qc = m0;
    double roots[2];
    int nr = 0;
    if (std::abs(qa) > 1e-300) {
      const double disc = qb * qb - 4 * qa * qc;
      if (disc >= 0) {
        const double sq = std::sqrt(disc);
        roots[nr++] = (-qb - sq) / (2 * qa);
        roots[nr++] = (-qb + sq) / (2 * qa);
      }
    } else if (std::abs(qb) > 1e-300) {
      roots[nr++] = -qc / qb;
    }
    for (int k = 0; k < nr; ++k) {
      const double t = roots[k];
      if (!(t > 0 && t < 1)) continue;
      const double t2 = t * t, t3 = t2 * t;
      const double d = (2 * t3 - 3 * t2 + 1) * a.delta + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * b.delta +
                       (t3 - t2) * m1;
      const double x = a.x + t * (b.x - a.x);
      take(st.mesh_force(std::min(x, std::nextafter(law.period, 0.0)), d, (1 - t) * a.rate + t * b.rate), d);
    }
  }
  const int N = o.history_points;
  r.travel.resize(N);
  r.mesh_force.resize(N);
  r.dte.resize(N);
  size_t j = 0;
  for (int i = 0; i < N; ++i) {
    const double X = law.period * i / N;
    while (j + 2 < rec.size() && rec[j + 1].x <= X) ++j;
    const Sample& a = rec[j];
    const Sample& b = rec[std::min(j + 1, rec.size() - 1)];
    const double dx = b.x - a.x;
    const double t = dx > 0 ? std::clamp((X - a.x) / dx, 0.0, 1.0) : 0.0;
    const double h = dx / r.speed;
    // Cubic Hermite in delta (the rates are the slopes); the rate itself linear.
    const double t2 = t * t, t3 = t2 * t;
    const double d = (2 * t3 - 3 * t2 + 1) * a.delta + (t3 - 2 * t2 + t) * h * a.rate +
                     (-2 * t3 + 3 * t2) * b.delta + (t3 - t2) * h * b.rate;
    const double v = (1 - t) * a.rate + t * b.rate;
    r.travel[i] = X;
    r.dte[i] = d;
    r.mesh_force[i] = st.mesh_force(X, d, v);
    r.mesh_force_max = std::max(r.mesh_force_max, r.mesh_force[i]);
    r.mesh_force_min = std::min(r.mesh_force_min, r.mesh_force[i]);
    r.dte_max = std::max(r.dte_max, d);
    r.dte_min = std::min(r.dte_min, d);
  }
  r.dte_peak_to_peak = r.dte_max - r.dte_min;
  r.dynamic_factor = r.static_force > 0 ? r.mesh_force_max / r.static_force : 0.0;
  r.contact_loss_fraction = std::clamp(po.no_load_time / st.period_s(), 0.0, 1.0);
  r.back_flank_contact = po.back_flank;
}

// March periods from `start` (the linear periodic solution when empty)
// until the state repeats; `z` returns the state at the start of the last period.
SteadyResponse march(const DriveTrain& train, const MeshForceLaw& law, double speed, double static_force,
                     const DynamicsOptions& o, std::optional<State> start, State& z) {
  const DriveStepper st(train, law, speed, static_force, o);
  SteadyResponse r;
  r.speed = speed;
  r.static_force = static_force;
  r.excitation_period_s = st.period_s();
  const double ds0 = law.approach_at(0, static_force);
  if (!start) {
    start = linear_periodic_start(st);
    // Near an undamped resonance the linear solution is huge (a multiplier
    // near 1): the contact nonlinearity bounds the real response, so start static.
    if (start && std::abs((*start)[0] - ds0) > 1e2 * st.approach_scale()) start.reset();
  }
  if (!start) {
    // No usable linear periodic solution: start static.
    start = State{ds0, st.dof() == 2 ? train.base_radius * static_force / train.drive_stiffness : 0, 0, 0};
  }
  z = *start;
  std::vector<Sample> rec;
  rec.reserve(3 * st.steps() + 16);
  detail::PeriodOutcome po;
  r.status = ResponseStatus::kNotPeriodic;
  for (int p = 1; p <= o.max_periods; ++p) {
    const State z0 = z;
    po = st.nonlinear_period(z, &rec);
    r.periods = p;
    if (po.unbounded) {
      r.status = ResponseStatus::kUnbounded;
      r.message = "the approach grew beyond 1e3 static approaches in period " + std::to_string(p) +
                  ": the drive is unstable at this speed";
      z = *start;
      break;
    }
    const double err = periodic_error(st, z0, z);
    if (err <= o.periodic_tolerance) {
      r.status = ResponseStatus::kConverged;
      z = z0;
      break;
    }
    if (p == o.max_periods) {
      r.message = "not periodic after " + std::to_string(p) + " periods (last change " + std::to_string(err) +
                  " static approaches): parametrically unstable, subharmonic or chaotic";
      z = z0;
    }
  }
  if (r.status == ResponseStatus::kUnbounded) {
    r.dynamic_factor = std::numeric_limits<double>::infinity();
    return r;
  }
  summarize(st, law, rec, po, o, r);
  return r;
}

}  // namespace

SteadyResponse steady_response(const DriveTrain& train, const MeshForceLaw& law, double speed,
                               double static_force, const DynamicsOptions& options) {
  State z;
  return march(train, law, speed, static_force, options, std::nullopt, z);
}

FloquetResult floquet(const DriveTrain& train, const MeshForceLaw& law, double speed, double static_force,
                      const DynamicsOptions& options) {
  const DriveStepper st(train, law, speed, static_force, options);
  Eigen::MatrixXd phi;
  Eigen::VectorXd zp;
  st.linear_period(phi, zp);
  Eigen::EigenSolver<Eigen::MatrixXd> es(phi, false);
  FloquetResult f;
  for (int i = 0; i < es.eigenvalues().size(); ++i) f.multiplier_magnitudes.push_back(std::abs(es.eigenvalues()[i]));
  std::sort(f.multiplier_magnitudes.begin(), f.multiplier_magnitudes.end(), std::greater<>());
  f.spectral_radius = f.multiplier_magnitudes.front();
  f.stable = f.spectral_radius < 1;
  f.margin = 1 - f.spectral_radius;
  return f;
}

std::vector<SweepPoint> speed_sweep(const DriveTrain& train, const MeshForceLaw& law,
                                    const std::vector<double>& speeds, double static_force,
                                    const DynamicsOptions& options) {
  if (speeds.empty()) throw std::invalid_argument("speed_sweep: speeds must not be empty");
  for (double v : speeds)
    if (!(std::isfinite(v) && v > 0)) throw std::invalid_argument("speed_sweep: every speed must be finite and > 0 [m/s]");
  std::vector<size_t> order(speeds.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return speeds[a] < speeds[b]; });
  std::vector<SweepPoint> out(speeds.size());
  // Whether any speed of the rising sweep left the flanks' front contact
  // (separation, back flank) or found no periodic state: only then can the
  // falling sweep land on another branch.
  bool left_front_contact = false;
  // One direction: each speed starts from the previous one's steady state
  // (same travel phase; rates scale with the speed).
  auto run = [&](bool up) {
    std::optional<State> prev;
    double prev_v = 0;
    for (size_t k = 0; k < order.size(); ++k) {
      const size_t i = up ? order[k] : order[order.size() - 1 - k];
      const double v = speeds[i];
      std::optional<State> start;
      if (prev) {
        State s = *prev;
        s[2] *= v / prev_v;
        s[3] *= v / prev_v;
        start = s;
      }
      State z;
      const SteadyResponse r = march(train, law, v, static_force, options, start, z);
      SweepPoint& p = out[i];
      p.speed = v;
      (up ? p.kv_up : p.kv_down) = r.dynamic_factor;
      (up ? p.dte_pp_up : p.dte_pp_down) = r.dte_peak_to_peak;
      (up ? p.contact_loss_up : p.contact_loss_down) = r.contact_loss_fraction;
      (up ? p.status_up : p.status_down) = r.status;
      if (up && (r.mesh_force_min <= 0 || r.contact_loss_fraction > 0 || r.status != ResponseStatus::kConverged))
        left_front_contact = true;
      if (r.status == ResponseStatus::kUnbounded) prev.reset(); else prev = z;
      prev_v = v;
    }
  };
  run(true);
  if (left_front_contact) {
    run(false);
  } else {
    // The flanks stayed in front contact at every speed: the drive is a
    // linear periodic system plus the corner slots' mild hardening, whose
    // periodic state the monodromy start fixes; falling speeds find the same.
    for (SweepPoint& p : out) {
      p.kv_down = p.kv_up;
      p.dte_pp_down = p.dte_pp_up;
      p.contact_loss_down = p.contact_loss_up;
      p.status_down = p.status_up;
    }
  }
  return out;
}

TransientResult drive_transient(const DriveTrain& train, const MeshForceLaw& law, double speed,
                                double static_force, const DynamicsOptions& options, const DriveState& start,
                                int periods) {
  if (periods < 1) throw std::invalid_argument("drive_transient: periods must be >= 1");
  const DriveStepper st(train, law, speed, static_force, options);
  TransientResult r;
  r.steps_per_period = st.steps();
  State z{start.delta, st.dof() == 2 ? start.twist : 0, start.delta_rate, st.dof() == 2 ? start.twist_rate : 0};
  for (int p = 0; p < periods; ++p) {
    if (st.nonlinear_period(z, nullptr).unbounded) {
      r.status = ResponseStatus::kUnbounded;
      break;
    }
    r.period_end.push_back({z[0], z[1], z[2], z[3]});
  }
  return r;
}

}  // namespace rackopt
