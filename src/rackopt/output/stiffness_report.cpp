#include "rackopt/output/stiffness_report.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string_view>

#include "rackopt/stiffness/iso_single_stiffness.hpp"
#include "rackopt/stiffness/pair_compliance.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/output/plot.hpp"

namespace rackopt {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string mm(double v) { return fmt("%.3f", v * 1e3) + " mm"; }
std::string deg(double v) { return fmt("%.3f", v * 180.0 / M_PI) + " deg"; }
std::string mnm(double v) { return fmt("%.3f", v * 1e-6) + " MN/m"; }

const char* limited_by_text(const std::string& s) {
  if (s == "rack_tip") return "rack tip";
  if (s == "form_circle") return "pinion form circle (undercut / interference limit)";
  if (s == "base_circle") return "pinion base circle (interference limit)";
  return s.c_str();
}

}  // namespace

std::string geometry_summary(const Drive& d, const MeshGeometry& g) {
  std::ostringstream o;
  const PinionGeometry& p = g.pinion;
  const ContactPath& c = g.path;
  o << (d.name.empty() ? std::string("rack drive") : d.name) << "\n";
  o << "  pinion: z = " << d.pinion.teeth << ", m = " << mm(d.pinion.module)
    << ", alpha = " << deg(d.pinion.pressure_angle) << ", x = " << d.pinion.profile_shift
    << ", b = " << mm(d.pinion.face_width) << "\n";
  o << "    radii: pitch " << mm(p.pitch_radius) << ", base " << mm(p.base_radius) << ", tip "
    << mm(p.tip_radius) << ", root " << mm(p.root_radius) << ", form " << mm(p.form_radius) << "\n";
  o << "    tip thickness " << mm(p.tip_thickness) << (p.undercut ? ", UNDERCUT" : ", no undercut") << "\n";
  o << "  rack: pitch " << mm(g.rack.pitch) << ", addendum " << mm(g.rack.addendum) << ", dedendum "
    << mm(g.rack.dedendum) << ", span " << fmt("%.3f", d.rack.span) << " m ("
    << (d.rack.supports == Supports::kPinPin ? "pin-pin" : "pin-roller") << ")\n";
  o << "  mounting clearance " << mm(d.mounting.clearance) << "\n";
  o << "  line of action (from the base-circle tangency point):\n";
  o << "    rack tip at s_A = " << mm(c.s_rack_tip) << ", pitch point s_P = " << mm(c.s_pitch)
    << ", pinion tip s_E = " << mm(c.s_end) << "\n";
  o << "    active path " << mm(c.s_start) << " .. " << mm(c.s_end) << " (start limited by "
    << limited_by_text(c.start_limited_by) << "), base pitch " << mm(c.base_pitch) << "\n";
  o << "  contact ratio " << fmt("%.4f", c.contact_ratio) << " (geometric, interference ignored: "
    << fmt("%.4f", c.contact_ratio_geometric) << ")\n";
  o << "  zones per mesh period:\n";
  for (const Zone& z : g.zones) {
    o << "    " << z.pairs << " pair" << (z.pairs == 1 ? " " : "s") << ": " << mm(z.length_loa)
      << " along the LOA, " << mm(z.length_travel) << " of rack travel, " << mm(z.length_flank)
      << " along the rack flank, " << deg(z.pinion_angle) << " of pinion rotation\n";
  }
  const Effects& e = d.effects;
  auto onoff = [](bool b) { return b ? "on" : "off"; };
  const char* span = e.rack_span == RackSpanModel::kRigid     ? "rigid"
                     : e.rack_span == RackSpanModel::kCoupled ? "coupled (one beam for all pairs)"
                                                              : "per pair (the rack railway paper)";
  const char* hertz = e.hertz == HertzModel::kOff      ? "off"
                      : e.hertz == HertzModel::kLinear ? "linear"
                                                       : "Weber-Banaschek (load dependent, plane stress)";
  o << "  effects: pinion tooth " << onoff(e.pinion_tooth) << " (root segment " << onoff(e.root_segment)
    << "), fillet foundation " << onoff(e.fillet_foundation)
    << (e.fillet_foundation ? (e.fillet_calibration ? " (FE-calibrated)" : " (Sainsot's table)") : "") << ", rack tooth "
    << onoff(e.rack_tooth)
    << " (foundation " << onoff(e.rack_foundation) << "), contact " << hertz << ", pair coupling "
    << onoff(e.pair_coupling) << ",\n           rack span " << span;
  if (e.rack_span != RackSpanModel::kRigid) {
    o << " [couple " << onoff(e.couple_term) << ", axial " << onoff(e.body_axial) << ", shear "
      << onoff(e.body_shear);
    if (e.rack_span == RackSpanModel::kCoupled) o << ", supported rack " << onoff(e.supported_rack);
    o << "]";
  }
  o << ", interference limit " << onoff(e.interference_limit) << ", spalls "
    << (e.spalling ? std::to_string(d.spalls.size()) : std::string("off")) << "\n";
  o << iso_single_stiffness_line(d, g);
  for (const std::string& w : g.warnings) o << "  warning: " << w << "\n";
  return o.str();
}

double single_pair_stiffness_at_pitch_point(const Drive& d, const MeshGeometry& g) {
  const PairCompliance pair(d, g);
  const double s = g.path.s_pitch;
  return 1.0 / (pair.teeth(s).total() + pair.contact(s, d.load.force));
}

std::string iso_single_stiffness_line(const Drive& d, const MeshGeometry& g) {
  std::ostringstream o;
  try {
    const IsoSingleStiffness iso = iso_single_stiffness(d);
    o << "  beside ISO 6336-1: single stiffness c' = " << fmt("%.3g", iso.c_prime) << " N/(mm um), c' b = "
      << fmt("%.4g", iso.stiffness / 1e6) << " MN/m";
    if (iso.load_factor < 1) o << " (load factor " << fmt("%.3f", iso.load_factor) << ")";
    const double k = single_pair_stiffness_at_pitch_point(d, g);
    o << "; this model, one pair at the pitch point, rigid rack body: " << fmt("%.4g", k / 1e6) << " MN/m ("
      << fmt("%.2f", k / iso.stiffness) << " c' b)\n";
  } catch (const std::exception& ex) {
    o << "\n  (the model's single pair at the pitch point: not available: " << ex.what() << ")\n";
  }
  return o.str();
}

std::string stiffness_summary(const StiffnessCurve& c) {
  std::ostringstream o;
  o << "  mesh stiffness over the span (" << c.samples.size() << " samples, " << c.breakpoints.size()
    << " discontinuities):\n";
  o << "    min  " << mnm(c.k_min) << " at X = " << fmt("%.4f", c.travel_at_min) << " m\n";
  o << "    max  " << mnm(c.k_max) << " at X = " << fmt("%.4f", c.travel_at_max) << " m\n";
  o << "    mean " << mnm(c.k_mean) << ", fluctuation (max-min)/mean = " << fmt("%.4f", c.k_fluctuation)
    << "\n";
  return o.str();
}

std::string mesh_dynamics_summary(const MeshRipple& r, const TransmissionError& te) {
  std::ostringstream o;
  o << "  mesh ripple (max-min)/mean per mesh period: max " << fmt("%.4f", r.max) << ", mean "
    << fmt("%.4f", r.mean) << " (" << r.ripple.size() << " periods)\n";
  o << "  static transmission error (mesh deflection under the load): peak-to-peak "
    << fmt("%.4g", te.peak_to_peak * 1e6) << " um over the span, per period max "
    << fmt("%.4g", te.period_max * 1e6) << " um, mean " << fmt("%.4g", te.period_mean * 1e6) << " um\n";
  return o.str();
}

namespace {

// Each pair slot's columns of stiffness.csv, in order.
constexpr const char* kPairColumns[] = {"in_mesh",        "rack_tooth",     "pinion_tooth",      "s_m",
                                        "x_m",            "load_share",     "c_pinion_bending",  "c_pinion_shear",
                                        "c_pinion_axial", "c_fillet",       "c_hertz",           "c_rack_bending",
                                        "c_rack_shear",   "c_rack_axial",   "c_rack_foundation", "c_body",
                                        "relief_m"};

}  // namespace

std::string stiffness_csv(const StiffnessCurve& c) {
  std::string text;
  write_stiffness_csv(c, [&](std::string_view piece) { text += piece; });
  return text;
}

void write_stiffness_csv(const StiffnessCurve& c, const std::function<void(std::string_view piece)>& write) {
  // Rows go into one buffer of a fixed size, handed on when it is nearly full.
  constexpr std::size_t kPiece = 64 * 1024;
  std::string out;
  out.reserve(kPiece + 64 + 260 * static_cast<std::size_t>(c.max_pairs));
  out += "travel_m,stiffness_N_per_m,rigid_body_stiffness_N_per_m,pairs_in_mesh,body_equivalent_compliance_m_per_N,"
         "transmission_error_m";
  for (int q = 0; q < c.max_pairs; ++q) {
    for (const char* col : kPairColumns) out += ",pair" + std::to_string(q) + "_" + col;
  }
  out += '\n';
  // %.9g through std::to_chars (the same digits, specified so): printf's
  // digit generation was two thirds of writing a long curve's table.
  char buf[64];
  auto g9 = [&](double v) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 9);
    out.append(buf, r.ptr);
  };
  auto num = [&](double v) {
    out += ',';
    g9(v);
  };
  for (const MeshState& s : c.samples) {
    g9(s.travel);
    num(s.stiffness);
    num(s.local_stiffness);
    out += "," + std::to_string(s.pairs.size());
    num(s.stiffness > 0 && s.local_stiffness > 0 ? 1.0 / s.stiffness - 1.0 / s.local_stiffness : 0.0);
    num(s.approach);
    for (int q = 0; q < c.max_pairs; ++q) {
      const PairState* p = nullptr;
      for (const PairState& cand : s.pairs) {
        if (cand.slot == q) p = &cand;
      }
      if (!p) {
        out += ",0";
        for (std::size_t k = 1; k < std::size(kPairColumns); ++k) out += ",";
        continue;
      }
      out += ",1," + std::to_string(p->rack_tooth) + "," + std::to_string(p->pinion_tooth);
      num(p->s);
      num(p->x);
      num(p->load_share);
      num(p->pinion.bending);
      num(p->pinion.shear);
      num(p->pinion.axial);
      num(p->fillet);
      num(p->hertz);
      num(p->rack.bending);
      num(p->rack.shear);
      num(p->rack.axial);
      num(p->rack_foundation);
      num(p->body);
      num(p->relief);
    }
    out += '\n';
    if (out.size() >= kPiece) {
      write(out);
      out.clear();
    }
  }
  if (!out.empty()) write(out);
}

std::string stiffness_json(const Drive& d, const MeshGeometry& g, const StiffnessCurve& c, const MeshRipple& r,
                           const TransmissionError& te, const Timings& t, const std::string& csv_path,
                           const std::string& plot_path) {
  JsonWriter j;
  j.begin_object();
  j.key("problem").value(d.source_file);
  j.key("name").value(d.name);
  j.key("contact_ratio").value(g.path.contact_ratio);
  j.key("contact_ratio_geometric").value(g.path.contact_ratio_geometric);
  j.key("path_of_contact").begin_object();
  j.key("s_start").value(g.path.s_start);
  j.key("s_end").value(g.path.s_end);
  j.key("s_pitch").value(g.path.s_pitch);
  j.key("s_rack_tip").value(g.path.s_rack_tip);
  j.key("start_limited_by").value(g.path.start_limited_by);
  j.key("base_pitch").value(g.path.base_pitch);
  j.end_object();
  j.key("undercut").value(g.pinion.undercut);
  {
    // ISO 6336-1's single stiffness beside the model's single pair at the pitch point.
    const IsoSingleStiffness iso = iso_single_stiffness(d);
    j.key("iso_6336_single_stiffness").begin_object();
    j.key("c_prime_N_per_mm_um").value(iso.c_prime);
    j.key("stiffness_N_per_m").value(iso.stiffness);
    j.key("model_single_pair_at_pitch_point_N_per_m").value(single_pair_stiffness_at_pitch_point(d, g));
    j.end_object();
  }
  j.key("k_min").value(c.k_min);
  j.key("k_max").value(c.k_max);
  j.key("k_mean").value(c.k_mean);
  j.key("k_fluctuation").value(c.k_fluctuation);
  j.key("travel_at_min").value(c.travel_at_min);
  j.key("travel_at_max").value(c.travel_at_max);
  j.key("mesh_ripple_max").value(r.max);
  j.key("mesh_ripple_mean").value(r.mean);
  j.key("mesh_ripple").begin_array();
  for (double v : r.ripple) j.value(v);
  j.end_array();
  j.key("transmission_error").begin_object();
  j.key("peak_to_peak").value(te.peak_to_peak);
  j.key("min").value(te.min);
  j.key("max").value(te.max);
  j.key("travel_at_min").value(te.travel_at_min);
  j.key("travel_at_max").value(te.travel_at_max);
  j.key("period_max").value(te.period_max);
  j.key("period_mean").value(te.period_mean);
  j.key("period_peak_to_peak").begin_array();
  for (double v : te.period_peak_to_peak) j.value(v);
  j.end_array();
  j.end_object();
  j.key("zones").begin_object();
  for (const Zone& z : g.zones) j.key(std::to_string(z.pairs)).value(z.length_travel);
  j.end_object();
  j.key("zones_along_loa").begin_object();
  for (const Zone& z : g.zones) j.key(std::to_string(z.pairs)).value(z.length_loa);
  j.end_object();
  j.key("breakpoints").begin_array();
  for (double b : c.breakpoints) j.value(b);
  j.end_array();
  j.key("samples").value(static_cast<long>(c.samples.size()));
  j.key("warnings").begin_array();
  for (const std::string& w : c.warnings) j.value(w);
  j.end_array();
  j.key("files").begin_object();
  j.key("csv").value(csv_path);
  if (plot_path.empty()) {
    j.key("plot").null();
  } else {
    j.key("plot").value(plot_path);
  }
  j.end_object();
  j.key("timings").begin_object();
  j.key("model_ms").value(t.model_ms);
  j.key("curve_ms").value(t.curve_ms);
  j.key("total_ms").value(t.total_ms);
  j.end_object();
  j.end_object();
  return j.str();
}

std::string stiffness_plot_data(const StiffnessCurve& c) {
  std::string out;
  out.reserve(c.samples.size() * (48 + 16 * static_cast<std::size_t>(c.max_pairs)));
  char buf[64];
  auto csv_digits = [&](double v) {  // the CSV's digits (%.9g)
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 9);
    return std::string_view(buf, static_cast<std::size_t>(r.ptr - buf));
  };
  auto num = [&](double v) {
    out += ' ';
    out += csv_digits(v);
  };
  // The value gnuplot computed from the CSV's digits scaled by `factor` (the
  // same double: one IEEE operation on the parsed digits), written so that
  // it parses back to that double (the shortest round-trip form).
  auto scaled = [&](double v, double factor, bool divide) {
    const std::string_view digits = csv_digits(v);
    double parsed = 0;
    std::from_chars(digits.data(), digits.data() + digits.size(), parsed);
    const double shown = divide ? parsed / factor : parsed * factor;
    out += ' ';
    const auto r = std::to_chars(buf, buf + sizeof buf, shown);
    out.append(buf, r.ptr);
  };
  for (const MeshState& s : c.samples) {
    num(s.travel);
    scaled(s.stiffness, 1e6, true);
    scaled(s.local_stiffness, 1e6, true);
    scaled(s.approach, 1e6, false);
    for (int q = 0; q < c.max_pairs; ++q) {
      const PairState* p = nullptr;
      for (const PairState& cand : s.pairs) {
        if (cand.slot == q) p = &cand;
      }
      // NaN leaves a gap in the line where the slot is out of mesh.
      if (p != nullptr) {
        num(p->load_share);
      } else {
        out += " NaN";
      }
    }
    out += '\n';
  }
  return out;
}

std::string stiffness_gnuplot(const StiffnessCurve& c, const std::string& title, const std::string& csv_name,
                              const std::string& png_name) {
  std::ostringstream o;
  o << "# Generated by rackopt: plots the columns of " << gnuplot_quote(csv_name)
    << " it draws, copied below (columns: docs/output.md)\n";
  // The plotted columns inline, read once per image: parsing the whole
  // 60-column CSV once per curve and image was most of gnuplot's time.
  // Columns in the units drawn (stiffness_plot_data): plain column numbers
  // in `using`, because gnuplot evaluates a `using` expression per point
  // with three signal system calls each (its SIGFPE guard), which was a third
  // of this plot's gnuplot time.
  o << "$rackopt_stiffness << EOD\n" << stiffness_plot_data(c) << "EOD\n";
  o << gnuplot_terminal(png_name, 1400, 1200);
  o << "set multiplot layout 3,1 title " << gnuplot_quote(title) << "\n";
  o << "set grid\nset key outside right\n";
  // Fixed margins: the panels' travel axes line up whatever their legends' widths.
  o << "set lmargin at screen 0.08\nset rmargin at screen 0.80\n";
  // The travel runs from one rack support to the next: the x range ends at
  // the span, and both supports (hinges) are marked in every panel.
  if (!c.samples.empty()) {
    const double span = c.samples.back().travel;
    o << std::setprecision(17) << "set xrange [0:" << span << "]\n";
    for (double x : {0.0, span}) {
      o << "set arrow from " << x << ", graph 0 to " << x << ", graph 1 nohead dt 2 lw 3 lc rgb '#555555' front\n";
    }
    o << "set label 'hinge' at first 0, graph 1 offset 0.5,-1 front\n";
    o << "set label 'hinge' at first " << span << ", graph 1 right offset -0.5,-1 front\n";
  }
  const std::string data = "$rackopt_stiffness";
  o << "set ylabel 'mesh stiffness [MN/m]'\nset logscale y\n";
  o << "plot " << data << " using 1:2 with lines lw 2 title 'coupled mesh', \\\n"
    << "     " << data << " using 1:3 with lines dt 2 title 'rigid rack body'\n";
  o << "set xlabel 'travel of the pitch point along the span [m]'\n";
  o << "unset logscale y\nset ylabel 'load share [-]'\nset yrange [0:1.05]\n";
  // The empty first plot takes the first line colour (one point read).
  o << "plot " << data << " using 1:(1/0) every ::0::0 notitle";
  for (int q = 0; q < c.max_pairs; ++q) {
    o << ", \\\n     " << data << " using 1:" << 5 + q << " with lines title 'pair slot " << q << "'";
  }
  o << "\nset yrange [*:*]\nset ylabel 'transmission error [um]'\n";
  o << "plot " << data << " using 1:4 with lines lw 2 title 'mesh deflection under load'\n";
  o << "unset multiplot\n";
  return o.str();
}

}  // namespace rackopt
