// rackopt._rackopt.Problem: a problem (its YAML text, the name its messages
// carry and the `--set` assignments over it) with the drive built from it,
// and the models of that drive as Python values: dicts of SI numbers and
// NumPy arrays. Every model call releases the GIL, so Python threads can
// evaluate several problems at once.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "python_bindings.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/marked_yaml/input_file.hpp"
#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/units/units.hpp"
#include "rackopt/wear/wear_life.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace py = pybind11;

namespace rackopt::python {
namespace {

using Array = py::array_t<double>;

Array array(const std::vector<double>& v) { return Array(static_cast<py::ssize_t>(v.size()), v.data()); }

py::dict geometry_dict(const MeshGeometry& g) {
  py::dict pinion, rack, path;
  const PinionGeometry& p = g.pinion;
  pinion["pitch_radius"] = p.pitch_radius;
  pinion["base_radius"] = p.base_radius;
  pinion["tip_radius"] = p.tip_radius;
  pinion["root_radius"] = p.root_radius;
  pinion["form_radius"] = p.form_radius;
  pinion["tip_thickness"] = p.tip_thickness;
  pinion["cutter_tip_radius"] = p.cutter_tip_radius;
  pinion["undercut_teeth_limit"] = p.undercut_teeth_limit;
  pinion["undercut"] = p.undercut;
  rack["pitch"] = g.rack.pitch;
  rack["addendum"] = g.rack.addendum;
  rack["dedendum"] = g.rack.dedendum;
  rack["half_thickness_at_root"] = g.rack.half_thickness_at_root;
  rack["half_thickness_at_tip"] = g.rack.half_thickness_at_tip;
  path["s_pitch"] = g.path.s_pitch;
  path["s_start"] = g.path.s_start;
  path["s_end"] = g.path.s_end;
  path["start_limited_by"] = g.path.start_limited_by;
  path["base_pitch"] = g.path.base_pitch;
  path["contact_ratio"] = g.path.contact_ratio;
  path["contact_ratio_geometric"] = g.path.contact_ratio_geometric;
  py::list zones;
  for (const Zone& z : g.zones) {
    py::dict d;
    d["pairs"] = z.pairs;
    d["length_loa"] = z.length_loa;
    d["length_travel"] = z.length_travel;
    zones.append(d);
  }
  py::dict out;
  out["pinion"] = pinion;
  out["rack"] = rack;
  out["path"] = path;
  out["zones"] = zones;
  out["contact_ratio"] = g.path.contact_ratio;
  out["pressure_angle"] = g.pressure_angle;
  out["clearance"] = g.clearance;
  out["backlash"] = g.backlash;
  out["warnings"] = g.warnings;
  return out;
}

// One field of a pair state, for the breakdown's per-slot arrays.
struct PairField {
  const char* name;
  double (*get)(const PairState&);
};

// The per-pair quantities of a curve, named as stiffness.csv's pair
// columns without their unit suffix (docs/output.md); compliances in m/N.
const PairField kPairFields[] = {
    {"rack_tooth", [](const PairState& p) { return double(p.rack_tooth); }},
    {"pinion_tooth", [](const PairState& p) { return double(p.pinion_tooth); }},
    {"s", [](const PairState& p) { return p.s; }},
    {"x", [](const PairState& p) { return p.x; }},
    {"load_share", [](const PairState& p) { return p.load_share; }},
    {"c_pinion_bending", [](const PairState& p) { return p.pinion.bending; }},
    {"c_pinion_shear", [](const PairState& p) { return p.pinion.shear; }},
    {"c_pinion_axial", [](const PairState& p) { return p.pinion.axial; }},
    {"c_fillet", [](const PairState& p) { return p.fillet; }},
    {"c_hertz", [](const PairState& p) { return p.hertz; }},
    {"c_rack_bending", [](const PairState& p) { return p.rack.bending; }},
    {"c_rack_shear", [](const PairState& p) { return p.rack.shear; }},
    {"c_rack_axial", [](const PairState& p) { return p.rack.axial; }},
    {"c_rack_foundation", [](const PairState& p) { return p.rack_foundation; }},
    {"c_body", [](const PairState& p) { return p.body; }},
    {"relief", [](const PairState& p) { return p.relief; }},
};

py::dict curve_dict(const StiffnessCurve& c) {
  const std::size_t n = c.samples.size();
  const std::size_t slots = static_cast<std::size_t>(std::max(c.max_pairs, 0));
  std::vector<double> travel(n), k(n), approach(n), local(n), pairs(n);
  for (std::size_t i = 0; i < n; ++i) {
    const MeshState& s = c.samples[i];
    travel[i] = s.travel;
    k[i] = s.stiffness;
    approach[i] = s.approach;
    local[i] = s.local_stiffness;
    pairs[i] = static_cast<double>(s.pairs.size());
  }
  // Slot arrays: samples x slots, NaN where the slot holds no pair (plots
  // then leave a gap instead of drawing the pair out of mesh at zero).
  py::array_t<bool> in_mesh({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(slots)});
  auto mesh = in_mesh.mutable_unchecked<2>();
  py::dict breakdown;
  std::vector<py::array_t<double>> fields;
  for (const PairField& f : kPairFields) {
    fields.emplace_back(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(slots)});
    breakdown[f.name] = fields.back();
  }
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t q = 0; q < slots; ++q) {
      const PairState* p = nullptr;
      for (const PairState& cand : c.samples[i].pairs) {
        if (cand.slot == static_cast<int>(q)) p = &cand;
      }
      mesh(i, q) = p != nullptr;
      for (std::size_t f = 0; f < fields.size(); ++f) {
        fields[f].mutable_at(i, q) = p ? kPairFields[f].get(*p) : kNone;
      }
    }
  }
  breakdown["in_mesh"] = in_mesh;
  py::dict out;
  out["travel"] = array(travel);
  out["stiffness"] = array(k);
  out["approach"] = array(approach);
  out["local_stiffness"] = array(local);
  out["pairs_in_mesh"] = array(pairs);
  out["breakpoints"] = array(c.breakpoints);
  out["k_min"] = c.k_min;
  out["k_max"] = c.k_max;
  out["k_mean"] = c.k_mean;
  out["k_fluctuation"] = c.k_fluctuation;
  out["travel_at_min"] = c.travel_at_min;
  out["travel_at_max"] = c.travel_at_max;
  out["breakdown"] = breakdown;
  out["warnings"] = c.warnings;
  return out;
}

py::dict profile_dict(const WearProfile& p) {
  py::dict d;
  d["s"] = array(p.s);
  d["position"] = array(p.position);
  d["radius_or_height"] = array(p.radius_or_height);
  d["depth"] = array(p.depth);
  return d;
}

const char* member_name(Member m) { return m == Member::kPinion ? "pinion" : "rack"; }

py::dict wear_life_dict(const WearLifeResult& r) {
  py::dict d;
  d["life_cycles"] = r.life_cycles;
  d["life_pinion_cycles"] = r.life_pinion_cycles;
  d["life_years"] = r.life_years;
  d["life"] = r.life_years * kSecondsPerYear;
  d["criterion"] = r.criterion;
  d["reason"] = r.reason;
  d["limiting_member"] = member_name(r.limiting_member);
  d["initial_contact_ratio"] = r.initial_contact_ratio;
  d["final_contact_ratio"] = r.final_contact_ratio;
  d["max_depth"] = r.max_depth;
  d["max_depth_member"] = member_name(r.max_depth_member);
  d["max_depth_position"] = r.max_depth_position;
  d["pinion"] = profile_dict(r.pinion);
  d["rack"] = profile_dict(r.rack);
  py::list snaps;
  for (const WearSnapshot& s : r.snapshots) {
    py::dict sd;
    sd["fraction"] = s.fraction;
    sd["cycles"] = s.cycles;
    sd["years"] = s.years;
    sd["contact_ratio"] = s.contact_ratio;
    sd["pinion"] = profile_dict(s.pinion);
    sd["rack"] = profile_dict(s.rack);
    snaps.append(sd);
  }
  d["snapshots"] = snaps;
  d["warnings"] = r.warnings;
  return d;
}

// "key=<17 digits> <SI unit>": a design value as an override that gives
// the drive the value bit for bit (the parser reads 17 digits exactly).
std::string si_assignment(const std::string& key, double value) {
  const auto kind = problem_key_kind(key);
  if (!kind) {
    throw InputError(SourceMark{"<values>", 0, 0}, key, "not a numeric problem key (docs/yaml.md lists them)");
  }
  if (!std::isfinite(value)) throw InputError(SourceMark{"<values>", 0, 0}, key, "the value is not finite");
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  std::string out = key + "=" + buf;
  const std::string_view unit = si_unit(*kind);
  if (!unit.empty()) out += " " + std::string(unit);
  return out;
}

}  // namespace

Problem::Problem(std::string yaml_text, std::string name, std::vector<std::string> overrides)
    : yaml_text_(std::move(yaml_text)), name_(std::move(name)), overrides_(std::move(overrides)) {
  drive_ = std::make_shared<const Drive>(load_problem_text(yaml_text_, name_, overrides_));
}

Problem Problem::from_file(const std::string& path, const std::vector<std::string>& overrides) {
  return Problem(read_input_file(path, "problem file"), path, overrides);
}

Problem Problem::with_overrides(const std::vector<std::string>& more) const {
  std::vector<std::string> all = overrides_;
  all.insert(all.end(), more.begin(), more.end());
  return Problem(yaml_text_, name_, all);
}

Problem Problem::with_values(const std::map<std::string, double>& values) const {
  std::vector<std::string> assignments;
  for (const auto& [key, value] : values) assignments.push_back(si_assignment(key, value));
  return with_overrides(assignments);
}

void bind_problem(py::module_& m) {
  py::class_<Problem>(m, "Problem")
      .def(py::init<std::string, std::string, std::vector<std::string>>(), py::arg("yaml_text"),
           py::arg("name") = "<string>", py::arg("overrides") = std::vector<std::string>{})
      .def_static("from_file", &Problem::from_file, py::arg("path"),
                  py::arg("overrides") = std::vector<std::string>{})
      .def("with_overrides", &Problem::with_overrides, py::arg("assignments"))
      .def("with_values", &Problem::with_values, py::arg("values"))
      .def_property_readonly("name", [](const Problem& p) { return p.drive().name; })
      .def_property_readonly("source", &Problem::name)
      .def_property_readonly("yaml_text", &Problem::yaml_text)
      .def_property_readonly("overrides", &Problem::overrides)
      .def("geometry",
           [](const Problem& p) {
             MeshGeometry g;
             {
               py::gil_scoped_release free;
               g = build_mesh_geometry(p.drive());
             }
             return geometry_dict(g);
           })
      .def(
          "stiffness_curve",
          [](const Problem& p, long positions_per_period) {
            if (positions_per_period != 0) check_count(positions_per_period, kPositionsPerPeriodLimit, "positions_per_period");
            StiffnessCurve c;
            {
              py::gil_scoped_release free;
              c = MeshStiffnessModel(p.drive()).curve(CurveDetail::kFull, static_cast<int>(positions_per_period));
            }
            return curve_dict(c);
          },
          py::arg("positions_per_period") = 0)
      .def("wear_life",
           [](const Problem& p) {
             WearLifeResult r;
             {
               py::gil_scoped_release free;
               r = WearModel(p.drive()).life();
             }
             return wear_life_dict(r);
           })
      .def(
          "wear_reliability",
          [](const Problem& p, std::optional<long> samples, std::optional<long> seed, long threads) {
            // Python's ints are unbounded: checked here before the library's
            // unsigned takes them (run_wear_reliability checks the rest).
            check_count(threads, kThreadsLimit, "threads");
            std::optional<WearReliabilityResult> r;
            {
              py::gil_scoped_release free;
              WearReliabilityOptions opt = wear_reliability_options(p.drive());
              opt.samples = samples;
              opt.seed = seed;
              opt.threads = static_cast<unsigned>(threads);
              r = run_wear_reliability(p.drive(), opt);
            }
            py::dict d = py::module_::import("json").attr("loads")(wear_json(p.drive(), *r, WearFiles{}, 0.0));
            d["nominal"] = wear_life_dict(r->nominal);
            std::vector<double> lives;
            for (const auto& s : r->lives) lives.push_back(s.value);
            d["lives"] = array(lives);
            d["input_keys"] = r->input_keys;
            d["input_values"] = r->input_values;
            d["criteria"] = r->criteria;
            return d;
          },
          py::arg("samples") = std::nullopt, py::arg("seed") = std::nullopt, py::arg("threads") = 0L)
      .def(
          "metrics",
          [](const Problem& p, const std::vector<std::string>& names, std::optional<long> positions_per_period,
             std::optional<long> reliability_samples, std::optional<long> reliability_seed, long threads) {
            // Python's ints are unbounded: the narrower library types take them
            // only once inside the shared limits (evaluate_metrics checks them too).
            if (positions_per_period) check_count(*positions_per_period, kPositionsPerPeriodLimit, "positions_per_period");
            check_count(threads, kThreadsLimit, "threads");
            std::vector<metrics::MetricRequest> requests;
            for (const std::string& n : names) {
              requests.push_back(metrics::resolve_request(metrics::parse_metric_request(n)));
            }
            metrics::MetricOptions opt;
            if (positions_per_period) opt.positions_per_period = static_cast<int>(*positions_per_period);
            opt.reliability_samples = reliability_samples;
            opt.reliability_seed = reliability_seed;
            opt.threads = static_cast<unsigned>(threads);
            metrics::MetricValues v;
            {
              py::gil_scoped_release free;
              v = metrics::evaluate_metrics(p.drive(), requests, opt);
            }
            py::list out;
            for (const metrics::MetricValue& mv : v.values) {
              py::dict d;
              d["label"] = mv.label;
              d["ok"] = mv.ok;
              d["value"] = mv.ok ? py::cast(mv.value) : py::none();
              d["display"] = mv.display;
              d["error_code"] = mv.error_code;
              d["message"] = mv.message;
              d["cause"] = mv.cause;
              out.append(d);
            }
            py::dict result;
            result["values"] = out;
            result["models"] = v.models_run.names();
            result["warnings"] = v.warnings;
            return result;
          },
          py::arg("names"), py::arg("positions_per_period") = std::nullopt,
          py::arg("reliability_samples") = std::nullopt, py::arg("reliability_seed") = std::nullopt,
          py::arg("threads") = 1L);

  m.def("metric_definitions", [] {
    py::list out;
    for (const metrics::MetricDefinition& d : metrics::metric_registry()) {
      py::dict e;
      e["name"] = std::string(d.name);
      e["unit"] = std::string(d.unit);
      e["display_unit"] = std::string(d.display_unit);
      e["description"] = std::string(d.description);
      e["models"] = d.models.names();
      if (d.parameter.use != metrics::ParameterSpec::Use::kNone) {
        e["parameter"] = std::string(d.parameter.name);
      }
      out.append(e);
    }
    return out;
  });
}

}  // namespace rackopt::python
