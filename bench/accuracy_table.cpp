// Error versus time for each fidelity knob of the stiffness curve; prints the
// Markdown tables of docs/accuracy.md.
//
//   ./build/accuracy_table [problem.yaml ...]     (default: the bundled rack_railway
//                                                   and ship_lift problems)
//
// Knobs:
//  * numerics.quadrature_order: fixed Gauss-Legendre points per tooth integral,
//    against GSL adaptive quadrature (QAGS, rel. 1e-12) as the reference;
//  * numerics.positions_per_period: uniform samples per mesh period, against
//    3200 per period as the reference. Besides k_min/k_max/k_mean, the
//    "curve" column is the largest error of the piecewise-linear curve drawn
//    through the samples (what a plot or a downstream interpolation sees),
//    measured at 4 points between every pair of reference samples.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>

#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

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

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
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
  return 0;
}
