#include "rackopt/dynamics/drive_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/dynamics/drive_train_builder.hpp"
#include "rackopt/dynamics/mesh_force_law_builder.hpp"

namespace rackopt {
namespace {

SourceMark problem_mark(const Drive& drive) {
  return SourceMark{drive.source_file.empty() ? "<problem>" : drive.source_file, 0, 0};
}

// The stiffness every linearised output uses: the law's tangent at the
// static approach (each touching pair's slope where it carries its share of
// F_s), per law sample.
std::vector<double> tangent_at_static_load(const MeshForceLaw& law, double static_force) {
  std::vector<double> k(law.travel.size());
  for (std::size_t j = 0; j < law.travel.size(); ++j) {
    const double x = law.travel[j];
    k[j] = law.tangent(x, law.approach_at(x, static_force));
  }
  return k;
}

// Mean over the travel of a sampled quantity (trapezoid; the duplicated
// samples at a jump add a zero-length interval).
double travel_mean(const std::vector<double>& travel, const std::vector<double>& value, double period) {
  double area = 0;
  for (std::size_t j = 1; j < travel.size(); ++j)
    area += 0.5 * (value[j] + value[j - 1]) * (travel[j] - travel[j - 1]);
  return area / period;
}

std::vector<ExcitationOrder> excitation_orders(const MeshForceLaw& law) {
  return {{"mesh", law.mesh_pitch},
          {"2 x mesh", law.mesh_pitch / 2},
          {"3 x mesh", law.mesh_pitch / 3},
          {"span", law.period}};
}

void find_resonances(DriveDynamics& d) {
  const std::size_t modes = d.natural_frequencies_hz.size();
  for (const ExcitationOrder& o : d.orders) {
    for (std::size_t i = 0; i < modes; ++i) {
      const auto& along = d.natural_frequency_along_travel[i];
      const auto [lo, hi] = std::minmax_element(along.begin(), along.end());
      d.resonances.push_back({o.name, static_cast<int>(i), d.natural_frequencies_hz[i] * o.wavelength,
                              *lo * o.wavelength, *hi * o.wavelength});
    }
  }
  std::sort(d.resonances.begin(), d.resonances.end(),
            [](const Resonance& a, const Resonance& b) { return a.speed_at_mean < b.speed_at_mean; });
  d.resonance_margin = std::numeric_limits<double>::infinity();
  if (!(d.operating_speed > 0)) return;
  for (const Resonance& r : d.resonances) {
    // The main resonances: the mesh and the span order against the lowest mode.
    if (r.mode != 0 || (r.order != "mesh" && r.order != "span")) continue;
    d.resonance_margin = std::min(d.resonance_margin, std::abs(d.operating_speed - r.speed_at_mean) / r.speed_at_mean);
  }
}

}  // namespace

std::vector<double> dynamics_speeds(const Drive& drive, double operating_speed) {
  const DynamicsSpec& s = drive.dynamics;
  double from = s.speed_from, to = s.speed_to;
  int points = s.speed_points;
  if (points <= 0) {
    if (!(operating_speed > 0)) {
      throw InputError(problem_mark(drive), "dynamics.speed_range",
                       "the dynamic model needs speeds: give load.speed (the operating speed; the default range is "
                       "load.speed/20 ... 1.25 load.speed) or dynamics.speed_range {from, to, points}");
    }
    from = operating_speed / 20;
    to = 1.25 * operating_speed;
    points = 40;
  }
  std::vector<double> v(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) v[i] = points == 1 ? from : from + (to - from) * i / (points - 1);
  return v;
}

DriveDynamics analyse_drive_dynamics(const Drive& drive, const MeshStiffnessModel& model,
                                     const DynamicsRequest& request) {
  DriveDynamics d;
  d.train = drive_train(drive, model.geometry());
  d.law = build_mesh_force_law(drive, model, request.positions_per_period);
  d.static_force = drive.load.force;
  if (!(d.static_force > 0)) {
    throw InputError(problem_mark(drive), "load.force",
                     "the dynamic model needs the static mesh load (load.force, torque or thrust > 0)");
  }
  d.damping_ratio = drive.dynamics.damping_ratio;
  d.operating_speed = request.speed.value_or(drive.load.speed);
  DynamicsOptions options = request.options;
  options.damping_ratio = d.damping_ratio;

  // --- natural frequencies at the tangent stiffness along the travel ---------
  d.travel = d.law.travel;
  const std::vector<double> k = tangent_at_static_load(d.law, d.static_force);
  d.mean_stiffness = travel_mean(d.travel, k, d.law.period);
  d.natural_frequencies_hz = natural_frequencies_hz(d.train, d.mean_stiffness);
  d.natural_frequency_along_travel.assign(d.natural_frequencies_hz.size(), std::vector<double>(k.size()));
  for (std::size_t j = 0; j < k.size(); ++j) {
    const std::vector<double> f = natural_frequencies_hz(d.train, k[j]);
    for (std::size_t i = 0; i < f.size(); ++i) d.natural_frequency_along_travel[i][j] = f[i];
  }
  d.orders = excitation_orders(d.law);
  find_resonances(d);

  // --- responses ---------------------------------------------------------------
  if (request.response_at_speed) {
    if (!(d.operating_speed > 0)) {
      throw InputError(problem_mark(drive), "load.speed",
                       "the response at the operating speed needs load.speed > 0 (or a speed asked for)");
    }
    d.at_speed = steady_response(d.train, d.law, d.operating_speed, d.static_force, options);
    d.kv_max = d.at_speed->dynamic_factor;
    d.speed_at_kv_max = d.operating_speed;
  }
  if (request.sweep || request.stability) d.speeds = dynamics_speeds(drive, d.operating_speed);
  if (request.sweep) {
    d.sweep = speed_sweep(d.train, d.law, d.speeds, d.static_force, options);
    d.kv_max = 0;
    for (const SweepPoint& p : d.sweep) {
      for (double kv : {p.kv_up, p.kv_down}) {
        if (kv > d.kv_max) {
          d.kv_max = kv;
          d.speed_at_kv_max = p.speed;
        }
      }
      if (p.status_up != ResponseStatus::kConverged || p.status_down != ResponseStatus::kConverged) {
        const bool unbounded =
            p.status_up == ResponseStatus::kUnbounded || p.status_down == ResponseStatus::kUnbounded;
        const std::string w = std::string(unbounded ? "the response grows without bound"
                                                    : "the response is not periodic") +
                              " at some speeds of the range (parametric instability or contact loss): K_V there is "
                              "the largest force seen";
        if (std::find(d.warnings.begin(), d.warnings.end(), w) == d.warnings.end()) d.warnings.push_back(w);
      }
    }
  }
  if (request.stability) {
    d.stability_margin = std::numeric_limits<double>::infinity();
    for (double v : d.speeds) {
      const FloquetResult f = floquet(d.train, d.law, v, d.static_force, options);
      d.stability.push_back({v, f.spectral_radius});
      d.stability_margin = std::min(d.stability_margin, f.margin);
    }
  }
  return d;
}

}  // namespace rackopt
