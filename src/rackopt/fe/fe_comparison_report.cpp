#include "rackopt/fe/fe_comparison_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "rackopt/output/json_writer.hpp"
#include "rackopt/output/plot.hpp"

namespace rackopt::fe {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
// A CSV cell: empty when undefined.
std::string cell(double v) { return std::isfinite(v) ? fmt("%.9g", v) : std::string(); }
std::string percent(double v) { return std::isfinite(v) ? fmt("%+.2f", 100.0 * v) + " %" : std::string("n/a"); }
std::string mnm(double v) { return fmt("%.4g", v * 1e-6) + " MN/m"; }
// Compliances in um/kN (= 1e-9 m/N): numbers of order 1..100 for gear teeth.
std::string umkn(double v) { return fmt("%.4g", v * 1e9); }
std::string time_text(double s) {
  if (s >= 1) return fmt("%.3g", s) + " s";
  if (s >= 1e-3) return fmt("%.3g", s * 1e3) + " ms";
  return fmt("%.3g", s * 1e6) + " us";
}

const ComparedPair* in_slot(const ComparedPosition& row, int slot) {
  for (const ComparedPair& p : row.pairs) {
    if (p.slot == slot) return &p;
  }
  return nullptr;
}

}  // namespace

std::string fe_comparison_csv(const FeComparison& c) {
  std::string out =
      "travel_m,k_fe_N_per_m,k_analytic_N_per_m,k_error,pairs_in_mesh,extended_pairs_fe,extended_share_fe,fe_force_N,"
      "fe_mesh_s,fe_tooth_s,analytic_s";
  static const char* kPairCols[] = {"in_mesh",
                                    "rack_tooth",
                                    "pinion_tooth",
                                    "s_m",
                                    "share_fe",
                                    "share_analytic",
                                    "share_difference",
                                    "c_pinion_fe_m_per_N",
                                    "c_pinion_analytic_m_per_N",
                                    "c_pinion_error",
                                    "c_rack_fe_m_per_N",
                                    "c_rack_analytic_m_per_N",
                                    "c_rack_error"};
  for (int q = 0; q < c.slots; ++q) {
    for (const char* col : kPairCols) out += ",pair" + std::to_string(q) + "_" + col;
  }
  out += '\n';
  for (const ComparedPosition& r : c.rows) {
    out += cell(r.travel) + "," + cell(r.k_fe) + "," + cell(r.k_analytic) + "," + cell(r.k_error) + "," +
           std::to_string(r.pairs.size()) + "," + std::to_string(r.extended_pairs.size()) + "," + cell(r.extended_share_fe) + "," + cell(r.fe_force) +
           "," + cell(r.fe_mesh_seconds) + "," + cell(r.fe_tooth_seconds) + "," + cell(r.analytic_seconds);
    for (int q = 0; q < c.slots; ++q) {
      const ComparedPair* p = in_slot(r, q);
      if (!p) {
        out += ",0";
        for (std::size_t k = 1; k < std::size(kPairCols); ++k) out += ",";
        continue;
      }
      out += ",1," + std::to_string(p->rack_tooth) + "," + std::to_string(p->pinion_tooth);
      for (double v : {p->s, p->share_fe, p->share_analytic, p->share_error}) out += "," + cell(v);
      // Empty cells where the pinion's contact is off its involute (not compared).
      out += p->pinion_compared ? "," + cell(p->pinion_fe) : std::string(",");
      out += "," + cell(p->pinion_analytic);
      out += p->pinion_compared ? "," + cell(p->pinion_error) : std::string(",");
      for (double v : {p->rack_fe, p->rack_analytic, p->rack_error}) out += "," + cell(v);
    }
    out += '\n';
  }
  return out;
}

std::string fe_comparison_json(const Drive& drive, const FeComparison& c, const FeFiles& files,
                               const std::vector<std::string>& warnings) {
  JsonWriter j;
  j.begin_object();
  j.key("ok").value(true);
  j.key("problem").value(drive.source_file);
  j.key("name").value(drive.name);
  j.key("options").begin_object();
  j.key("positions").value(static_cast<int>(c.rows.size()));
  j.key("level").value(c.fe.level);
  j.key("extended_contact").value(c.fe.extended_contact);
  j.key("rack_body_depth").value(c.fe.rack_body_depth);
  j.key("rack_on_supports").value(c.fe.rack_on_supports);
  j.key("threads").value(static_cast<long>(c.threads));
  j.end_object();
  j.key("conventions").begin_array();
  for (const std::string& n : c.notes) j.value(n);
  j.end_array();
  j.key("pitch").value(c.pitch);
  j.key("period_start").value(c.period_start);
  j.key("contact_ratio").value(c.contact_ratio);
  j.key("positions").begin_array();
  for (const ComparedPosition& r : c.rows) {
    j.begin_object();
    j.key("travel").value(r.travel);
    j.key("k_fe").value(r.k_fe);
    j.key("k_analytic").value(r.k_analytic);
    j.key("k_error").value(r.k_error);
    j.key("fe_force").value(r.fe_force);
    j.key("nodes").value(r.nodes);
    j.key("elements").value(r.elements);
    j.key("fe_mesh_seconds").value(r.fe_mesh_seconds);
    j.key("fe_tooth_seconds").value(r.fe_tooth_seconds);
    j.key("analytic_seconds").value(r.analytic_seconds);
    j.key("pairs").begin_array();
    for (const ComparedPair& p : r.pairs) {
      j.begin_object();
      j.key("rack_tooth").value(p.rack_tooth);
      j.key("pinion_tooth").value(p.pinion_tooth);
      j.key("slot").value(p.slot);
      j.key("s").value(p.s);
      j.key("carried_in_fe").value(p.carried_in_fe);
      j.key("share_fe").value(p.share_fe);
      j.key("share_analytic").value(p.share_analytic);
      j.key("share_difference").value(p.share_error);
      j.key("pinion_compared").value(p.pinion_compared);
      if (p.pinion_compared) {
        j.key("pinion_fe").value(p.pinion_fe);
      } else {
        j.key("pinion_fe").null();
      }
      j.key("pinion_analytic").value(p.pinion_analytic);
      if (p.pinion_compared) {
        j.key("pinion_error").value(p.pinion_error);
      } else {
        j.key("pinion_error").null();
      }
      j.key("rack_fe").value(p.rack_fe);
      j.key("rack_analytic").value(p.rack_analytic);
      j.key("rack_error").value(p.rack_error);
      j.key("pinion_seconds").value(p.pinion_seconds);
      j.key("rack_seconds").value(p.rack_seconds);
      j.end_object();
    }
    j.end_array();
    j.key("extended_share_fe").value(r.extended_share_fe);
    j.key("extended_pairs").begin_array();
    for (const FePair& p : r.extended_pairs) {
      j.begin_object();
      j.key("rack_tooth").value(p.rack_tooth);
      j.key("pinion_tooth").value(p.pinion_tooth);
      j.key("s").value(p.s);
      j.key("theoretical").value(p.theoretical);
      j.key("share_fe").value(p.load_share);
      j.key("force").value(p.force);
      j.end_object();
    }
    j.end_array();
    j.end_object();
  }
  j.end_array();
  const FeComparisonSummary& s = c.summary;
  j.key("summary").begin_object();
  j.key("max_k_error").value(s.max_k_error);
  j.key("max_share_difference").value(s.max_share_error);
  j.key("max_pinion_error").value(s.max_pinion_error);
  j.key("max_rack_error").value(s.max_rack_error);
  j.key("fe_mesh_seconds_per_position").value(s.fe_mesh_seconds_per_position);
  j.key("fe_seconds_per_position").value(s.fe_seconds_per_position);
  j.key("analytic_seconds_per_position").value(s.analytic_seconds_per_position);
  j.key("time_ratio").value(s.time_ratio);
  j.key("analytic_model_seconds").value(s.analytic_model_seconds);
  j.key("wall_seconds").value(s.wall_seconds);
  j.end_object();
  j.key("analytic_curve").begin_array();
  for (const auto& [x, k] : c.analytic_curve) j.begin_array().value(x).value(k).end_array();
  j.end_array();
  j.key("files").begin_object();
  auto path = [&](const char* key, const std::string& p) {
    if (p.empty()) {
      j.key(key).null();
    } else {
      j.key(key).value(p);
    }
  };
  path("csv", files.csv);
  path("json", files.json);
  path("plot", files.plot);
  path("mesh_png", files.mesh_png);
  path("deformed_png", files.deformed_png);
  j.end_object();
  j.key("pictures");
  if (files.pictures.asked) {
    j.begin_object();
    j.key("travel").value(files.pictures.travel);
    j.key("displacement_scale").value(files.pictures.displacement_scale);
    j.key("largest_displacement").value(files.pictures.largest_displacement);
    j.end_object();
  } else {
    j.null();
  }
  j.key("warnings").begin_array();
  for (const std::string& w : warnings) j.value(w);
  j.end_array();
  j.end_object();
  return j.str();
}

std::string fe_comparison_gnuplot(const FeComparison& c, const std::string& title, const std::string& png_name) {
  std::ostringstream o;
  o << "# Generated by rackopt: mesh stiffness over one mesh period, analytic vs FE (docs/fe.md)\n";
  o << "$analytic << EOD\n";
  for (const auto& [x, k] : c.analytic_curve) o << fmt("%.9g", x) << " " << fmt("%.9g", k) << "\n";
  o << "EOD\n$fe << EOD\n";
  for (const ComparedPosition& r : c.rows) o << fmt("%.9g", r.travel) << " " << fmt("%.9g", r.k_fe) << "\n";
  o << "EOD\n";
  o << gnuplot_terminal(png_name, 1200, 700);
  o << "set title "
    << gnuplot_quote(title + ": mesh stiffness, analytic (" +
                     (c.fe.rack_on_supports ? "rack on its supports" : "rigid rack body") + ") vs FE, level " +
                     std::to_string(c.fe.level))
    << "\n";
  o << "set grid\nset key outside right\n";
  o << "set xlabel 'travel of the pitch point [m]'\nset ylabel 'mesh stiffness [MN/m]'\n";
  o << "plot $analytic using 1:($2/1e6) with lines lw 2 title 'analytic', \\\n"
    << "     $fe using 1:($2/1e6) with points pt 7 ps 1.8 title 'FE'\n";
  return o.str();
}

std::string fe_comparison_summary(const FeComparison& c) {
  std::ostringstream o;
  o << "  FE vs analytic over one mesh period (" << c.rows.size() << " positions from X0 = "
    << fmt("%.6g", c.period_start) << " m, pitch " << fmt("%.4g", c.pitch * 1e3) << " mm; level " << c.fe.level
    << (c.fe.extended_contact ? ", extended contact" : "") << (c.fe.rack_on_supports ? ", rack on its supports" : "")
    << ", " << c.threads << " thread"
    << (c.threads == 1 ? "" : "s") << "):\n";
  for (const ComparedPosition& r : c.rows) {
    o << "    X = " << fmt("%.6g", r.travel) << " m: K FE " << mnm(r.k_fe) << ", analytic " << mnm(r.k_analytic)
      << " (" << percent(r.k_error) << "), " << r.pairs.size() << " pair" << (r.pairs.size() == 1 ? "" : "s");
    if (!r.extended_pairs.empty()) {
      o << " + " << r.extended_pairs.size() << " in extended contact carrying " << fmt("%.1f", 100 * r.extended_share_fe)
        << " % of the force";
    }
    o << "\n";
  }
  const FeComparisonSummary& s = c.summary;
  o << "  max |error|: K " << fmt("%.2f", 100 * s.max_k_error) << " %, load share "
    << fmt("%.3f", s.max_share_error) << " (difference), pinion tooth + fillet "
    << fmt("%.2f", 100 * s.max_pinion_error) << " %, rack tooth " << fmt("%.2f", 100 * s.max_rack_error) << " %\n";
  o << "  time per position: FE " << time_text(s.fe_seconds_per_position) << " (mesh solve "
    << time_text(s.fe_mesh_seconds_per_position) << "), analytic " << time_text(s.analytic_seconds_per_position)
    << ": FE / analytic = " << fmt("%.3g", s.time_ratio) << "\n";
  for (const std::string& n : c.notes) o << "  note: " << n << "\n";
  return o.str();
}

std::string fe_comparison_markdown(const FeComparison& c) {
  std::ostringstream o;
  o << c.rows.size() << " positions over one mesh period (X0 = " << fmt("%.6g", c.period_start)
    << " m, pitch " << fmt("%.4g", c.pitch * 1e3) << " mm), FE level " << c.fe.level
    << (c.fe.extended_contact ? ", extended contact" : "") << (c.fe.rack_on_supports ? ", rack on its supports" : "")
    << ". Conventions:\n\n";
  for (const std::string& n : c.notes) o << "- " << n << "\n";
  o << "\n| X [m] | K FE [MN/m] | K analytic [MN/m] | K error | pair (rack/pinion) | share FE | share analytic |"
       " pinion FE [um/kN] | pinion analytic | pinion error | rack FE [um/kN] | rack analytic | rack error |\n";
  o << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const ComparedPosition& r : c.rows) {
    bool first = true;
    for (const ComparedPair& p : r.pairs) {
      if (first) {
        o << "| " << fmt("%.6g", r.travel) << " | " << fmt("%.4g", r.k_fe * 1e-6) << " | "
          << fmt("%.4g", r.k_analytic * 1e-6) << " | " << percent(r.k_error) << " | ";
      } else {
        o << "| | | | | ";
      }
      first = false;
      o << p.rack_tooth << "/" << p.pinion_tooth << " | " << fmt("%.3f", p.share_fe) << " | "
        << fmt("%.3f", p.share_analytic) << " | " << (p.pinion_compared ? umkn(p.pinion_fe) : "off involute")
        << " | " << umkn(p.pinion_analytic) << " | " << (p.pinion_compared ? percent(p.pinion_error) : "—") << " | " << umkn(p.rack_fe) << " | " << umkn(p.rack_analytic) << " | "
        << percent(p.rack_error) << " |\n";
    }
    if (first) {
      o << "| " << fmt("%.6g", r.travel) << " | " << fmt("%.4g", r.k_fe * 1e-6) << " | "
        << fmt("%.4g", r.k_analytic * 1e-6) << " | " << percent(r.k_error) << " | | | | | | | | | |\n";
    }
  }
  const FeComparisonSummary& s = c.summary;
  o << "\nLargest |error|: K " << fmt("%.2f", 100 * s.max_k_error) << " %, load share "
    << fmt("%.3f", s.max_share_error) << " (difference of fractions), pinion tooth + fillet "
    << fmt("%.2f", 100 * s.max_pinion_error) << " %, rack tooth " << fmt("%.2f", 100 * s.max_rack_error)
    << " %.\n\n";
  o << "Time per position: FE " << time_text(s.fe_seconds_per_position) << " (mesh-position solve "
    << time_text(s.fe_mesh_seconds_per_position) << ", the rest single-tooth solves), analytic "
    << time_text(s.analytic_seconds_per_position) << ": FE / analytic = " << fmt("%.3g", s.time_ratio) << ".\n";
  return o.str();
}

}  // namespace rackopt::fe
