// rackopt check / rackopt stiffness.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/output/folder_lock.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/geometry/pressure_angle_range.hpp"
#include "rackopt/output/stiffness_files.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/units/units.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/period_stats.hpp"

namespace rackopt::cli {

int cmd_check(const Args& a) {
  const rackopt::Drive drive = rackopt::load_problem(a.file, a.overrides);
  const rackopt::MeshStiffnessModel model(drive);
  std::string text = rackopt::geometry_summary(drive, model.geometry());
  const rackopt::PressureAngleRange range = rackopt::feasible_pressure_angles(drive);
  {
    auto limit = [](const std::string& code, const char* end) {
      return code.empty() ? std::string("the ") + end + " of the scanned 5..45 deg" : code;
    };
    text += "  pressure angles this cutter, tooth count, shift and clearance allow: " +
            rackopt::format_angle_deg(range.lower, 5) + " .. " + rackopt::format_angle_deg(range.upper, 5) +
            " (below: " + limit(range.lower_limit, "end") + "; above: " + limit(range.upper_limit, "end") + ")\n";
  }
  for (std::size_t i = model.geometry().warnings.size(); i < model.warnings().size(); ++i) {
    text += "  warning: " + model.warnings()[i] + "\n";
  }
  if (a.json) {
    rackopt::JsonWriter j;
    j.begin_object();
    j.key("ok").value(true);
    j.key("contact_ratio").value(model.geometry().path.contact_ratio);
    j.key("pressure_angle_range").begin_object();
    j.key("lower").value(range.lower);
    j.key("upper").value(range.upper);
    j.key("lower_limit").value(range.lower_limit);
    j.key("upper_limit").value(range.upper_limit);
    j.end_object();
    j.key("warnings").begin_array();
    for (const auto& w : model.warnings()) j.value(w);
    j.end_array();
    j.end_object();
    std::cerr << text;
    std::cout << j.str() << "\n";
  } else {
    std::cout << text << "ok: " << a.file << "\n";
  }
  return kOk;
}

int cmd_stiffness(const Args& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const rackopt::Drive drive = rackopt::load_problem(a.file, a.overrides);
  namespace fs = std::filesystem;
  const fs::path dir = a.out_dir.empty() ? fs::path("out") / fs::path(a.file).stem() : fs::path(a.out_dir);
  const rackopt::FolderLock lock(dir.string());
  report_stale_temporaries(lock);
  const rackopt::MeshStiffnessModel model(drive);
  rackopt::Timings t;
  t.model_ms = ms_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  rackopt::StiffnessCurve curve = model.curve();
  t.curve_ms = ms_since(t1);
  const rackopt::MeshRipple ripple =
      rackopt::mesh_ripple(rackopt::period_stats(model, curve, rackopt::CurveQuantity::kStiffness));
  const rackopt::TransmissionError te =
      rackopt::transmission_error(rackopt::period_stats(model, curve, rackopt::CurveQuantity::kApproach));

  rackopt::throw_if_stop_requested("stiffness");

  const std::string title = (drive.name.empty() ? fs::path(a.file).stem().string() : drive.name);
  const rackopt::WrittenFiles files = rackopt::write_stiffness_files(curve, dir.string(), title);
  // A plot that was not drawn is one of the curve's warnings here: the text
  // and the JSON list the curve's warnings.
  curve.warnings.insert(curve.warnings.end(), files.warnings.begin(), files.warnings.end());
  const std::string csv = files.path_of("stiffness_csv");
  const std::string png = files.path_of("stiffness_png");
  rackopt::throw_if_stop_requested("stiffness");  // the CSV is complete; the plot was not drawn
  t.total_ms = ms_since(t0);

  std::string text = rackopt::geometry_summary(drive, model.geometry()) + rackopt::stiffness_summary(curve) +
                     rackopt::mesh_dynamics_summary(ripple, te);
  text += "  wrote " + csv + "\n";
  text += png.empty() ? "  no plot (see warnings)\n" : "  plot  " + png + "\n";
  for (std::size_t i = model.warnings().size(); i < curve.warnings.size(); ++i) {
    text += "  warning: " + curve.warnings[i] + "\n";
  }
  rackopt::set_immediate_stop_output("");  // our own output follows
  if (a.json) {
    std::cerr << text;
    std::cout << rackopt::stiffness_json(drive, model.geometry(), curve, ripple, te, t, csv, png) << "\n";
  } else {
    std::cout << text;
  }
  return kOk;
}


}  // namespace rackopt::cli
