// The tabulated mesh force law (docs/models/dynamics.md).
#include "rackopt/dynamics/mesh_force_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rackopt/dynamics/mesh_law_eval.hpp"

namespace rackopt {
namespace detail {

double SlotsView::approach(double force, double* tangent) const {
  // F(delta) is piecewise linear and increasing in delta: walk the closing
  // gaps in ascending order until the next gap lies beyond the candidate.
  int order[16];
  std::vector<int> big;
  int* o = order;
  if (n > 16) { big.resize(n); o = big.data(); }
  for (int i = 0; i < n; ++i) o[i] = i;
  std::sort(o, o + n, [&](int a, int b) { return g[a] < g[b]; });
  double K = 0, Kg = 0, d = 0;
  for (int j = 0; j < n; ++j) {
    K += k[o[j]];
    Kg += k[o[j]] * g[o[j]];
    d = (force + Kg) / K;
    if (j + 1 == n || d <= g[o[j + 1]]) break;
  }
  if (tangent) *tangent = K;
  if (K <= 0) throw std::invalid_argument("mesh force law: no slot touches at this travel (stiffness 0)");
  return d;
}

double reduce_travel(const MeshForceLaw& law, double X) {
  double r = std::fmod(X, law.period);
  if (r < 0) r += law.period;
  if (r >= law.period) r = 0;
  return r;
}

int interval_of(const MeshForceLaw& law, double X, int hint) {
  const auto& t = law.travel;
  const int last = static_cast<int>(t.size()) - 2;
  if (hint >= 0 && hint <= last) {
    // Walk from the hint: the stepper advances in small steps.
    int i = hint;
    for (int s = 0; s < 8; ++s) {
      if (X < t[i]) { if (i == 0) break; --i; continue; }
      if (i < last && X >= t[i + 1]) { ++i; continue; }
      return i;
    }
  }
  int i = static_cast<int>(std::upper_bound(t.begin(), t.end(), X) - t.begin()) - 1;
  return std::clamp(i, 0, last);
}

void slots_at(const MeshForceLaw& law, double X, int i, MeshAt& out) {
  out.clear();
  const double x0 = law.travel[i], x1 = law.travel[i + 1];
  const double w = x1 > x0 ? std::clamp((X - x0) / (x1 - x0), 0.0, 1.0) : 1.0;
  const int s = law.slots;
  for (int j = 0; j < s; ++j) {
    const double k = (1 - w) * law.stiffness[i * s + j] + w * law.stiffness[(i + 1) * s + j];
    if (k <= 0) continue;
    out.k.push_back(k);
    out.idx.push_back(j);
    out.g.push_back((1 - w) * law.gap[i * s + j] + w * law.gap[(i + 1) * s + j]);
  }
}

}  // namespace detail

namespace {

detail::MeshAt at(const MeshForceLaw& law, double X) {
  const double r = detail::reduce_travel(law, X);
  detail::MeshAt m;
  detail::slots_at(law, r, detail::interval_of(law, r, -1), m);
  return m;
}

void require_finite(double v, const char* name) {
  if (!std::isfinite(v)) throw std::invalid_argument(std::string("mesh force law: ") + name + " must be finite");
}

}  // namespace

double MeshForceLaw::force(double X, double delta) const {
  require_finite(X, "travel");
  require_finite(delta, "delta");
  return at(*this, X).view().force(delta, backlash);
}

double MeshForceLaw::tangent(double X, double delta) const {
  require_finite(X, "travel");
  require_finite(delta, "delta");
  return at(*this, X).view().tangent(delta, backlash);
}

double MeshForceLaw::full_stiffness(double X) const {
  require_finite(X, "travel");
  return at(*this, X).view().full();
}

double MeshForceLaw::approach_at(double X, double f) const {
  require_finite(X, "travel");
  if (!(std::isfinite(f) && f >= 0)) throw std::invalid_argument("mesh force law: force must be finite and >= 0");
  return at(*this, X).view().approach(f, nullptr);
}

double MeshForceLaw::mean_stiffness() const {
  double area = 0;
  for (size_t i = 0; i + 1 < travel.size(); ++i) {
    double k0 = 0, k1 = 0;
    for (int j = 0; j < slots; ++j) {
      k0 += stiffness[i * slots + j];
      k1 += stiffness[(i + 1) * slots + j];
    }
    area += 0.5 * (k0 + k1) * (travel[i + 1] - travel[i]);
  }
  return area / period;
}

void MeshForceLaw::validate() const {
  auto fail = [](const std::string& m) { throw std::invalid_argument("mesh force law: " + m); };
  if (!(std::isfinite(period) && period > 0)) fail("period must be finite and > 0");
  if (!(std::isfinite(mesh_pitch) && mesh_pitch > 0)) fail("mesh_pitch must be finite and > 0");
  if (slots < 1) fail("slots must be >= 1");
  if (travel.size() < 2) fail("travel needs at least 2 samples");
  const size_t n = travel.size() * static_cast<size_t>(slots);
  if (stiffness.size() != n) fail("stiffness size must be travel.size() * slots");
  if (gap.size() != n) fail("gap size must be travel.size() * slots");
  if (std::isnan(backlash) || backlash < 0) fail("backlash must be >= 0 (infinity: no back flank)");
  if (!(travel.front() == 0 && travel.back() == period)) fail("travel must run from 0 to period");
  for (size_t i = 0; i < travel.size(); ++i) {
    if (!std::isfinite(travel[i])) fail("travel must be finite");
    if (i > 0 && travel[i] < travel[i - 1]) fail("travel must be ascending");
    if (i > 1 && travel[i] == travel[i - 2]) fail("travel: at most two samples at one travel (a jump)");
  }
  for (size_t i = 0; i < n; ++i) {
    if (!(std::isfinite(stiffness[i]) && stiffness[i] >= 0)) fail("stiffness must be finite and >= 0");
    if (!(std::isfinite(gap[i]) && gap[i] >= 0)) fail("gap must be finite and >= 0");
  }
  for (size_t i = 0; i < travel.size(); ++i) {
    double k = 0;
    for (int j = 0; j < slots; ++j) k += stiffness[i * slots + j];
    if (!(k > 0)) fail("full stiffness must be > 0 at every travel sample (some slot must touch)");
  }
}

}  // namespace rackopt
