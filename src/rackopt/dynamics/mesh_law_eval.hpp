// Fast evaluation of a MeshForceLaw for the time stepper (internal to the
// dynamics module; docs/models/dynamics.md). The slots' stiffness and gap at
// one travel are interpolated once (MeshAt) and then give the force, its
// tangent and the static approach for any delta without another search.
#pragma once

#include <vector>

#include "rackopt/dynamics/mesh_force_law.hpp"

namespace rackopt::detail {

// The slots touching (k > 0) at one travel, as a view into storage that
// outlives it (MeshAt, or the stepper's per-period cache).
struct SlotsView {
  const double* k = nullptr;  // stiffness [N/m] of each touching slot
  const double* g = nullptr;  // its gap [m]
  const int* idx = nullptr;   // its slot index in the law, ascending
  int n = 0;
  // Elastic front-flank force sum k max(0, delta - g); `touching`: any slot closed.
  double front(double delta, bool& touching) const {
    double f = 0;
    touching = false;
    for (int i = 0; i < n; ++i)
      if (delta > g[i]) { f += k[i] * (delta - g[i]); touching = true; }
    return f;
  }
  // Magnitude of the mirrored back-flank terms.
  double back(double delta, double backlash, bool& touching) const {
    double f = 0;
    touching = false;
    for (int i = 0; i < n; ++i) {
      const double s = -delta - backlash - g[i];
      if (s > 0) { f += k[i] * s; touching = true; }
    }
    return f;
  }
  double force(double delta, double backlash) const {
    bool t;
    const double f = front(delta, t);
    if (t) return f;
    return -back(delta, backlash, t);
  }
  double tangent(double delta, double backlash) const {
    double kt = 0;
    for (int i = 0; i < n; ++i)
      if (delta > g[i] || -delta - backlash - g[i] > 0) kt += k[i];
    return kt;
  }
  double full() const {
    double s = 0;
    for (int i = 0; i < n; ++i) s += k[i];
    return s;
  }
  // Front-flank approach carrying `force` >= 0, and the tangent there.
  double approach(double force, double* tangent) const;
};

// Owning storage of the slots at one travel.
struct MeshAt {
  std::vector<double> k, g;
  std::vector<int> idx;
  void clear() { k.clear(); g.clear(); idx.clear(); }
  SlotsView view() const { return {k.data(), g.data(), idx.data(), static_cast<int>(k.size())}; }
};

// Reduces X modulo the period into [0, period).
double reduce_travel(const MeshForceLaw& law, double X);
// Interval index i with travel[i] <= X < travel[i+1] for X in [0, period)
// (the right limit at a jump); `hint` is a starting guess (-1: none).
int interval_of(const MeshForceLaw& law, double X, int hint);
// Fills `out` with the slots at X (already reduced) in interval i.
void slots_at(const MeshForceLaw& law, double X, int i, MeshAt& out);

}  // namespace rackopt::detail
