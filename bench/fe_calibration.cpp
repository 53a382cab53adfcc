// FE reference data the analytic stiffness model is calibrated and checked
// against: single-tooth compliances of the rack and of the pinion over a
// design sample, and mesh positions in the single-pair zone (the local
// contact term is what is left of the pair's FE compliance once both FE
// tooth compliances are taken off), and mesh positions over one whole mesh
// period of the shipped problems (single-, double- and, where it occurs,
// triple-pair zones: what the pairs' coupling through the bodies would
// show). Writes CSV files with their provenance
// in '#' lines; tests/data/fe/ holds the committed ones and their README
// says how they were made (docs/models/fe_calibration.md).
//
//   ./build/fe_calibration --set rack|pinion|contact|period|spread|supports --out FILE
//                          [--threads T] [--level L] [--limit N]
//   ./build/fe_calibration --fit rack|pinion|coupling|supports FILE[,FILE...]
//
// --fit rack: the least-squares fit of the rack foundation law
// (stiffness/rack_foundation.hpp) to a rack data file, printed as the
// coefficient rows of rack_foundation.cpp, with the residuals before and
// after and the fit on each base tooth form predicting the other.
// --fit pinion: the same for the fillet calibration
// (stiffness/fillet_calibration.hpp) on a pinion data file, the data's
// analytic column being the tooth beam + Sainsot's foundation (run the
// data set with effects.fillet_calibration off, as --set pinion does), and
// each tooth count left out in turn.
// --fit coupling FILE[,FILE...]: the share kappa of the pairs' coupling
// (stiffness/pair_coupling.hpp), linear in the pressure angle, on period
// data files (period, spread), the largest K error of the double-pair
// positions made smallest, and each design left out in turn.
// --fit supports: the supported rack's law (stiffness/supported_rack.hpp)
// on a supports data file, fitted on the slender spans, each design left
// out in turn.
//
// Rows are appended to FILE.partial as the solves finish, so an interrupted
// run resumes where it stopped; the finished file is sorted by key and
// renamed to FILE. Every row is one FE solve (or, for contact, one mesh
// position with its two single-tooth solves) on a variant of a shipped
// problem, given by --set-style overrides in the `design` column.
#include <algorithm>
#include <cstdlib>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Dense>

#include "rackopt/core/error.hpp"
#include "rackopt/core/text.hpp"
#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/fe/ccx_runner.hpp"
#include "rackopt/fe/mesh_position_fe.hpp"
#include "rackopt/fe/rack_span_fe.hpp"
#include "rackopt/fe/tooth_compliance_fe.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/fillet_foundation.hpp"
#include "rackopt/stiffness/hertz.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/supported_rack.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace {

using namespace rackopt;
using namespace rackopt::fe;

struct Args {
  std::string set;
  std::string fit;  // --fit: the data set to fit
  std::string fit_file;
  std::string out;
  int threads = 1;
  int level = 0;
  int limit = 0;  // 0: every job
};

struct Job {
  std::string key;        // unique: problem|overrides|position
  std::string problem;    // name in problems/
  std::vector<std::string> overrides;
  double fraction = 0;    // position along the path of contact (0 = start, 1 = end), or of the single-pair zone
};

std::string problem_path(const std::string& name) {
  return std::string(RACKOPT_SOURCE_DIR) + "/problems/" + name + ".yaml";
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.7g", v);
  return buf;
}

Drive job_drive(const Job& j) {
  Drive d = load_problem(problem_path(j.problem), j.overrides);
  // The data's analytic columns are what the calibrations correct.
  d.effects.fillet_calibration = false;
  d.effects.rack_foundation = false;
  d.effects.rack_span = RackSpanModel::kRigid;
  d.spalls.clear();
  d.pinion.tip_relief = {};
  d.pinion.root_relief = {};
  d.rack.tip_relief = {};
  d.rack.root_relief = {};
  return d;
}

// The sample. Tooth compliance scales with 1/(E b) and is otherwise a
// function of the tooth shape in module units, so the sample varies shapes
// (pressure angle, tooth form, body depth, root round; teeth and profile
// shift for the pinion) at one module per base problem.
std::vector<Job> rack_jobs() {
  std::vector<Job> jobs;
  const std::vector<std::string> bases = {"rack_railway", "gantry_axis"};
  for (const std::string& base : bases) {
    const Drive d0 = load_problem(problem_path(base));
    const double m = d0.pinion.module;
    for (double alpha : {14.0, 20.0, 25.0}) {
      for (double depth : {1.5, 3.0, 6.0}) {
        for (double rho : {0.1, 0.3}) {
          std::vector<std::string> ov = {"pinion.pressure_angle=" + fmt(alpha) + " deg",
                                         "rack.body_height=" + fmt(depth * m * 1e3) + " mm",
                                         "rack.root_radius=" + fmt(rho * m * 1e3) + " mm",
                                         "effects.interference_limit=off"};
          for (double f : {0.05, 0.35, 0.65, 0.95}) {
            jobs.push_back({base + "|" + join(ov, ";") + "|" + fmt(f), base, ov, f});
          }
        }
      }
    }
  }
  return jobs;
}

std::vector<Job> pinion_jobs() {
  std::vector<Job> jobs;
  for (int z : {12, 18, 26, 40}) {
    for (double x : {-0.3, 0.0, 0.5}) {
      for (double alpha : {14.0, 20.0, 25.0}) {
        std::vector<std::string> ov = {"pinion.teeth=" + std::to_string(z), "pinion.profile_shift=" + fmt(x),
                                       "pinion.pressure_angle=" + fmt(alpha) + " deg"};
        // The analytic column is what the calibration corrects: the beam and Sainsot's term.
        for (double f : {0.05, 0.35, 0.65, 0.95}) {
          jobs.push_back({"gantry_axis|" + join(ov, ";") + "|" + fmt(f), "gantry_axis", ov, f});
        }
      }
    }
  }
  return jobs;
}

std::vector<Job> contact_jobs() {
  std::vector<Job> jobs;
  for (const char* p : {"gantry_axis", "large_module", "rack_railway", "ship_lift"}) {
    jobs.push_back({std::string(p) + "||0.5", p, {}, 0.5});
  }
  // A spread: pressure angle, teeth and shift on the gantry axis.
  const std::vector<std::vector<std::string>> spread = {
      {"pinion.pressure_angle=14 deg", "pinion.teeth=16", "pinion.profile_shift=0.3"},
      {"pinion.pressure_angle=25 deg"},
      {"pinion.teeth=14", "pinion.profile_shift=0.4"},
      {"pinion.teeth=40", "pinion.profile_shift=-0.2"},
  };
  for (const auto& ov : spread) jobs.push_back({"gantry_axis|" + join(ov, ";") + "|0.5", "gantry_axis", ov, 0.5});
  return jobs;
}

// Six positions over one mesh period (cell middles from the entry of a pair)
// of each shipped single-rack problem, rack rigid as everywhere here.
std::vector<Job> period_jobs() {
  std::vector<Job> jobs;
  for (const char* p : {"gantry_axis", "large_module", "rack_railway", "ship_lift"}) {
    for (int k = 0; k < 6; ++k) {
      const double f = (k + 0.5) / 6;
      jobs.push_back({std::string(p) + "||" + fmt(f), p, {}, f});
    }
  }
  return jobs;
}

// The FE load shares of the theoretical pairs, ';'-separated.
std::string theoretical_shares(const FePosition& pos) {
  std::string shares;
  for (const FePair& q : pos.pairs) {
    if (q.theoretical) shares += (shares.empty() ? "" : ";") + fmt(q.load_share);
  }
  return shares;
}

// The first cells of a row: key, problem and the design's overrides.
std::string row_start(const Job& j) {
  return '"' + j.key + "\"," + j.problem + ",\"" + join(j.overrides, ";") + "\",";
}

// A spread of designs over the range the model claims (z 12..40, pressure
// angle 14..25 deg, profile shift -0.3..+0.5, modules 4..63 mm, with and
// without undercut), at the same six positions of a mesh period as
// period_jobs. Each design must pass the geometry checks of its base
// problem; one that does not is recorded as skipped with the reason.
std::vector<std::vector<std::string>> spread_designs_of(const std::string& base) {
  if (base == "gantry_axis") {
    return {{"pinion.teeth=12", "pinion.profile_shift=0.5"},
            {"pinion.teeth=14"},                                                  // undercut
            {"pinion.teeth=40", "pinion.profile_shift=-0.3", "pinion.pressure_angle=14 deg"},  // undercut
            {"pinion.teeth=26", "pinion.profile_shift=0.2", "pinion.pressure_angle=25 deg"}};
  }
  if (base == "large_module") return {{"pinion.teeth=30", "pinion.profile_shift=-0.3", "pinion.pressure_angle=17 deg"}};
  if (base == "rack_railway") return {{"pinion.teeth=18", "pinion.profile_shift=0.5"}};
  if (base == "ship_lift") {
    return {{"pinion.teeth=12", "pinion.profile_shift=0.3", "pinion.pressure_angle=25 deg", "pinion.tip_radius=0.3"},
            {"pinion.teeth=40", "pinion.profile_shift=-0.2"},
            {"pinion.teeth=16", "pinion.pressure_angle=14 deg"}};  // undercut
  }
  return {};
}

std::vector<Job> spread_jobs() {
  std::vector<Job> jobs;
  for (const char* p : {"gantry_axis", "large_module", "rack_railway", "ship_lift"}) {
    for (const std::vector<std::string>& ov : spread_designs_of(p)) {
      for (int k = 0; k < 6; ++k) {
        const double f = (k + 0.5) / 6;
        jobs.push_back({std::string(p) + "|" + join(ov, ";") + "|" + fmt(f), p, ov, f});
      }
    }
  }
  return jobs;
}

// The rack on its hinged supports: body depth and span varied on the gantry
// axis (teeth tall and short against the body, spans of 16 and 32 pitches),
// the pressure angle, and the shipped heavy racks, at mid-span (fraction 0)
// and near the left hinge (fraction 1: the first position of the mid-span
// phase whose loaded teeth and one each side lie on the span).
std::vector<Job> supports_jobs() {
  std::vector<Job> jobs;
  auto add = [&](const std::string& p, const std::vector<std::string>& ov, bool hinge) {
    jobs.push_back({p + "|" + join(ov, ";") + "|" + (hinge ? "1" : "0"), p, ov, hinge ? 1.0 : 0.0});
  };
  for (double depth : {12.0, 24.0, 48.0}) {
    for (double span : {0.2, 0.4}) {
      const std::vector<std::string> ov = {"rack.body_height=" + fmt(depth) + " mm", "rack.span=" + fmt(span) + " m"};
      add("gantry_axis", ov, false);
      if (span == 0.4) add("gantry_axis", ov, true);
    }
  }
  for (double alpha : {14.0, 25.0}) {
    add("gantry_axis", {"rack.body_height=24 mm", "rack.span=0.4 m", "pinion.pressure_angle=" + fmt(alpha) + " deg"},
        false);
  }
  add("gantry_axis", {"rack.body_height=24 mm", "rack.span=0.4 m", "pinion.teeth=14"}, false);
  // The pressure angle on other bodies: what the tooth layer depends on.
  for (double alpha : {17.0, 22.5}) {
    add("gantry_axis", {"rack.body_height=24 mm", "rack.span=0.4 m", "pinion.pressure_angle=" + fmt(alpha) + " deg"},
        false);
  }
  for (double alpha : {14.0, 25.0}) {
    add("gantry_axis", {"rack.body_height=12 mm", "rack.span=0.4 m", "pinion.pressure_angle=" + fmt(alpha) + " deg"},
        false);
  }
  for (double alpha : {20.0, 25.0}) add("rack_railway", {"pinion.pressure_angle=" + fmt(alpha) + " deg"}, false);
  add("large_module", {"pinion.pressure_angle=25 deg", "pinion.tip_radius=0.25"}, false);
  add("rack_railway", {}, false);
  add("rack_railway", {}, true);
  add("rack_railway", {"rack.body_height=150 mm"}, false);
  add("large_module", {}, false);
  add("ship_lift", {}, false);
  return jobs;
}

std::string supports_header() {
  return "key,problem,design,module_m,face_width_m,force_N,span_m,body_depth_m,travel_m,a_first_m,pairs,K_fe,"
         "load_fraction,shares_fe,level,elements,seconds";
}

std::string supports_row(const Job& j, FeOptions o) {
  o.rack_on_supports = true;
  const Drive d = fe_reference_drive(job_drive(j));
  const MeshStiffnessModel coupled(rack_on_supports_drive(d, o));
  const double p = coupled.geometry().rack.pitch;
  double X = fe_positions(coupled, 4).front();
  if (j.fraction > 0.5) {
    // Near the left hinge: the first position of the same phase that the
    // FE accepts (every design and placement check passes).
    const double phase = X - std::floor(X / p) * p;
    X = -1;
    for (int k = 0; k < 40 && X < 0; ++k) {
      FeOptions probe = o;
      probe.ccx.program = "/nonexistent/ccx";
      try {
        fe_mesh_position(d, phase + k * p, probe);
      } catch (const CcxNotFound&) {
        X = phase + k * p;
      } catch (const std::invalid_argument&) {
      }
    }
    if (X < 0) throw DesignError("no_hinge_position", "no position near the left hinge keeps the teeth on the span");
  }
  const MeshState an = coupled.at(X);
  const FePosition pos = fe_mesh_position(d, X, o);
  const std::string shares = theoretical_shares(pos);
  std::ostringstream r;
  r << row_start(j) << fmt(d.pinion.module) << ',' << fmt(fe_contact_width(d)) << ',' << fmt(d.load.force) << ',' << fmt(d.rack.span) << ','
    << fmt(fe_rack_body_depth(d, o)) << ',' << fmt(X) << ',' << fmt(an.pairs.front().a) << ',' << an.pairs.size()
    << ',' << fmt(pos.stiffness) << ',' << fmt(pos.load_fraction) << ",\"" << shares << "\"," << o.level << ','
    << pos.elements << ',' << fmt(pos.seconds);
  return r.str();
}

std::string period_header() {
  return "key,problem,design,module_m,face_width_m,force_N,travel_m,period_fraction,pairs,K_fe,load_fraction,"
         "shares_fe,level,elements,seconds";
}

std::string period_row(const Job& j, const FeOptions& o) {
  const Drive d = job_drive(j);
  const MeshStiffnessModel model(d);
  double x0 = 0;
  const std::vector<double> xs = fe_positions(model, 1, &x0);
  (void)xs;
  const double pitch = std::numbers::pi * d.pinion.module;
  const double X = x0 + j.fraction * pitch;
  const FePosition pos = fe_mesh_position(d, X, o);
  const std::string shares = theoretical_shares(pos);
  std::ostringstream r;
  r << row_start(j) << fmt(d.pinion.module) << ','
    << fmt(std::min(d.pinion.face_width, d.rack.face_width > 0 ? d.rack.face_width : d.pinion.face_width)) << ','
    << fmt(d.load.force) << ',' << fmt(X) << ',' << fmt(j.fraction) << ',' << model.at(X).pairs.size() << ','
    << fmt(pos.stiffness) << ',' << fmt(pos.load_fraction) << ",\"" << shares << "\"," << o.level << ','
    << pos.elements << ',' << fmt(pos.seconds);
  return r.str();
}

// The single-pair zone of the first full mesh period after mid-span: its
// travel range [lo, hi], found on a fine grid (NaN when there is none).
std::pair<double, double> single_pair_zone(const MeshStiffnessModel& model) {
  const double p = std::numbers::pi * model.drive().pinion.module;
  const double X0 = std::floor(0.5 * model.drive().rack.span / p) * p;
  const int n = 2000;
  double lo = NAN, hi = NAN, best = 0, run = NAN;
  for (int k = 0; k <= n; ++k) {
    const double X = X0 + p * k / n;
    const bool in = k < n && model.at(X).pairs.size() == 1;
    if (in && std::isnan(run)) run = X;
    if (!in && !std::isnan(run)) {
      if (X - run > best) {
        best = X - run;
        lo = run;
        hi = X;
      }
      run = NAN;
    }
  }
  return {lo, hi};
}

std::string rack_header() {
  return "key,problem,design,alpha_deg,ha_star,hf_star,root_radius_star,body_depth_star,teeth,profile_shift,"
         "s_star,load_height_star,E_Pa,nu,face_width_m,module_m,force_N,analytic_Eb,fe_Eb,level,elements,seconds";
}

std::string tooth_row(const Job& j, ToothMember member, const FeOptions& o) {
  const Drive d = job_drive(j);
  const MeshStiffnessModel model(d);
  const MeshGeometry& g = model.geometry();
  const double s = g.path.s_start + j.fraction * (g.path.s_end - g.path.s_start);
  const ToothComplianceFe c = fe_tooth_compliance(d, member, s, o);
  const double m = d.pinion.module;
  const Material& mat = member == ToothMember::kPinion ? d.pinion.material : d.rack.material;
  const double b = member == ToothMember::kPinion
                       ? d.pinion.face_width
                       : (d.rack.face_width > 0 ? d.rack.face_width : d.pinion.face_width);
  const double Eb = mat.youngs_modulus * b;
  const double depth = d.rack.body_height > 0 ? d.rack.body_height : 2 * d.rack.section.neutral_axis_depth;
  const double root = d.rack.root_radius > 0 ? d.rack.root_radius : g.pinion.cutter_tip_radius;
  // Load height: rack, above the root line; pinion, the contact radius.
  const double height = member == ToothMember::kRack ? g.rack.dedendum + g.contact_height_above_datum(s)
                                                     : std::hypot(g.pinion.base_radius, s);
  std::ostringstream r;
  r << '"' << j.key << "\"," << j.problem << ",\"" << join(j.overrides, ";") << "\","
    << fmt(d.pinion.pressure_angle * 180 / std::numbers::pi) << ','
    << fmt(member == ToothMember::kRack ? d.rack.addendum_coef : d.pinion.addendum_coef) << ','
    << fmt(member == ToothMember::kRack ? d.rack.dedendum_coef : d.pinion.dedendum_coef) << ',' << fmt(root / m) << ','
    << fmt(depth / m) << ',' << d.pinion.teeth << ',' << fmt(d.pinion.profile_shift) << ',' << fmt(s / m) << ','
    << fmt(height / m) << ',' << fmt(mat.youngs_modulus) << ',' << fmt(mat.poisson_ratio) << ',' << fmt(b) << ','
    << fmt(m) << ',' << fmt(d.load.force) << ',' << fmt(c.analytic * Eb) << ',' << fmt(c.compliance * Eb) << ','
    << o.level << ',' << c.elements << ',' << fmt(c.seconds);
  return r.str();
}

std::string contact_header() {
  return "key,problem,design,alpha_deg,teeth,profile_shift,module_m,face_width_m,force_N,travel_m,s_m,"
         "K_fe,load_fraction,c_pinion_fe,c_rack_fe,c_pinion_an,c_rack_an,c_contact_fe,"
         "c_hertz_linear,level,elements,seconds";
}

std::string contact_row(const Job& j, const FeOptions& o) {
  const Drive d = job_drive(j);
  const MeshStiffnessModel model(d);
  const auto [lo, hi] = single_pair_zone(model);
  if (std::isnan(lo)) throw DesignError("no_single_pair_zone", "no single-pair zone in the mesh period");
  const double X = lo + j.fraction * (hi - lo);
  const MeshState st = model.at(X);
  const double s = st.pairs.at(0).s;
  const FePosition pos = fe_mesh_position(d, X, o);
  const ToothComplianceFe cp = fe_tooth_compliance(d, ToothMember::kPinion, s, o);
  const ToothComplianceFe cr = fe_tooth_compliance(d, ToothMember::kRack, s, o);
  const double b = std::min(d.pinion.face_width, d.rack.face_width > 0 ? d.rack.face_width : d.pinion.face_width);
  const double c_contact = 1.0 / pos.stiffness - cp.compliance - cr.compliance;
  std::ostringstream r;
  r << '"' << j.key << "\"," << j.problem << ",\"" << join(j.overrides, ";") << "\","
    << fmt(d.pinion.pressure_angle * 180 / std::numbers::pi) << ',' << d.pinion.teeth << ','
    << fmt(d.pinion.profile_shift) << ',' << fmt(d.pinion.module) << ',' << fmt(b) << ',' << fmt(d.load.force) << ','
    << fmt(X) << ',' << fmt(s) << ',' << fmt(pos.stiffness) << ',' << fmt(pos.load_fraction) << ','
    << fmt(cp.compliance) << ',' << fmt(cr.compliance) << ',' << fmt(cp.analytic) << ',' << fmt(cr.analytic) << ','
    << fmt(c_contact) << ','
    << fmt(hertz_linear_compliance(effective_modulus(d.pinion.material, d.rack.material), b)) << ',' << o.level
    << ',' << pos.elements << ',' << fmt(pos.seconds + cp.seconds + cr.seconds);
  return r.str();
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buf;
}

std::string command_output(const char* cmd) {
  std::string out;
  if (FILE* f = popen(cmd, "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, f)) out += buf;
    pclose(f);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}


// ------------------------------------------------------------------ fit --

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) {
      out.push_back(cur);
      cur.clear();
    } else cur += c;
  }
  out.push_back(cur);
  return out;
}

// One data row of a calibration file: its cells, the numbers by column
// name, and the design's overrides (column 3, ';'-separated).
struct DataRow {
  const std::vector<std::string>& header;
  const std::vector<std::string>& cells;
  const std::string& path;
  double col(const char* name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return std::stod(cells.at(i));
    }
    throw std::runtime_error(std::string("no column ") + name + " in " + path);
  }
  std::string text(const char* name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return cells.at(i);
    }
    return {};
  }
  std::vector<std::string> overrides() const {
    std::vector<std::string> out;
    std::stringstream ss(cells.at(2));
    for (std::string t; std::getline(ss, t, ';');) {
      if (!t.empty()) out.push_back(t);
    }
    return out;
  }
};

// Calls fn for every row that carries values (comments, the header and
// skipped designs left out).
void for_each_data_row(const std::string& path, const std::function<void(const DataRow&)>& fn) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = split_csv(line);
    if (f[0] == "key") {
      header = f;
      continue;
    }
    if (f.size() != header.size()) continue;
    fn(DataRow{header, f, path});
  }
}

struct RackSample {
  std::string base;
  double alpha = 0, S = 0, q = 0, depth = 0, round = 0, analytic = 0, fe = 0;
};

std::vector<RackSample> read_rack_samples(const std::string& path) {
  std::vector<RackSample> out;
  for_each_data_row(path, [&](const DataRow& f) {
    RackSample r;
    r.base = f.cells[1];
    r.alpha = f.col("alpha_deg") * std::numbers::pi / 180;
    const double t = std::tan(r.alpha), y = f.col("load_height_star");
    const double w_f = std::numbers::pi / 4 + f.col("hf_star") * t;  // half thickness at the root line / m
    r.S = 2 * w_f;
    r.q = (y - (w_f - y * t) * t) / r.S;
    r.depth = f.col("body_depth_star") / r.S;
    r.round = f.col("root_radius_star") / r.S;
    r.analytic = f.col("analytic_Eb");
    r.fe = f.col("fe_Eb");
    out.push_back(r);
  });
  return out;
}

// One row of the design matrix: the law's 12 coefficients times their
// regressors, over the FE value (relative residuals).
Eigen::RowVectorXd rack_regressors(const RackSample& r) {
  const double c2 = std::cos(r.alpha) * std::cos(r.alpha), s2 = 1 - c2;
  const double term[4] = {c2 * r.q * r.q, c2 * r.q, c2, s2};
  const double g[3] = {1, std::log(r.depth), r.round};
  Eigen::RowVectorXd row(12);
  for (int t = 0; t < 4; ++t) {
    for (int k = 0; k < 3; ++k) row(3 * t + k) = term[t] * g[k] / r.fe;
  }
  return row;
}

int fit_rack(const std::string& path) {
  const std::vector<RackSample> rows = read_rack_samples(path);
  if (rows.size() < 24) throw std::runtime_error("too few rack samples to fit (" + std::to_string(rows.size()) + ")");
  auto solve = [&](const std::function<bool(const RackSample&)>& use) {
    std::vector<const RackSample*> sel;
    for (const RackSample& r : rows) {
      if (use(r)) sel.push_back(&r);
    }
    Eigen::MatrixXd A(sel.size(), 12);
    Eigen::VectorXd y(sel.size());
    for (std::size_t i = 0; i < sel.size(); ++i) {
      A.row(static_cast<Eigen::Index>(i)) = rack_regressors(*sel[i]);
      y(static_cast<Eigen::Index>(i)) = (sel[i]->fe - sel[i]->analytic) / sel[i]->fe;
    }
    return Eigen::VectorXd(A.colPivHouseholderQr().solve(y));
  };
  auto residuals = [&](const Eigen::VectorXd& c, const std::function<bool(const RackSample&)>& use) {
    double mx = 0, ss = 0;
    int n = 0;
    for (const RackSample& r : rows) {
      if (!use(r)) continue;
      const double res = (rack_regressors(r) * c)(0) - (r.fe - r.analytic) / r.fe;
      mx = std::max(mx, std::abs(res));
      ss += res * res;
      ++n;
    }
    return std::pair<double, double>{mx, std::sqrt(ss / std::max(n, 1))};
  };
  double before = 0;
  for (const RackSample& r : rows) before = std::max(before, std::abs(r.analytic - r.fe) / r.fe);
  const auto all = [](const RackSample&) { return true; };
  const Eigen::VectorXd c = solve(all);
  const auto [mx, rms] = residuals(c, all);
  std::printf("// %zu samples; clamped tooth alone: largest error %.3f of the FE compliance;\n", rows.size(), before);
  std::printf("// with the foundation: largest %.4f, rms %.4f\n", mx, rms);
  std::set<std::string> bases;
  for (const RackSample& r : rows) bases.insert(r.base);
  for (const std::string& b : bases) {
    const Eigen::VectorXd cb = solve([&](const RackSample& r) { return r.base == b; });
    const auto [mo, ro] = residuals(cb, [&](const RackSample& r) { return r.base != b; });
    std::printf("// fitted on %s alone, on the others: largest %.4f, rms %.4f\n", b.c_str(), mo, ro);
  }
  const char* names[4] = {"kL", "kM", "kP", "kQ"};
  for (int t = 0; t < 4; ++t) {
    std::printf("constexpr Row %s{%.5f, %.5f, %.5f};\n", names[t], c(3 * t), c(3 * t + 1), c(3 * t + 2));
  }
  return 0;
}


struct PinionSample {
  int teeth = 0;
  double alpha_m = 0, q = 0, theta = 0, tan_a0 = 0, analytic = 0, fe = 0;
};

std::vector<PinionSample> read_pinion_samples(const std::string& path) {
  std::vector<PinionSample> out;
  for_each_data_row(path, [&](const DataRow& f) {
    const Drive d = load_problem(problem_path(f.cells[1]), f.overrides());
    const MeshGeometry g = build_mesh_geometry(d);
    const FilletFoundationCompliance ff(g, d.pinion);
    const double s = f.col("s_star") * d.pinion.module;
    PinionSample r;
    r.teeth = d.pinion.teeth;
    r.alpha_m = std::max(s, 0.0) / g.pinion.base_radius - g.pinion.half_base_angle;
    r.q = ff.u_f(s) / ff.root_thickness();
    r.theta = ff.theta_f();
    r.tan_a0 = std::tan(d.pinion.pressure_angle);
    r.analytic = f.col("analytic_Eb");
    r.fe = f.col("fe_Eb");
    out.push_back(r);
  });
  return out;
}

Eigen::RowVectorXd pinion_regressors(const PinionSample& r) {
  const double c2 = std::cos(r.alpha_m) * std::cos(r.alpha_m), s2 = 1 - c2;
  const double term[4] = {c2 * r.q * r.q, c2 * r.q, c2, s2};
  const double g[3] = {1, r.theta, r.tan_a0};
  Eigen::RowVectorXd row(12);
  for (int t = 0; t < 4; ++t) {
    for (int k = 0; k < 3; ++k) row(3 * t + k) = term[t] * g[k] / r.fe;
  }
  return row;
}

// The coefficients that make the largest relative residual small rather
// than their squares' sum: Lawson's iteration, least squares reweighted by
// the residuals (200 steps; it settles long before). The pinion's law is
// bounded by its form, so the worst sample is what matters.
Eigen::VectorXd minimax_fit(const Eigen::MatrixXd& A, const Eigen::VectorXd& y) {
  Eigen::VectorXd w = Eigen::VectorXd::Constant(y.size(), 1.0 / static_cast<double>(y.size()));
  Eigen::VectorXd c;
  for (int it = 0; it < 200; ++it) {
    const Eigen::VectorXd root = w.cwiseSqrt();
    c = (root.asDiagonal() * A).colPivHouseholderQr().solve(root.asDiagonal() * y);
    w = w.cwiseProduct((A * c - y).cwiseAbs());
    w /= w.sum();
    w = w.cwiseMax(1e-12);
  }
  return c;
}

int fit_pinion(const std::string& path) {
  const std::vector<PinionSample> rows = read_pinion_samples(path);
  if (rows.size() < 24) throw std::runtime_error("too few pinion samples to fit (" + std::to_string(rows.size()) + ")");
  auto solve = [&](const std::function<bool(const PinionSample&)>& use) {
    std::vector<const PinionSample*> sel;
    for (const PinionSample& r : rows) {
      if (use(r)) sel.push_back(&r);
    }
    Eigen::MatrixXd A(sel.size(), 12);
    Eigen::VectorXd y(sel.size());
    for (std::size_t i = 0; i < sel.size(); ++i) {
      A.row(static_cast<Eigen::Index>(i)) = pinion_regressors(*sel[i]);
      y(static_cast<Eigen::Index>(i)) = (sel[i]->fe - sel[i]->analytic) / sel[i]->fe;
    }
    return minimax_fit(A, y);
  };
  auto residuals = [&](const Eigen::VectorXd& c, const std::function<bool(const PinionSample&)>& use) {
    double mx = 0, ss = 0;
    int n = 0;
    for (const PinionSample& r : rows) {
      if (!use(r)) continue;
      const double res = (pinion_regressors(r) * c)(0) - (r.fe - r.analytic) / r.fe;
      mx = std::max(mx, std::abs(res));
      ss += res * res;
      ++n;
    }
    return std::pair<double, double>{mx, std::sqrt(ss / std::max(n, 1))};
  };
  double before = 0, th_lo = INFINITY, th_hi = 0;
  for (const PinionSample& r : rows) {
    before = std::max(before, std::abs(r.analytic - r.fe) / r.fe);
    th_lo = std::min(th_lo, r.theta);
    th_hi = std::max(th_hi, r.theta);
  }
  const auto all = [](const PinionSample&) { return true; };
  const Eigen::VectorXd c = solve(all);
  const auto [mx, rms] = residuals(c, all);
  std::printf("// %zu samples, theta_f %.3f..%.3f rad; beam + Sainsot alone: largest error %.3f;\n", rows.size(),
              th_lo, th_hi, before);
  std::printf("// with the calibration (minimax fit): largest %.4f, rms %.4f\n", mx, rms);
  std::set<int> teeth;
  for (const PinionSample& r : rows) teeth.insert(r.teeth);
  for (int z : teeth) {
    const Eigen::VectorXd cz = solve([&](const PinionSample& r) { return r.teeth != z; });
    const auto [mo, ro] = residuals(cz, [&](const PinionSample& r) { return r.teeth == z; });
    std::printf("// z = %d left out of the fit, on it: largest %.4f, rms %.4f\n", z, mo, ro);
  }
  const char* names[4] = {"kL", "kM", "kP", "kQ"};
  for (int t = 0; t < 4; ++t) {
    std::printf("constexpr Row %s{%.5f, %.5f, %.5f};\n", names[t], c(3 * t), c(3 * t + 1), c(3 * t + 2));
  }
  return 0;
}


// One double-pair position: the model's two pair compliances and their
// foundations (pair coupling off, rigid rack, at the FE's load) and K_FE.
struct CouplingSample {
  std::string problem;
  double alpha = 0;
  double c1 = 0, c2 = 0, foundations = 0, k_fe = 0;
  // K of two pairs with cross compliance x = kappa * foundations.
  double k(double kappa) const {
    const double x = kappa * foundations;
    return (c1 + c2 - 2 * x) / (c1 * c2 - x * x);
  }
  // kappa = k20 + k1 (alpha [deg] - 20).
  double k(double k20, double k1) const { return k(k20 + k1 * (alpha * 180 / std::numbers::pi - 20)); }
};

int fit_coupling(const std::string& paths) {
  std::vector<CouplingSample> rows;
  std::stringstream list(paths);
  for (std::string path; std::getline(list, path, ',');) {
    for_each_data_row(path, [&](const DataRow& f) {
      if (f.col("pairs") != 2) return;
      Drive d = load_problem(problem_path(f.cells[1]), f.overrides());
      d.effects.rack_span = RackSpanModel::kRigid;
      d.effects.pair_coupling = false;
      d.spalls.clear();
      d.load.force *= f.col("load_fraction");
      const MeshState st = MeshStiffnessModel(d).at(f.col("travel_m"));
      if (st.pairs.size() != 2) throw std::runtime_error("expected two pairs at a row of " + path);
      CouplingSample r;
      r.problem = f.cells[1] + (f.cells[2].empty() ? "" : "|" + f.cells[2]);
      r.alpha = d.pinion.pressure_angle;
      r.c1 = st.pairs[0].local();
      r.c2 = st.pairs[1].local();
      r.foundations = 0.5 * (st.pairs[0].fillet + st.pairs[0].rack_foundation + st.pairs[1].fillet +
                             st.pairs[1].rack_foundation);
      r.k_fe = f.col("K_fe");
      rows.push_back(r);
    });
  }
  if (rows.size() < 4) throw std::runtime_error("too few double-pair positions in " + paths);
  auto worst = [&](double kappa, const std::function<bool(const CouplingSample&)>& use) {
    double w = 0;
    for (const CouplingSample& r : rows) {
      if (use(r)) w = std::max(w, std::abs(r.k(kappa) / r.k_fe - 1));
    }
    return w;
  };
  auto best = [&](const std::function<bool(const CouplingSample&)>& use) {
    double kappa = 0, w = INFINITY;
    for (int i = 0; i <= 10000; ++i) {
      const double k = i * 1e-4;
      const double e = worst(k, use);
      if (e < w) {
        w = e;
        kappa = k;
      }
    }
    return kappa;
  };
  const auto all = [](const CouplingSample&) { return true; };
  const double kappa = best(all);
  std::printf("// %zu double-pair positions; pairs in parallel: largest K error %.4f; with kappa = %.4f: %.4f\n",
              rows.size(), worst(0, all), kappa, worst(kappa, all));
  std::set<std::string> problems;
  for (const CouplingSample& r : rows) problems.insert(r.problem);
  for (const std::string& p : problems) {
    const double k = best([&](const CouplingSample& r) { return r.problem != p; });
    std::printf("// %s left out: kappa %.4f, on it: largest K error %.4f\n", p.c_str(), k,
                worst(k, [&](const CouplingSample& r) { return r.problem == p; }));
  }
  // kappa linear in the pressure angle, largest K error made smallest.
  auto worst2 = [&](double k20, double k1, const std::function<bool(const CouplingSample&)>& use) {
    double w = 0;
    for (const CouplingSample& r : rows) {
      if (use(r)) w = std::max(w, std::abs(r.k(k20, k1) / r.k_fe - 1));
    }
    return w;
  };
  auto best2 = [&](const std::function<bool(const CouplingSample&)>& use, double* k20, double* k1) {
    double w = INFINITY;
    for (int i = 0; i <= 400; ++i) {
      for (int j = -40; j <= 40; ++j) {
        const double a = 0.2 + 0.001 * i, b = 0.0005 * j;
        const double e = worst2(a, b, use);
        if (e < w) {
          w = e;
          *k20 = a;
          *k1 = b;
        }
      }
    }
    return w;
  };
  double k20 = 0, k1 = 0;
  const double w2 = best2(all, &k20, &k1);
  std::printf("// kappa = %.4f + %.5f (alpha - 20 deg): largest K error %.4f\n", k20, k1, w2);
  for (const std::string& p : problems) {
    double a = 0, b = 0;
    best2([&](const CouplingSample& r) { return r.problem != p; }, &a, &b);
    std::printf("// %s left out: kappa %.4f + %.5f (alpha - 20), on it: largest K error %.4f\n", p.c_str(), a, b,
                worst2(a, b, [&](const CouplingSample& r) { return r.problem == p; }));
  }
  for (const CouplingSample& r : rows) {
    // The share that alone makes this position's K equal to FE's.
    double lo = 0, hi = 1;
    for (int it = 0; it < 50; ++it) {
      const double mid = 0.5 * (lo + hi);
      (r.k(mid) > r.k_fe ? lo : hi) = mid;
    }
    std::printf("//   %s (%.1f deg): kappa alone %.4f, error at the fit %+.4f\n", r.problem.c_str(),
                r.alpha * 180 / std::numbers::pi, 0.5 * (lo + hi), r.k(k20, k1) / r.k_fe - 1);
  }
  std::printf("PairCouplingShare pair_coupling_fit() { return {%.4f, %.5f}; }\n", k20, k1);
  return 0;
}

// The rack on its supports: the analytic coupled model on the FE body
// against the FE mesh positions of a supports data file, as is and with a
// candidate law: a tooth layer of beta times the tooth height added on top
// of the beam's section, and the rack foundation taken at k_depth root thicknesses below the
// body depth (the held-base calibration counts the body down to its held
// base, which the beam counts again).
struct SupportsSample {
  std::string problem, design;
  Drive drive;  // the FE body's coupled beam, at the FE's force
  double X = 0, k_fe = 0, tooth_height = 0, depth = 0;
  std::string shares;
};

// The law with explicit beta and k_depth on a drive whose own
// effects.supported_rack is off (stiffness/supported_rack.hpp).
Drive with_supported_rack_law(Drive d, double depth, double tooth_height, double beta, double k_depth) {
  const double S = 2 * build_mesh_geometry(d).rack.half_thickness_at_root;
  d.effects.supported_rack = false;
  d.rack = rack_with_tooth_layer(d.rack, tooth_height, d.rack.section.area / depth, beta);
  // The section is explicit: body_height is what the foundation reads.
  d.rack.body_height = supported_foundation_depth(depth, S, k_depth);
  return d;
}

int fit_supports(const std::string& path) {
  std::vector<SupportsSample> rows;
  for_each_data_row(path, [&](const DataRow& f) {
    Job j;
    j.problem = f.cells[1];
    j.overrides = f.overrides();
    FeOptions on;
    on.rack_on_supports = true;
    SupportsSample r;
    r.problem = f.cells[1];
    r.design = f.cells[2];
    const Drive ref = fe_reference_drive(job_drive(j));
    r.drive = rack_on_supports_drive(ref, on);
    r.drive.effects.supported_rack = false;
    r.drive.effects.rack_foundation = true;
    r.drive.effects.fillet_calibration = true;
    r.drive.load.force *= f.col("load_fraction");
    r.depth = f.col("body_depth_m");
    r.tooth_height = (r.drive.rack.addendum_coef + r.drive.rack.dedendum_coef) * r.drive.pinion.module;
    r.X = f.col("travel_m");
    r.k_fe = f.col("K_fe");
    r.shares = f.text("shares_fe");
    rows.push_back(r);
  });
  // beta = b20 + b1 (alpha - 20 deg).
  auto beta_of = [](const SupportsSample& r, double b20, double b1) {
    return std::max(0.0, b20 + b1 * (r.drive.pinion.pressure_angle * 180 / std::numbers::pi - 20));
  };
  auto k_of = [&](const SupportsSample& r, double b20, double b1, double k_depth) {
    try {
      return MeshStiffnessModel(
                 with_supported_rack_law(r.drive, r.depth, r.tooth_height, beta_of(r, b20, b1), k_depth))
          .at(r.X)
          .stiffness;
    } catch (const DesignError&) {
      return double(INFINITY);  // the foundation law left its ground
    }
  };
  std::printf("| problem | design | X | K FE | K analytic | FE/analytic |\n");
  for (const SupportsSample& r : rows) {
    const double k = MeshStiffnessModel(r.drive).at(r.X).stiffness;
    std::printf("| %s | %s | %.4f | %.4g | %.4g | %.3f |\n", r.problem.c_str(), r.design.c_str(), r.X, r.k_fe, k,
                r.k_fe / k);
  }
  auto worst = [&](double b20, double b1, double k_depth, const std::function<bool(const SupportsSample&)>& use) {
    double w = 0;
    for (const SupportsSample& r : rows) {
      if (use(r)) w = std::max(w, std::abs(k_of(r, b20, b1, k_depth) / r.k_fe - 1));
    }
    return w;
  };
  struct Law {
    double b20 = 0, b1 = 0, k = 3, error = INFINITY;
  };
  auto best = [&](const std::function<bool(const SupportsSample&)>& use, std::vector<double> ks, bool slope) {
    Law l;
    for (double g : ks) {
      for (int ib = 0; ib <= 60; ++ib) {
        for (int j = slope ? -10 : 0; j <= (slope ? 20 : 0); ++j) {
          const double b = 0.005 * ib, b1 = 0.001 * j;
          const double e = worst(b, b1, g, use);
          if (e < l.error) l = {b, b1, g, e};
        }
      }
    }
    return l;
  };
  const auto all = [](const SupportsSample&) { return true; };
  // Fitted on the slender spans (at least 8 body depths): the beam picture
  // the law corrects; the deep short spans are reported, not fitted.
  const auto slender = [](const SupportsSample& r) { return r.drive.rack.span >= 8 * r.depth; };
  const Law flat = best(slender, {0.55, 0.75, 1.0, 1.5, 3.0}, false);
  std::printf("// %zu positions; beam alone: largest K error %.4f\n", rows.size(), worst(0, 0, 100, all));
  std::printf("// one beta, fitted on the slender spans: beta %.3f, k %.2f: largest K error there %.4f, on all %.4f\n",
              flat.b20, flat.k, flat.error, worst(flat.b20, 0, flat.k, all));
  const Law law = best(slender, {flat.k}, true);
  std::printf("// beta = %.3f + %.4f (alpha - 20 deg), k = %.2f: largest K error on the slender spans %.4f, on all %.4f\n",
              law.b20, law.b1, law.k, law.error, worst(law.b20, law.b1, law.k, all));
  const double beta = law.b20, beta1 = law.b1, k_depth = law.k;
  for (const SupportsSample& r : rows) {
    std::string shares;
    try {
      const MeshState st = MeshStiffnessModel(with_supported_rack_law(r.drive, r.depth, r.tooth_height,
                                                                      beta_of(r, beta, beta1), k_depth))
                               .at(r.X);
      for (const PairState& q : st.pairs) shares += (shares.empty() ? "" : ";") + fmt(q.load_share);
    } catch (const DesignError&) {
    }
    // The beta that alone would match this row at the fitted depth.
    double lo = 0, hi = 1;
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (lo + hi);
      (k_of(r, mid, 0, k_depth) < r.k_fe ? lo : hi) = mid;
    }
    std::printf("//   %s %s X %.4f: error %+.4f (one beta %+.4f), beta alone %.3f, shares %s (FE %s)\n",
                r.problem.c_str(), r.design.c_str(), r.X, k_of(r, beta, beta1, k_depth) / r.k_fe - 1,
                k_of(r, flat.b20, 0, flat.k) / r.k_fe - 1, 0.5 * (lo + hi), shares.c_str(), r.shares.c_str());
  }
  std::set<std::string> designs;
  for (const SupportsSample& r : rows) designs.insert(r.problem + "|" + r.design);
  for (const std::string& dsg : designs) {
    const Law l = best([&](const SupportsSample& r) { return slender(r) && r.problem + "|" + r.design != dsg; },
                       {k_depth}, true);
    std::printf("// %s left out: beta %.3f + %.4f (alpha - 20), on it: largest K error %.4f\n", dsg.c_str(), l.b20,
                l.b1, worst(l.b20, l.b1, l.k, [&](const SupportsSample& r) { return r.problem + "|" + r.design == dsg; }));
  }
  std::printf("SupportedRackLaw supported_rack_law() { return {%.3f, %.4f, %.2f}; }\n", beta, beta1, k_depth);
  return 0;
}

int run(const Args& a) {
  if (!a.fit.empty()) {
    if (a.fit == "coupling") return fit_coupling(a.fit_file);
    if (a.fit == "rack") return fit_rack(a.fit_file);
    if (a.fit == "pinion") return fit_pinion(a.fit_file);
    if (a.fit == "supports") return fit_supports(a.fit_file);
    throw std::invalid_argument("--fit must be rack, pinion, coupling or supports");
  }
  std::vector<Job> jobs;
  std::string header;
  if (a.set == "rack" || a.set == "pinion") {
    jobs = a.set == "rack" ? rack_jobs() : pinion_jobs();
    header = rack_header();
  } else if (a.set == "contact") {
    jobs = contact_jobs();
    header = contact_header();
  } else if (a.set == "period" || a.set == "spread") {
    jobs = a.set == "period" ? period_jobs() : spread_jobs();
    header = period_header();
  } else if (a.set == "supports") {
    jobs = supports_jobs();
    header = supports_header();
  } else {
    throw std::invalid_argument("--set must be rack, pinion, contact, period, spread or supports");
  }
  if (a.limit > 0 && static_cast<std::size_t>(a.limit) < jobs.size()) jobs.resize(static_cast<std::size_t>(a.limit));
  const std::string partial = a.out + ".partial";
  std::set<std::string> done;
  {
    std::ifstream in(partial);
    for (std::string line; std::getline(in, line);) {
      if (line.size() > 1 && line[0] == '"') done.insert(line.substr(1, line.find('"', 1) - 1));
    }
  }
  const bool fresh = done.empty();
  std::ofstream part(partial, std::ios::app);
  if (fresh) part << header << '\n';
  FeOptions o;
  o.level = a.level;
  std::mutex mu;
  std::atomic<std::size_t> next{0};
  std::atomic<int> failures{0};
  auto worker = [&] {
    for (std::size_t k; (k = next++) < jobs.size();) {
      const Job& j = jobs[k];
      if (done.count(j.key)) continue;
      std::string row;
      try {
        if (a.set == "contact") row = contact_row(j, o);
        else if (a.set == "period" || a.set == "spread") row = period_row(j, o);
        else if (a.set == "supports") row = supports_row(j, o);
        else row = tooth_row(j, a.set == "rack" ? ToothMember::kRack : ToothMember::kPinion, o);
      } catch (const std::exception& e) {
        std::string what = e.what();
        what = what.substr(0, what.find('\n'));
        std::lock_guard<std::mutex> lock(mu);
        // A design the geometry refuses is part of the sample's edge, not a
        // failure: it is recorded as skipped so a resumed run does not retry it.
        part << '"' << j.key << "\",skipped,\"" << what << "\"\n" << std::flush;
        std::fprintf(stderr, "[%zu/%zu] %s: skipped: %s\n", k + 1, jobs.size(), j.key.c_str(), what.c_str());
        if (!dynamic_cast<const DesignError*>(&e)) ++failures;
        continue;
      }
      std::lock_guard<std::mutex> lock(mu);
      part << row << '\n' << std::flush;
      std::fprintf(stderr, "[%zu/%zu] %s\n", k + 1, jobs.size(), j.key.c_str());
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, a.threads); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  part.close();

  // Sorted, with provenance, written then renamed.
  std::ifstream in(partial);
  std::vector<std::string> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (!line.empty()) rows.push_back(line);
  }
  std::sort(rows.begin(), rows.end());
  const std::string tmp = a.out + ".tmp";
  {
    std::ofstream out(tmp);
    out << "# rackopt FE calibration data, set '" << a.set << "' (docs/models/fe_calibration.md)\n"
        << "# made by: ./build/fe_calibration --set " << a.set << " --level " << a.level << " --out <file>\n"
        << "# finished: " << now_utc() << "; rackopt commit " << command_output("git -C " RACKOPT_SOURCE_DIR
                                                                                 " rev-parse --short HEAD 2>/dev/null")
        << "\n# FE: " << command_output("ccx -v 2>/dev/null | grep -i version | head -1")
        << "; Gmsh " << command_output("gmsh --version 2>&1 | head -1") << "; plane stress, level " << a.level << "\n"
        << (a.set == "period" || a.set == "spread" ? "# K in N/m (secant 0.2..1 of the last step), shares of the theoretical pairs "
                                "nearest the pinion tip first; skipped rows name the reason\n"
            : a.set == "supports" ? "# rack on its hinged supports; K in N/m (secant 0.2..1 of the last step), "
                                    "a_first = the first pair's abscissa from the left hinge; skipped rows name the reason\n"
            : a.set == "contact" ? "# compliances in m/N, K in N/m, the FE contact term = 1/K_fe - c_pinion_fe - c_rack_fe; "
                                 "skipped rows name the reason\n"
                               : "# compliances in units of 1/(E b) (columns *_Eb), lengths with _star in modules; "
                                 "skipped rows name the reason\n")
        << header << '\n';
    for (const std::string& r : rows) out << r << '\n';
  }
  std::filesystem::rename(tmp, a.out);
  std::filesystem::remove(partial);
  std::fprintf(stderr, "%zu rows -> %s (%d unexpected failures)\n", rows.size(), a.out.c_str(), failures.load());
  return failures > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string k = argv[i];
      auto val = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(k + " needs a value");
        return argv[++i];
      };
      if (k == "--set") a.set = val();
      else if (k == "--out") a.out = val();
      else if (k == "--threads") a.threads = std::stoi(val());
      else if (k == "--level") a.level = std::stoi(val());
      else if (k == "--limit") a.limit = std::stoi(val());
      else if (k == "--fit") {
        a.fit = val();
        a.fit_file = val();
      }
      else throw std::invalid_argument("unknown option " + k);
    }
    if (a.out.empty() && a.fit.empty()) throw std::invalid_argument("--out FILE is required");
    return run(a);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fe_calibration: %s\n", e.what());
    return 2;
  }
}
