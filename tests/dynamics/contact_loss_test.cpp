// Contact loss: a backlash oscillator (constant stiffness, harmonic kinematic
// error, finite backlash) swept up and down in speed. Its jump speeds are
// checked against a one-term harmonic balance written here (Kahraman and
// Singh, J. Sound Vib. 142 (1990) 49-75, solve the same oscillator that way).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "dynamics/dynamics_test_support.hpp"

namespace rackopt {
namespace {

struct Backlash {
  DriveTrain t = dyntest::rigid_train();
  double k = 8e8, a = 2e-6, period = 0.02, zeta = 0.05;
  double fs = k * 2.5 * a;   // static approach 2.5 a: the resonant response loses contact
  double b = 10 * a;         // backlash
  double m = dyntest::mesh_mass(t), c = 2 * zeta * std::sqrt(k * m), wn = std::sqrt(k / m);
  MeshForceLaw law = dyntest::harmonic_gap_law(k, a, period, 800, b);

  // Total mesh force of the model (docs/models/dynamics.md) at phase th.
  double force(double th, double d, double v) const {
    const double g = a * (1 + std::sin(th));
    if (d > g) return std::max(0.0, k * (d - g) + c * v);
    if (-d - b - g > 0) return std::min(0.0, k * (d + b + g) + c * v);
    return 0;
  }
  // Harmonic-balance residual of d = d0 + p cos(th) + q sin(th) at W.
  Eigen::Vector3d residual(const Eigen::Vector3d& x, double W) const {
    const int n = 4096;
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (int i = 0; i < n; ++i) {
      const double th = 2 * M_PI * (i + 0.5) / n, cs = std::cos(th), sn = std::sin(th);
      const double d = x(0) + x(1) * cs + x(2) * sn, v = W * (-x(1) * sn + x(2) * cs);
      const double e = -m * W * W * (x(1) * cs + x(2) * sn) + force(th, d, v) - fs;
      r += Eigen::Vector3d(e, 2 * e * cs, 2 * e * sn) / n;
    }
    return r / fs;
  }
  // Newton from x; false when it does not converge.
  bool solve(Eigen::Vector3d& x, double W) const {
    for (int it = 0; it < 60; ++it) {
      const Eigen::Vector3d r = residual(x, W);
      if (r.norm() < 1e-10) return true;
      Eigen::Matrix3d J;
      for (int j = 0; j < 3; ++j) {
        Eigen::Vector3d xp = x;
        xp(j) += 1e-4 * a;
        J.col(j) = (residual(xp, W) - r) / (1e-4 * a);
      }
      Eigen::Vector3d dx = J.fullPivLu().solve(-r);
      const double lim = 2 * a;  // damped steps: the residual has kinks
      if (dx.norm() > lim) dx *= lim / dx.norm();
      x += dx;
    }
    return residual(x, W).norm() < 1e-8;
  }
};

// Ratio at which a sweep (in its direction) first lands on another branch:
// the amplitude changes by more than 20 % from one grid point to the next.
double jump_at(const std::vector<double>& ratio, const std::vector<double>& amp, bool ascending) {
  const int n = static_cast<int>(amp.size());
  for (int kk = 1; kk < n; ++kk) {
    const int i = ascending ? kk : n - 1 - kk, prev = ascending ? i - 1 : i + 1;
    if (std::abs(amp[i] - amp[prev]) > 0.2 * std::max(amp[i], amp[prev])) return ratio[i];
  }
  return -1;
}

TEST(ContactLoss, JumpSpeedsAgreeWithHarmonicBalance) {
  const Backlash s;
  std::vector<double> ratio;
  for (int i = 0; i <= 60; ++i) ratio.push_back(0.6 + 0.6 * i / 60);  // excitation / natural frequency
  std::vector<double> speeds;
  for (double r : ratio) speeds.push_back(r * s.wn * s.period / (2 * M_PI));
  DynamicsOptions o;
  o.damping_ratio = s.zeta;
  o.max_periods = 400;
  o.periodic_tolerance = 1e-7;
  const auto sweep = speed_sweep(s.t, s.law, speeds, s.fs, o);
  std::vector<double> up, down;
  for (const auto& p : sweep) {
    up.push_back(p.dte_pp_up);
    down.push_back(p.dte_pp_down);
  }

  // Harmonic balance continued the same way, up and down: the sweep jumps
  // where the branch it follows ends (Newton from the previous solution
  // fails at the fold) or lands on another branch.
  auto hb_jump = [&](bool ascending) {
    Eigen::Vector3d x(s.fs / s.k + s.a, 0, 0);
    double prev_amp = -1;
    for (size_t kk = 0; kk < ratio.size(); ++kk) {
      const size_t i = ascending ? kk : ratio.size() - 1 - kk;
      if (!s.solve(x, ratio[i] * s.wn)) return ratio[i];
      const double amp = 2 * std::hypot(x(1), x(2));
      if (prev_amp > 0 && std::abs(amp - prev_amp) > 0.2 * std::max(amp, prev_amp)) return ratio[i];
      prev_amp = amp;
    }
    return -1.0;
  };
  const double hu = hb_jump(true), hd = hb_jump(false);
  const double ju = jump_at(ratio, up, true), jd = jump_at(ratio, down, false);
  // One-term harmonic balance misses the higher harmonics of the contact
  // loss: the jumps agree to 3 % of the natural frequency (3 grid points).
  ASSERT_GT(ju, 0);
  ASSERT_GT(jd, 0);
  std::cout << "jump up " << ju << " (harmonic balance " << hu << "), down " << jd << " (" << hd << ")\n";
  EXPECT_NEAR(ju, hu, 0.03);
  EXPECT_NEAR(jd, hd, 0.03);
  // A hysteresis band: the jumps differ and the branches differ inside it.
  EXPECT_GT(ju - jd, 0.1);
  const size_t mid = static_cast<size_t>(std::lround((0.5 * (ju + jd) - ratio[0]) / (ratio[1] - ratio[0])));
  EXPECT_GT(std::abs(up[mid] - down[mid]) / std::max(up[mid], down[mid]), 0.5);
  // Contact is lost on the high branch.
  double loss = 0;
  for (const auto& p : sweep) loss = std::max({loss, p.contact_loss_up, p.contact_loss_down});
  EXPECT_GT(loss, 0.05);
}

}  // namespace
}  // namespace rackopt
