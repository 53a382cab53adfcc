// The time stepper of the drive dynamics (internal to the module;
// docs/models/dynamics.md, "Numerics"): classical RK4 at fixed steps over a
// travel grid aligned with the law's jumps, contact switches located inside
// a step (cubic Hermite of the step) and the step split there; and the
// linearised period's monodromy matrix on the same grid.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Dense>

#include "rackopt/dynamics/drive_response.hpp"
#include "rackopt/dynamics/mesh_law_eval.hpp"

namespace rackopt::detail {

using State = std::array<double, 4>;  // delta, phi, delta', phi' (phi = 0 for a rigid drive train)

// One recorded point of a period: travel, state, total mesh force.
struct Sample {
  double x, delta, rate, force;
};

struct PeriodOutcome {
  bool unbounded = false;
  double no_load_time = 0;  // time with zero mesh force [s]
  bool back_flank = false;
};

class DriveStepper {
 public:
  DriveStepper(const DriveTrain& train, const MeshForceLaw& law, double speed, double static_force,
               const DynamicsOptions& options);

  int dof() const { return n_; }
  int steps() const { return static_cast<int>(grid_.size()) - 1; }
  double period_s() const { return period_s_; }
  // Scales of the periodicity test: static approach [m] and the highest natural angular frequency [rad/s].
  double approach_scale() const { return d_scale_; }
  double omega_max() const { return omega_max_; }
  double base_radius() const { return rb_; }

  // Monodromy matrix Phi (2n x 2n) and particular end state zp of the system
  // linearised about the static state, over one period from travel 0.
  void linear_period(Eigen::MatrixXd& phi, Eigen::VectorXd& zp) const;
  // Advances z over one period of the full (nonlinear) model; appends the
  // step ends to `record` when given.
  PeriodOutcome nonlinear_period(State& z, std::vector<Sample>* record) const;
  // Fills the recorded points' forces and `out`'s contact statistics
  // (no-load time, back flank) for a period recorded by nonlinear_period.
  void analyze(std::vector<Sample>& record, PeriodOutcome& out) const;
  // Total mesh force (contact damping included, never pulling) at travel X in [0, period).
  double mesh_force(double X, double delta, double rate) const;

 private:
  SlotsView stage(int p) const {
    return {k_.data() + off_[p], g_.data() + off_[p], idx_.data() + off_[p], off_[p + 1] - off_[p]};
  }
  double total_force(const SlotsView& s, double delta, double rate) const;
  // Contact state (which slots are closed on which flank, force positive):
  // a step whose ends differ holds a switch.
  std::uint64_t signature(const SlotsView& s, const State& z) const;
  void deriv(const SlotsView& s, const State& z, State& dz) const;
  State rk4(const State& z, double h, const SlotsView& a, const SlotsView& m, const SlotsView& b) const;
  // First switching function to change sign over the step, as a fraction
  // of the step in (0, 1), or -1 when none changes.
  double crossing(const SlotsView& a, const SlotsView& b, const State& z0, const State& z1, double h) const;
  void substep(State& z, double xa, double xb, int depth, std::vector<Sample>* record, PeriodOutcome& out,
               const SlotsView* cached) const;

  const MeshForceLaw& law_;
  int n_ = 1;
  double rb_ = 0, speed_ = 0, fs_ = 0, period_s_ = 0;
  double g00_ = 0, g01_ = 0, g11_ = 0;  // inverse reduced mass
  double kd_ = 0, cd_ = 0, cm_ = 0;     // drive spring and damper, mesh damper
  double d_scale_ = 0, omega_max_ = 0, limit_ = 0;
  std::vector<double> grid_;            // step boundaries in travel, 0 .. period
  // Per stage point (2 per step + 1: start, middle, end): the slots, flat.
  std::vector<int> off_;
  std::vector<double> k_, g_;
  std::vector<int> idx_;
  std::vector<double> kt_, ds_;         // tangent and static approach at each stage point
};

}  // namespace rackopt::detail
