#include "rackopt/metrics/evaluate_metrics.hpp"

#include "rackopt/statistics/goodness_of_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "rackopt/core/error.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/metrics/model_results.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::metrics {
namespace {

bool has(std::uint8_t bits, Requirement r) { return (bits & static_cast<std::uint8_t>(r)) != 0; }

[[noreturn]] void missing(const std::string& key, const std::string& message) {
  throw InputError(SourceMark{"<metric options>", 0, 0}, key, message);
}

// A problem key the metrics need: reported against the problem file.
[[noreturn]] void missing_in_problem(const Drive& drive, const std::string& key, const std::string& message) {
  throw InputError(SourceMark{drive.source_file.empty() ? "<problem>" : drive.source_file, 0, 0}, key, message);
}

std::string display(const MetricDefinition& def, double v) {
  if (def.kind) return format_quantity(v, *def.kind, def.display_unit, 4);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g %s", v, std::string(def.unit).c_str());
  return buf;
}

// Models built on the same geometry repeat its warnings: keep each once.
void add_warning(MetricValues& out, const std::string& w) {
  if (std::find(out.warnings.begin(), out.warnings.end(), w) == out.warnings.end()) out.warnings.push_back(w);
}

bool requested(std::span<const MetricRequest> requests, std::string_view name) {
  for (const MetricRequest& r : requests) {
    if (r.name == name) return true;
  }
  return false;
}

// The stresses read the computed K_V when effects.dynamics is on.
bool stress_uses_dynamics(const Drive& drive, std::span<const MetricRequest> requests) {
  if (!drive.effects.dynamics) return false;
  for (const MetricRequest& r : requests) {
    if (find_metric(r.name).models.contains(Model::kStress)) return true;
  }
  return false;
}

// What of the dynamic analysis the requests read (the natural frequencies
// and the resonance margin come with any).
DynamicsRequest dynamics_request(const Drive& drive, std::span<const MetricRequest> requests) {
  DynamicsRequest d;
  d.sweep = requested(requests, "dynamic_factor") || stress_uses_dynamics(drive, requests);
  d.stability = requested(requests, "parametric_stability_margin");
  d.response_at_speed = requested(requests, "dynamic_mesh_force_max") ||
                        requested(requests, "dynamic_transmission_error_pp") ||
                        requested(requests, "contact_loss_fraction");
  return d;
}

}  // namespace

StressInputs resolve_stress_inputs(const Drive& drive, const MetricOptions& o) {
  auto pick = [](double option, double from_drive) { return option > 0 ? option : from_drive; };
  StressInputs in;
  const LoadFactors d = drive_load_factors(drive);
  const LoadFactorOverrides& k = o.load_factors;
  in.factors.application = pick(k.application, d.application);
  in.factors.dynamic = pick(k.dynamic, d.dynamic);
  in.factors.face_contact = pick(k.face_contact, d.face_contact);
  in.factors.transverse_contact = pick(k.transverse_contact, d.transverse_contact);
  in.factors.transverse_bending = pick(k.transverse_bending, d.transverse_bending);
  // A derived K_Fbeta follows the K_Hbeta actually used.
  const double drive_face_bending =
      drive.load.face_load_factor_bending > 0 ? drive.load.face_load_factor_bending
                                              : derived_face_load_factor_bending(drive, in.factors.face_contact);
  in.factors.face_bending = pick(k.face_bending, drive_face_bending);

  const Material& mp = drive.pinion.material;
  const Material& mr = drive.rack.material;
  in.allowable_bending_pinion = pick(o.allowable_bending_pinion, mp.allowable_bending);
  in.allowable_contact_pinion = pick(o.allowable_contact_pinion, mp.allowable_contact);
  in.allowable_bending_rack = pick(o.allowable_bending_rack, pick(mr.allowable_bending, o.allowable_bending_pinion));
  in.allowable_contact_rack = pick(o.allowable_contact_rack, pick(mr.allowable_contact, o.allowable_contact_pinion));
  in.rack_root_radius = pick(o.rack_root_radius, drive.rack.root_radius);
  return in;
}

bool MetricValues::all_ok() const { return first_failure() == nullptr; }

const MetricValue* MetricValues::first_failure() const {
  for (const MetricValue& v : values) {
    if (!v.ok) return &v;
  }
  return nullptr;
}

const MetricValue& MetricValues::at(std::string_view label) const {
  for (const MetricValue& v : values) {
    if (v.label == label) return v;
  }
  throw std::out_of_range("no metric value labelled '" + std::string(label) + "'");
}

void check_metric_requests(const Drive& drive, std::span<const MetricRequest> requests,
                           const MetricOptions& o) {
  // The caller's counts, against the limits the study loader applies to the
  // same keys of metric_options.
  if (o.reliability_samples) check_count(*o.reliability_samples, kSamplesLimit, "reliability_samples");
  if (o.reliability_seed) check_count(*o.reliability_seed, kSeedLimit, "reliability_seed");
  if (o.positions_per_period) check_count(*o.positions_per_period, kPositionsPerPeriodLimit, "positions_per_period");
  check_count(o.threads, kThreadsLimit, "threads");
  std::uint8_t req = 0;
  bool reliability = false;
  for (const MetricRequest& r : requests) {
    const MetricDefinition& def = find_metric(resolve_request(r).name);
    req |= def.requirements;
    reliability = reliability || def.models.contains(Model::kWearReliability);
  }
  if (has(req, Requirement::kWear) && !(drive.wear.coefficient > 0)) {
    missing("wear.coefficient", "wear metrics need the problem's `wear` section (wear.coefficient > 0, hardness)");
  }
  if (has(req, Requirement::kDuty) && !(drive.duty.rack_meshes_per_year > 0)) {
    missing("duty.rack_meshes_per_year", "wear lives in seconds need duty.rack_meshes_per_year > 0 "
                                         "(wear_life_cycles needs no duty)");
  }
  if (has(req, Requirement::kSpeed) && !(drive.load.speed > 0)) {
    missing_in_problem(drive, "load.speed", "drive_power and pinion_speed need the rack speed load.speed (e.g. 0.5 m/s)");
  }
  if (stress_uses_dynamics(drive, requests)) req |= static_cast<std::uint8_t>(Requirement::kMovingMass);
  if (has(req, Requirement::kMovingMass) && !drive.dynamics.given()) {
    missing_in_problem(drive, "dynamics.moving_mass",
                       "the dynamics metrics need the problem's `dynamics` section: at least dynamics.moving_mass, the "
                       "mass this pinion drives along the rack (docs/yaml.md)");
  }
  const DynamicsRequest dyn = dynamics_request(drive, requests);
  if ((dyn.sweep || dyn.stability) && drive.dynamics.speed_points <= 0 && !(drive.load.speed > 0)) {
    missing_in_problem(drive, "dynamics.speed_range",
                       "dynamic_factor (and the stresses with effects.dynamics) sweep a speed range: give "
                       "dynamics.speed_range {from, to, points} or load.speed");
  }
  if (has(req, Requirement::kBodyHeight) && !(drive.rack.body_height > 0)) {
    missing_in_problem(drive, "rack.body_height",
                       "rack_section_height needs a rectangular rack body (rack.body_height); the rack section is "
                       "given explicitly");
  }
  auto nonneg = [](double v, const char* key) {
    if (!std::isfinite(v) || v < 0) missing(key, "must be >= 0 and finite (0 = not given)");
  };
  nonneg(o.cost.rack_per_kg, "cost.rack_per_kg");
  nonneg(o.cost.pinion_per_kg, "cost.pinion_per_kg");
  nonneg(o.cost.per_support, "cost.per_support");
  nonneg(o.cost.rack_length, "cost.rack_length");
  if (has(req, Requirement::kRackLength) && o.cost.pinion_per_kg > 0 && !(o.cost.rack_length > 0) &&
      !(drive.duty.stroke > 0)) {
    missing("cost.rack_length", "cost_per_metre spreads the pinion's cost over the installed rack: give "
                                "metric_options.cost.rack_length (or the problem's duty.stroke), or cost.pinion_per_kg: 0");
  }
  nonneg(o.allowable_bending_pinion, "allowable_bending_pinion");
  nonneg(o.allowable_bending_rack, "allowable_bending_rack");
  nonneg(o.allowable_contact_pinion, "allowable_contact_pinion");
  nonneg(o.allowable_contact_rack, "allowable_contact_rack");
  nonneg(o.rack_root_radius, "rack_root_radius");
  nonneg(o.load_factors.application, "load_factors.application");
  nonneg(o.load_factors.dynamic, "load_factors.dynamic");
  nonneg(o.load_factors.face_bending, "load_factors.face_bending");
  nonneg(o.load_factors.transverse_bending, "load_factors.transverse_bending");
  nonneg(o.load_factors.face_contact, "load_factors.face_contact");
  nonneg(o.load_factors.transverse_contact, "load_factors.transverse_contact");
  if (o.positions_per_period && (*o.positions_per_period < 4 || *o.positions_per_period > 10000))
    missing("positions_per_period", "must be a whole number in 4 ... 10000 (absent: the problem's "
                                    "numerics.positions_per_period)");
  // The problem key a member's allowable comes from. A drive built in code
  // may have unnamed materials.
  auto key_of = [](const Material& m, const char* which) {
    return "materials." + (m.name.empty() ? std::string("<name>") : m.name) + "." + which;
  };
  // Drives built in code skip the loader's checks.
  for (const Material* m : {&drive.pinion.material, &drive.rack.material}) {
    for (const auto& [v, which] : {std::pair{m->allowable_bending, "allowable_bending"},
                                   std::pair{m->allowable_contact, "allowable_contact"}}) {
      if (!std::isfinite(v) || v < 0) {
        missing_in_problem(drive, key_of(*m, which), "must be > 0 and finite (0 = not given)");
      }
    }
  }
  const StressInputs in = resolve_stress_inputs(drive, o);
  auto need = [&](double value, const char* metric, const char* member, const Material& m, const char* which,
                  const char* option) {
    if (value > 0) return;
    const std::string key = key_of(m, which);
    missing_in_problem(drive, key, std::string(metric) + " needs " + key + " (the permissible stress of the " + member +
                     "'s material " + (m.name.empty() ? std::string("(unnamed)") : "'" + m.name + "'") +
                     ", e.g. " + (std::string(which) == "allowable_bending" ? "740 MPa" : "1040 MPa") +
                     "; docs/metrics.md), or MetricOptions::" + option + " > 0");
  };
  if (has(req, Requirement::kAllowableBending)) {
    need(in.allowable_bending_pinion, "root_bending_safety", "pinion", drive.pinion.material, "allowable_bending",
         "allowable_bending_pinion");
    need(in.allowable_bending_rack, "root_bending_safety", "rack", drive.rack.material, "allowable_bending",
         "allowable_bending_rack");
  }
  if (has(req, Requirement::kAllowableContact)) {
    need(in.allowable_contact_pinion, "contact_safety", "pinion", drive.pinion.material, "allowable_contact",
         "allowable_contact_pinion");
    need(in.allowable_contact_rack, "contact_safety", "rack", drive.rack.material, "allowable_contact",
         "allowable_contact_rack");
  }
  if (reliability) {
    const std::size_t n_inputs = drive.reliability.inputs.size();
    const bool monte_carlo = n_inputs >= 2 || (n_inputs == 1 && !o.exact_quantile);
    if (monte_carlo && o.bootstrap_replicates && *o.bootstrap_replicates < statistics::kMinBootstrapReplicates)
      missing("bootstrap_replicates", "must be >= " + std::to_string(statistics::kMinBootstrapReplicates) +
                                          " (or absent: the problem's reliability.bootstrap_replicates)");
  }
}

MetricValues evaluate_metrics(const Drive& drive, std::span<const MetricRequest> requests,
                              const MetricOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  check_metric_requests(drive, requests, o);

  std::vector<MetricRequest> resolved;
  std::vector<const MetricDefinition*> defs;
  ModelSet needed;
  for (const MetricRequest& r : requests) {
    resolved.push_back(resolve_request(r));
    defs.push_back(&find_metric(r.name));
    needed.insert(defs.back()->models);
  }
  // The stresses with effects.dynamics read the computed K_V.
  const bool dynamic_stress = stress_uses_dynamics(drive, requests);
  if (dynamic_stress) needed.insert(Model::kDynamics);
  MetricValues out;
  ModelResults m;
  m.drive = &drive;
  m.options = &o;
  m.stress_inputs = resolve_stress_inputs(drive, o);
  auto failure_of = [](const DesignError& e, Model model) {
    return ModelFailure{e.code(), e.what(), std::string(model_name(model))};
  };

  // --- geometry ---------------------------------------------------------
  if (needed.contains(Model::kGeometry)) {
    out.models_run.insert(Model::kGeometry);
    ++out.model_runs;
    try {
      m.geometry_slot.value = build_mesh_geometry(drive);
      for (const std::string& w : m.geometry_slot.value->warnings) add_warning(out, w);
    } catch (const DesignError& e) {
      m.geometry_slot.failure = failure_of(e, Model::kGeometry);
    }
  }

  // --- stiffness curve ----------------------------------------------------
  if (needed.contains(Model::kStiffnessCurve)) {
    out.models_run.insert(Model::kStiffnessCurve);
    ++out.model_runs;
    try {
      // The geometry computed above is the model's own: reuse it.
      const MeshStiffnessModel model = m.geometry_slot.value ? MeshStiffnessModel(drive, *m.geometry_slot.value)
                                                             : MeshStiffnessModel(drive);
      // The metrics read each sample's own values and the curve's summary,
      // never its pairs: the summary curve skips storing them.
      m.curve_slot.value = model.curve(CurveDetail::kSummary, o.positions_per_period.value_or(0));
      // Post-processing of the one curve: listed in models_run, not counted as runs.
      m.dynamics_figures = mesh_dynamics_figures(model, *m.curve_slot.value, needed);
      if (m.dynamics_figures.ripple) out.models_run.insert(Model::kMeshRipple);
      if (m.dynamics_figures.transmission_error) out.models_run.insert(Model::kTransmissionError);
      for (const std::string& w : m.curve_slot.value->warnings) add_warning(out, w);
    } catch (const DesignError& e) {
      m.curve_slot.failure = failure_of(e, Model::kStiffnessCurve);
    }
  }

  // --- wear ------------------------------------------------------------------
  // wear_life_at_R goes through run_wear_reliability, whose result also holds
  // the nominal life: one wear model serves wear_life and every R.
  //  * no random input: the deterministic life (reached with probability 1);
  //  * one input (and exact_quantile): its exact quantile path, without
  //    Monte Carlo samples (exact_only; one sample when no exact path exists,
  //    whose failure then names the cause);
  //  * otherwise: Monte Carlo with the fixed seed, the fitted life at R
  //    (empirical quantile when nothing could be fitted).
  const std::vector<RandomInput>& inputs = drive.reliability.inputs;
  const bool exact = inputs.size() == 1 && o.exact_quantile;
  if (needed.contains(Model::kWearReliability)) {
    LifeAtR rel;
    for (std::size_t i = 0; i < resolved.size(); ++i) {
      if (!defs[i]->models.contains(Model::kWearReliability)) continue;
      const double R = *resolved[i].parameter;
      if (std::find(rel.reliabilities.begin(), rel.reliabilities.end(), R) == rel.reliabilities.end())
        rel.reliabilities.push_back(R);
    }
    out.models_run.insert(Model::kWearReliability);
    if (needed.contains(Model::kWearLife)) out.models_run.insert(Model::kWearLife);
    ++out.model_runs;
    try {
      Drive d = drive;
      d.reliability.reliabilities = rel.reliabilities;
      d.reliability.times.clear();
      WearReliabilityOptions ro = wear_reliability_options(drive);
      if (exact) {
        ro.samples = 1;
        ro.exact_only = true;
      } else if (o.reliability_samples) {
        ro.samples = *o.reliability_samples;
      }
      if (o.reliability_seed) ro.seed = *o.reliability_seed;
      ro.threads = std::max(1u, o.threads);
      if (o.bootstrap_replicates) ro.bootstrap_replicates = *o.bootstrap_replicates;
      // The metrics read the nominal life's years, cycles, criterion, reason
      // and warnings only.
      ro.nominal_detail = WearModel::Detail::kLifeOnly;
      // Exact path: the life at R is one direct life at the input's quantile
      // and no R(t) is asked for, so a life table (about 11 model lives)
      // would cost more than the one sample it serves (9.4 ms vs 3 ms).
      if (exact) ro.life_table = false;
      // Ctrl-C during a long Monte Carlo: the evaluation ends (Interrupted,
      // never recorded as a failure) instead of running to the end.
      ro.stop = [] { return stop_requested(); };
      const WearReliabilityResult r = run_wear_reliability(d, ro);
      m.wear_slot.value = r.nominal;
      for (const std::string& w : r.warnings) add_warning(out, w);  // a life at R above the nominal life
      // No sample could be evaluated (every value outside its input's
      // domain): no life at R, the metric fails with the cause.
      if (!inputs.empty() && r.status == SamplingStatus::kNoValidSample && !(exact && r.exact.available)) {
        throw DesignError("no_valid_reliability_sample",
                          r.summary.warnings.empty() ? std::string("no reliability sample could be evaluated")
                                                     : r.summary.warnings.back());
      }
      const std::string all_fail =
          r.status == SamplingStatus::kEverySampleFailsAtOnce ? " (every sample fails at once: no life at any R)" : "";
      for (std::size_t k = 0; k < rel.reliabilities.size(); ++k) {
        if (inputs.empty()) {
          rel.life_s.push_back(r.nominal.life_years * kSecondsPerYear);
          rel.remark.push_back("no reliability inputs: the deterministic wear life");
        } else if (exact && r.exact.available) {
          rel.life_s.push_back(r.exact.life_at_R_years.at(k) * kSecondsPerYear);
          rel.remark.push_back("exact quantile of " + r.exact.input + " (life " +
                               (r.exact.life_increases ? "increases" : "decreases") + " with it)" +
                               (r.exact.failed_at_start >= 1.0 ? " (every sample fails at once: no life at any R)"
                                                                : ""));
        } else {
          const statistics::LifeAtReliability& la = r.summary.life.at(k);
          const std::string n = std::to_string(r.summary.samples_total);
          if (la.fit) {
            const statistics::CandidateFit* cf = r.summary.chosen_fit();
            rel.life_s.push_back(la.fit->estimate);
            rel.remark.push_back("Monte Carlo, " + n + " samples, fitted " +
                                 (cf ? cf->fit->distribution.describe() : std::string()) +
                                 (r.summary.chosen_accepted ? "" : " (no candidate passed the KS test)"));
          } else {
            rel.life_s.push_back(la.empirical.estimate);
            rel.remark.push_back("Monte Carlo, " + n + " samples, empirical quantile (no distribution could be fitted)" +
                                 all_fail);
          }
        }
      }
      m.life_at_R_slot.value = std::move(rel);
    } catch (const DesignError& e) {
      m.wear_slot.failure = failure_of(e, Model::kWearReliability);
      m.life_at_R_slot.failure = failure_of(e, Model::kWearReliability);
    }
  } else if (needed.contains(Model::kWearLife)) {
    out.models_run.insert(Model::kWearLife);
    ++out.model_runs;
    try {
      const WearModel model(drive);
      for (const std::string& w : model.warnings()) add_warning(out, w);
      m.wear_slot.value = model.life({}, WearModel::Detail::kLifeOnly);  // read as above: the life alone
    } catch (const DesignError& e) {
      m.wear_slot.failure = failure_of(e, Model::kWearLife);
    }
  }
  if (m.wear_slot.value) {
    for (const std::string& w : m.wear_slot.value->warnings) add_warning(out, w);
  }

  // --- dynamics ------------------------------------------------------------
  if (needed.contains(Model::kDynamics)) {
    out.models_run.insert(Model::kDynamics);
    ++out.model_runs;
    if (m.geometry_slot.failure) {
      m.dynamics_slot.failure = m.geometry_slot.failure;
    } else {
      try {
        const MeshStiffnessModel model(drive, *m.geometry_slot.value);
        DynamicsRequest dr = dynamics_request(drive, requests);
        dr.positions_per_period = o.positions_per_period.value_or(0);
        m.dynamics_slot.value = analyse_drive_dynamics(drive, model, dr);
        for (const std::string& w : m.dynamics_slot.value->warnings) add_warning(out, w);
        // An explicit metric option K_V still wins: it is the caller's own number.
        // ISO 6336-1 never lets K_V below 1.
        if (dynamic_stress && !(o.load_factors.dynamic > 0))
          m.stress_inputs.factors.dynamic = std::max(1.0, m.dynamics_slot.value->kv_max);
      } catch (const DesignError& e) {
        m.dynamics_slot.failure = failure_of(e, Model::kDynamics);
      } catch (const std::invalid_argument& e) {
        // The drive train or the law cannot be integrated (a message naming the quantity).
        m.dynamics_slot.failure = ModelFailure{"dynamics_input", e.what(), std::string(model_name(Model::kDynamics))};
      }
    }
  }

  // --- stresses ------------------------------------------------------------
  if (needed.contains(Model::kStress)) {
    out.models_run.insert(Model::kStress);
    ++out.model_runs;
    if (m.geometry_slot.failure) {
      m.stress_slot.failure = m.geometry_slot.failure;
    } else if (dynamic_stress && m.dynamics_slot.failure) {
      m.stress_slot.failure = m.dynamics_slot.failure;
    } else {
      try {
        m.stress_slot.value = tooth_stress(drive, *m.geometry_slot.value, m.stress_inputs.factors,
                                           m.stress_inputs.rack_root_radius);
        if (m.stress_slot.value->rack_root_radius_clamped) {
          add_warning(out, "rack root round clamped to the largest that fits the rack space: " +
                               format_quantity(m.stress_slot.value->rack_root_radius, QuantityKind::kLength, "mm", 4));
        }
      } catch (const DesignError& e) {
        m.stress_slot.failure = failure_of(e, Model::kStress);
      }
    }
  }

  // --- causes --------------------------------------------------------------
  // Every model builds the geometry first: a model that failed because the
  // geometry is impossible reports the geometry as the cause (a contact
  // ratio below 1 is not a wear failure). Checked only on a failure, so the
  // geometry is not built twice on the normal path.
  {
    std::optional<ModelFailure> geometry_failure = m.geometry_slot.failure;
    bool geometry_known = m.geometry_slot.computed();
    auto attribute = [&](auto& slot) {
      if (!slot.failure || slot.failure->model == model_name(Model::kGeometry)) return;
      if (!geometry_known) {
        geometry_known = true;
        try {
          build_mesh_geometry(drive);
        } catch (const DesignError& e) {
          geometry_failure = failure_of(e, Model::kGeometry);
        }
      }
      if (geometry_failure) slot.failure = geometry_failure;
    };
    attribute(m.curve_slot);
    attribute(m.wear_slot);
    attribute(m.life_at_R_slot);
    attribute(m.stress_slot);
    attribute(m.dynamics_slot);
  }

  // --- values --------------------------------------------------------------
  for (std::size_t i = 0; i < resolved.size(); ++i) {
    const MetricDefinition& def = *defs[i];
    MetricValue mv;
    mv.request = requests[i];
    mv.label = to_string(requests[i]);
    try {
      const MetricOutcome oc = def.compute(m, resolved[i]);
      if (std::isfinite(oc.value)) {
        mv.ok = true;
        mv.value = oc.value;
        mv.display = display(def, oc.value);
        mv.message = oc.remark;
      } else {
        mv.error_code = "non_finite";
        mv.message = "metric " + mv.label + " evaluated to a non-finite number";
        mv.cause = "metric";
      }
    } catch (const ModelFailed& e) {
      mv.error_code = e.code();
      mv.message = e.what();
      mv.cause = e.model();
    } catch (const DesignError& e) {
      mv.error_code = e.code();
      mv.message = e.what();
      mv.cause = "metric";
    }
    out.values.push_back(std::move(mv));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rackopt::metrics
