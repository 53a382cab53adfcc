#include "rackopt/output/dynamics_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>

#include "rackopt/dynamics/spectrum.hpp"
#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt {
namespace {

const char* status_name(ResponseStatus s) {
  switch (s) {
    case ResponseStatus::kConverged: return "converged";
    case ResponseStatus::kNotPeriodic: return "not_periodic";
    case ResponseStatus::kUnbounded: return "unbounded";
  }
  return "unknown";
}

std::string num(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream o;
  o << std::setprecision(10) << v;
  return o.str();
}

// The spectrum of one steady period of a response history (uniform in travel,
// so uniform in time at constant speed).
Spectrum history_spectrum(const SteadyResponse& r, const std::vector<double>& values) {
  return amplitude_spectrum(values, r.excitation_period_s);
}

bool has_history(const DriveDynamics& d) { return d.at_speed && d.at_speed->mesh_force.size() >= 2; }

void response_json(JsonWriter& j, const DriveDynamics& d) {
  const SteadyResponse& r = *d.at_speed;
  j.key("response").begin_object();
  j.key("speed_m_per_s").value(r.speed);
  j.key("status").value(status_name(r.status));
  j.key("periods").value(r.periods);
  j.key("kv").value(r.dynamic_factor);
  j.key("mesh_force_max_N").value(r.mesh_force_max);
  j.key("mesh_force_min_N").value(r.mesh_force_min);
  j.key("dte_max_m").value(r.dte_max);
  j.key("dte_min_m").value(r.dte_min);
  j.key("dte_peak_to_peak_m").value(r.dte_peak_to_peak);
  j.key("contact_loss_fraction").value(r.contact_loss_fraction);
  j.key("back_flank_contact").value(r.back_flank_contact);
  if (has_history(d)) {
    const Spectrum s = history_spectrum(r, r.mesh_force);
    j.key("mesh_order_hz").value(r.speed / d.law.mesh_pitch);
    j.key("span_order_hz").value(r.speed / d.law.period);
    j.key("mesh_force_at_mesh_order_N").value(amplitude_at(s, r.speed / d.law.mesh_pitch));
    j.key("mesh_force_at_span_order_N").value(amplitude_at(s, r.speed / d.law.period));
  }
  if (!r.message.empty()) j.key("message").value(r.message);
  j.end_object();
}

}  // namespace

std::string dynamics_json(const DriveDynamics& d) {
  JsonWriter j;
  j.begin_object();
  j.key("static_mesh_force_N").value(d.static_force);
  j.key("mean_stiffness_N_per_m").value(d.mean_stiffness);
  j.key("damping_ratio").value(d.damping_ratio);
  j.key("operating_speed_m_per_s").value(d.operating_speed);
  j.key("backlash_along_line_of_action_m").value(d.law.backlash);
  j.key("drive_train").begin_object();
  j.key("moving_mass_kg").value(d.train.moving_mass);
  j.key("drive_inertia_kg_m2").value(d.train.drive_inertia);
  j.key("pinion_inertia_kg_m2").value(d.train.pinion_inertia);
  j.key("drive_stiffness_N_m_per_rad").value(d.train.drive_stiffness);
  j.key("base_radius_m").value(d.train.base_radius);
  j.key("pressure_angle_rad").value(d.train.pressure_angle);
  j.end_object();
  j.key("natural_frequencies_hz").begin_array();
  for (double f : d.natural_frequencies_hz) j.value(f);
  j.end_array();
  j.key("natural_frequency_range_hz").begin_array();
  for (const auto& along : d.natural_frequency_along_travel) {
    const auto [lo, hi] = std::minmax_element(along.begin(), along.end());
    j.begin_array().value(*lo).value(*hi).end_array();
  }
  j.end_array();
  j.key("resonances").begin_array();
  for (const Resonance& r : d.resonances) {
    j.begin_object();
    j.key("order").value(r.order);
    j.key("mode").value(r.mode);
    j.key("speed_m_per_s").value(r.speed_at_mean);
    j.key("speed_low_m_per_s").value(r.speed_low);
    j.key("speed_high_m_per_s").value(r.speed_high);
    j.end_object();
  }
  j.end_array();
  j.key("resonance_margin").value(d.resonance_margin);
  if (d.at_speed) response_json(j, d);
  j.key("kv_curve").begin_array();
  for (const SweepPoint& p : d.sweep) {
    j.begin_object();
    j.key("speed_m_per_s").value(p.speed);
    j.key("kv").value(std::max(p.kv_up, p.kv_down));
    j.key("kv_up").value(p.kv_up);
    j.key("kv_down").value(p.kv_down);
    j.key("dte_pp_up_m").value(p.dte_pp_up);
    j.key("dte_pp_down_m").value(p.dte_pp_down);
    j.key("contact_loss_up").value(p.contact_loss_up);
    j.key("contact_loss_down").value(p.contact_loss_down);
    j.key("status_up").value(status_name(p.status_up));
    j.key("status_down").value(status_name(p.status_down));
    j.end_object();
  }
  j.end_array();
  j.key("kv_max").value(d.kv_max);
  j.key("speed_at_kv_max_m_per_s").value(d.speed_at_kv_max);
  if (!d.stability.empty()) {
    j.key("stability").begin_array();
    for (const StabilityPoint& s : d.stability) {
      j.begin_object().key("speed_m_per_s").value(s.speed).key("spectral_radius").value(s.spectral_radius).end_object();
    }
    j.end_array();
    j.key("parametric_stability_margin").value(d.stability_margin);
  }
  j.key("warnings").begin_array();
  for (const std::string& w : d.warnings) j.value(w);
  j.end_array();
  j.end_object();
  return j.str();
}

std::string dynamics_summary(const DriveDynamics& d) {
  std::ostringstream o;
  o << "dynamics (mesh force law: " << d.law.travel.size() << " samples over the span, backlash "
    << (std::isfinite(d.law.backlash) ? format_length_mm(d.law.backlash, 4) : std::string("none")) << ")\n";
  o << "  static mesh force " << format_force_kN(d.static_force, 5) << ", tangent stiffness mean "
    << format_stiffness_MN_per_m(d.mean_stiffness, 5) << ", damping ratio " << format_number(d.damping_ratio, 3)
    << "\n";
  o << "  natural frequencies at the mean stiffness:";
  for (std::size_t i = 0; i < d.natural_frequencies_hz.size(); ++i) {
    const auto [lo, hi] = std::minmax_element(d.natural_frequency_along_travel[i].begin(),
                                              d.natural_frequency_along_travel[i].end());
    o << " " << format_number(d.natural_frequencies_hz[i], 5) << " Hz (" << format_number(*lo, 4) << " .. "
      << format_number(*hi, 4) << " along the span)";
  }
  o << "\n";
  for (const Resonance& r : d.resonances) {
    if (r.mode != 0 || (r.order != "mesh" && r.order != "span")) continue;
    o << "  main resonance, " << r.order << " order on mode 1: " << format_number(r.speed_at_mean, 4) << " m/s ("
      << format_number(r.speed_low, 4) << " .. " << format_number(r.speed_high, 4) << ")\n";
  }
  if (d.operating_speed > 0 && std::isfinite(d.resonance_margin)) {
    o << "  operating speed " << format_number(d.operating_speed, 4) << " m/s: "
      << format_number(100 * d.resonance_margin, 3) << " % from the nearest main resonance\n";
  }
  if (d.at_speed) {
    const SteadyResponse& r = *d.at_speed;
    o << "  at " << format_number(r.speed, 4) << " m/s: K_V " << format_number(r.dynamic_factor, 5)
      << ", mesh force " << format_force_kN(r.mesh_force_min, 4) << " .. " << format_force_kN(r.mesh_force_max, 4)
      << ", DTE peak-to-peak " << format_length_mm(r.dte_peak_to_peak, 4) << ", contact loss "
      << format_number(100 * r.contact_loss_fraction, 3) << " % of the time"
      << (r.back_flank_contact ? ", back-flank contact" : "") << " (" << status_name(r.status) << " after "
      << r.periods << " spans)\n";
  }
  if (!d.sweep.empty()) {
    o << "  K_V over " << d.sweep.size() << " speeds " << format_number(d.sweep.front().speed, 4) << " .. "
      << format_number(d.sweep.back().speed, 4) << " m/s: max " << format_number(d.kv_max, 5) << " at "
      << format_number(d.speed_at_kv_max, 4) << " m/s\n";
  }
  if (!d.stability.empty()) {
    o << "  parametric stability margin (1 - largest Floquet multiplier) " << format_number(d.stability_margin, 4)
      << (d.stability_margin > 0 ? " (stable over the range)\n" : " (unstable at some speeds)\n");
  }
  for (const std::string& w : d.warnings) o << "  warning: " << w << "\n";
  return o.str();
}

namespace {

void write_csv(const std::string& path, const std::function<void(std::ostringstream&)>& body) {
  std::ostringstream o;
  body(o);
  write_file_atomic(path, o.str());
}

// A panel with nothing to draw: its title and a note (gnuplot refuses a plot
// whose points are all undefined, so a constant outside the range is drawn).
std::string empty_panel(const std::string& note) {
  return "set xrange [0:1]\nset yrange [0:1]\nunset logscale y\nset label 9 " + gnuplot_quote(note) +
         " at 0.5, 0.5 center\nplot 2 notitle\nunset label 9\nset xrange [*:*]\nset yrange [*:*]\n";
}

std::string gnuplot_script(const DriveDynamics& d, const std::string& title, const std::string& png) {
  std::ostringstream o;
  o << std::setprecision(10);
  o << "# Generated by rackopt: the dynamic analysis (docs/output.md); data from the dynamics_*.csv files\n";
  o << "$sweep << EOD\n";
  for (const SweepPoint& p : d.sweep) o << p.speed << " " << p.kv_up << " " << p.kv_down << "\n";
  o << "EOD\n$response << EOD\n";
  if (d.at_speed) {
    const SteadyResponse& r = *d.at_speed;
    for (std::size_t i = 0; i < r.travel.size(); ++i)
      o << r.travel[i] << " " << r.mesh_force[i] << " " << r.dte[i] << "\n";
  }
  o << "EOD\n$spectrum << EOD\n";
  if (has_history(d)) {
    const Spectrum s = history_spectrum(*d.at_speed, d.at_speed->mesh_force);
    for (std::size_t k = 1; k < s.frequency_hz.size(); ++k) o << s.frequency_hz[k] << " " << s.amplitude[k] << "\n";
  }
  o << "EOD\n";
  const int panels = 4 + (d.stability.empty() ? 0 : 1);
  o << gnuplot_terminal(png, 1400, panels > 4 ? 1500 : 1200);
  o << "set multiplot layout " << (panels > 4 ? 3 : 2) << ",2 title " << gnuplot_quote(title) << "\n";
  o << "set grid\nset key top left\n";
  // K_V over speed.
  o << "set title 'dynamic factor over speed'\nset xlabel 'pitch-line speed [m/s]'\nset ylabel 'K_V [-]'\n";
  if (d.operating_speed > 0)
    o << "set arrow 1 from " << d.operating_speed << ", graph 0 to " << d.operating_speed
      << ", graph 1 nohead dt 2 lc rgb '#555555'\n";
  if (d.sweep.empty()) {
    o << empty_panel("no speed sweep (rackopt dynamics --sweep)");
  } else {
    o << "plot $sweep using 1:2 with linespoints pt 7 ps 0.5 title 'speed rising', "
         "$sweep using 1:3 with lines dt 2 title 'speed falling'\n";
  }
  o << "unset arrow 1\n";
  // Force and DTE over the travel.
  o << "set title 'steady response over one span'\nset xlabel 'travel [m]'\nset ylabel 'mesh force [kN]'\n"
       "set y2label 'dynamic transmission error [um]'\nset ytics nomirror\nset y2tics\n";
  if (d.at_speed) {
    o << "plot $response using 1:($2/1e3) with lines lw 2 title 'mesh force', "
         "$response using 1:($3*1e6) axes x1y2 with lines title 'DTE', "
      << d.static_force / 1e3 << " with lines dt 2 lc rgb '#555555' title 'static force'\n";
  } else {
    o << empty_panel("no operating speed (load.speed or --speed)");
  }
  o << "unset y2label\nunset y2tics\nset ytics mirror\n";
  // Spectrum.
  o << "set title 'mesh force spectrum at the operating speed'\nset xlabel 'frequency [Hz]'\n"
       "set ylabel 'amplitude [N]'\nset logscale y\n";
  if (has_history(d)) {
    const double fm = d.at_speed->speed / d.law.mesh_pitch;
    o << "set xrange [0:" << 4 * fm << "]\n";
    o << "plot $spectrum using 1:($2>0?$2:1/0) with impulses lw 2 title 'amplitude'\nset xrange [*:*]\n";
  } else {
    o << empty_panel("no operating speed (load.speed or --speed)");
  }
  o << "unset logscale y\n";
  // Campbell diagram.
  const double vmax = d.speeds.empty() ? std::max(d.operating_speed, 1e-3) * 1.25 : d.speeds.back();
  o << "set title 'Campbell diagram'\nset xlabel 'pitch-line speed [m/s]'\nset ylabel 'frequency [Hz]'\n"
       "set xrange [0:" << vmax << "]\nset key top left\n";
  // The frequency axis shows the orders over the speed range and the modes
  // they can meet there: a stiff drive-train mode far above every order
  // would squeeze the crossings into the bottom of the panel.
  double f1max = 0;
  if (!d.natural_frequency_along_travel.empty())
    f1max = *std::max_element(d.natural_frequency_along_travel[0].begin(), d.natural_frequency_along_travel[0].end());
  double order_max = 0;
  for (const ExcitationOrder& e : d.orders) {
    if (e.name != "span") order_max = std::max(order_max, vmax / e.wavelength);
  }
  const double fmax = std::max(1.5 * f1max, 1.1 * order_max);
  o << "set yrange [0:" << fmax << "]\nset samples 400\n";
  o << "plot ";
  for (std::size_t i = 0; i < d.orders.size(); ++i) {
    o << (i ? ", " : "") << "x/" << d.orders[i].wavelength << " with lines title " << gnuplot_quote(d.orders[i].name + " order");
  }
  for (std::size_t i = 0; i < d.natural_frequency_along_travel.size(); ++i) {
    const auto [lo, hi] = std::minmax_element(d.natural_frequency_along_travel[i].begin(),
                                              d.natural_frequency_along_travel[i].end());
    if (*lo > fmax) continue;
    o << ", " << d.natural_frequencies_hz[i] << " with lines lw 2 lc rgb 'black' title 'mode " << i + 1
      << " (mean stiffness)'";
    o << ", " << *lo << " with lines dt 3 lc rgb 'black' title 'mode " << i + 1 << " along the span', " << *hi
      << " with lines dt 3 lc rgb 'black' notitle";
  }
  o << "\nset xrange [*:*]\nset yrange [*:*]\n";
  if (!d.stability.empty()) {
    o << "$stability << EOD\n";
    for (const StabilityPoint& s : d.stability) o << s.speed << " " << s.spectral_radius << "\n";
    o << "EOD\n";
    o << "set title 'parametric stability (Floquet)'\nset xlabel 'pitch-line speed [m/s]'\n"
         "set ylabel 'largest |multiplier| [-]'\n"
         "plot $stability using 1:2 with linespoints pt 7 ps 0.5 title 'spectral radius', 1 with lines dt 2 "
         "title 'stability limit'\n";
  }
  o << "unset multiplot\n";
  return o.str();
}

}  // namespace

WrittenFiles write_dynamics_files(const DriveDynamics& d, const std::string& out_dir, const std::string& title,
                                  PlotImages plots) {
  namespace fs = std::filesystem;
  const fs::path dir(out_dir.empty() ? std::string(".") : out_dir);
  WrittenFiles files;
  auto add = [&](const std::string& role, const std::string& path) {
    files.written.push_back(path);
    files.listed.emplace_back(role, path);
  };
  const std::string json = (dir / "dynamics.json").string();
  write_file_atomic(json, dynamics_json(d) + "\n");
  add("dynamics_json", json);
  if (!d.sweep.empty()) {
    const std::string path = (dir / "dynamics_sweep.csv").string();
    write_csv(path, [&](std::ostringstream& o) {
      o << "speed_m_per_s,kv_up,kv_down,dte_pp_up_m,dte_pp_down_m,contact_loss_up,contact_loss_down,status_up,"
           "status_down\n";
      for (const SweepPoint& p : d.sweep) {
        o << num(p.speed) << "," << num(p.kv_up) << "," << num(p.kv_down) << "," << num(p.dte_pp_up) << ","
          << num(p.dte_pp_down) << "," << num(p.contact_loss_up) << "," << num(p.contact_loss_down) << ","
          << status_name(p.status_up) << "," << status_name(p.status_down) << "\n";
      }
    });
    add("dynamics_sweep_csv", path);
  }
  if (has_history(d)) {
    const SteadyResponse& r = *d.at_speed;
    const std::string path = (dir / "dynamics_response.csv").string();
    write_csv(path, [&](std::ostringstream& o) {
      o << "travel_m,time_s,mesh_force_N,dte_m\n";
      for (std::size_t i = 0; i < r.travel.size(); ++i)
        o << num(r.travel[i]) << "," << num(r.travel[i] / r.speed) << "," << num(r.mesh_force[i]) << ","
          << num(r.dte[i]) << "\n";
    });
    add("dynamics_response_csv", path);
    const Spectrum force = history_spectrum(r, r.mesh_force);
    const Spectrum dte = history_spectrum(r, r.dte);
    const std::string spath = (dir / "dynamics_spectrum.csv").string();
    write_csv(spath, [&](std::ostringstream& o) {
      o << "frequency_hz,mesh_force_amplitude_N,dte_amplitude_m\n";
      for (std::size_t k = 0; k < force.frequency_hz.size(); ++k)
        o << num(force.frequency_hz[k]) << "," << num(force.amplitude[k]) << "," << num(dte.amplitude[k]) << "\n";
    });
    add("dynamics_spectrum_csv", spath);
  }
  {
    const std::string path = (dir / "dynamics_campbell.csv").string();
    write_csv(path, [&](std::ostringstream& o) {
      o << "travel_m";
      for (std::size_t i = 0; i < d.natural_frequency_along_travel.size(); ++i) o << ",mode" << i + 1 << "_hz";
      o << "\n";
      for (std::size_t j = 0; j < d.travel.size(); ++j) {
        o << num(d.travel[j]);
        for (const auto& along : d.natural_frequency_along_travel) o << "," << num(along[j]);
        o << "\n";
      }
    });
    add("dynamics_campbell_csv", path);
  }
  if (plots == PlotImages::kNone) return files;
  const std::string script = (dir / "dynamics.gp").string();
  write_file_atomic(script, gnuplot_script(d, title, "dynamics.png.tmp"));
  files.written.push_back(script);
  const RenderedImages images = render_plot_images(dir.string(), "dynamics.gp", "dynamics.png",
                                                   plots == PlotImages::kPngAndSvg ? "dynamics.svg" : "",
                                                   files.warnings);
  if (!images.png.empty()) add("dynamics_png", images.png);
  if (!images.svg.empty()) files.written.push_back(images.svg);
  return files;
}

}  // namespace rackopt
