// rackopt check / rackopt stiffness.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/period_stats.hpp"

namespace rackopt::cli {

int cmd_check(const Args& a) {
  const rackopt::Drive drive = rackopt::load_problem(a.file, a.overrides);
  const rackopt::MeshStiffnessModel model(drive);
  std::string text = rackopt::geometry_summary(drive, model.geometry());
  for (std::size_t i = model.geometry().warnings.size(); i < model.warnings().size(); ++i) {
    text += "  warning: " + model.warnings()[i] + "\n";
  }
  if (a.json) {
    rackopt::JsonWriter j;
    j.begin_object();
    j.key("ok").value(true);
    j.key("contact_ratio").value(model.geometry().path.contact_ratio);
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

  namespace fs = std::filesystem;
  fs::path dir = a.out_dir.empty() ? fs::path("out") / fs::path(a.file).stem() : fs::path(a.out_dir);
  const fs::path csv = dir / "stiffness.csv";
  rackopt::write_file_atomic(csv.string(), rackopt::stiffness_csv(curve));
  const std::string title = (drive.name.empty() ? fs::path(a.file).stem().string() : drive.name);
  rackopt::write_file_atomic((dir / "stiffness.gp").string(),
                             rackopt::stiffness_gnuplot(curve, title, "stiffness.csv", "stiffness.png.tmp"));
  const std::string png = render_plot(dir, "stiffness.gp", "stiffness.png", curve.warnings);
  t.total_ms = ms_since(t0);

  std::string text = rackopt::geometry_summary(drive, model.geometry()) + rackopt::stiffness_summary(curve) +
                     rackopt::mesh_dynamics_summary(ripple, te);
  text += "  wrote " + csv.string() + "\n";
  text += png.empty() ? "  no plot (see warnings)\n" : "  plot  " + png + "\n";
  for (std::size_t i = model.warnings().size(); i < curve.warnings.size(); ++i) {
    text += "  warning: " + curve.warnings[i] + "\n";
  }
  if (a.json) {
    std::cerr << text;
    std::cout << rackopt::stiffness_json(drive, model.geometry(), curve, ripple, te, t, csv.string(), png) << "\n";
  } else {
    std::cout << text;
  }
  return kOk;
}


}  // namespace rackopt::cli
