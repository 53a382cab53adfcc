// rackopt dynamics.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>

#include "cli.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/dynamics/drive_dynamics.hpp"
#include "rackopt/output/dynamics_files.hpp"
#include "rackopt/output/folder_lock.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::cli {

int cmd_dynamics(const Args& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const rackopt::Drive drive = rackopt::load_problem(a.file, a.overrides);
  namespace fs = std::filesystem;
  const fs::path dir =
      a.out_dir.empty() ? fs::path("out") / (fs::path(a.file).stem().string() + "_dynamics") : fs::path(a.out_dir);
  const rackopt::FolderLock lock(dir.string());
  report_stale_temporaries(lock);
  const rackopt::MeshStiffnessModel model(drive);
  rackopt::DynamicsRequest request;
  request.speed = a.speed;
  // The response at the operating speed whenever there is one; the sweep and
  // the stability map when asked (or when no speed is known at all).
  request.response_at_speed = a.speed.has_value() || drive.load.speed > 0;
  request.sweep = a.sweep || !request.response_at_speed;
  request.stability = a.stability;
  rackopt::DriveDynamics d = rackopt::analyse_drive_dynamics(drive, model, request);
  rackopt::throw_if_stop_requested("dynamics");

  const std::string title = (drive.name.empty() ? fs::path(a.file).stem().string() : drive.name) + ": dynamics";
  const rackopt::WrittenFiles files = rackopt::write_dynamics_files(d, dir.string(), title);
  d.warnings.insert(d.warnings.end(), files.warnings.begin(), files.warnings.end());
  rackopt::throw_if_stop_requested("dynamics");
  const double total_ms = ms_since(t0);

  std::string text = rackopt::dynamics_summary(d);
  for (const auto& [role, path] : files.listed) text += "  wrote " + path + "\n";
  rackopt::set_immediate_stop_output("");  // our own output follows
  if (a.json) {
    rackopt::JsonWriter j;
    j.begin_object();
    j.key("ok").value(true);
    j.key("natural_frequencies_hz").begin_array();
    for (double f : d.natural_frequencies_hz) j.value(f);
    j.end_array();
    j.key("kv_curve").begin_array();
    for (const rackopt::SweepPoint& p : d.sweep) {
      j.begin_object().key("speed_m_per_s").value(p.speed).key("kv").value(std::max(p.kv_up, p.kv_down)).end_object();
    }
    j.end_array();
    j.key("kv_max").value(d.kv_max);
    j.key("static_mesh_force_N").value(d.static_force);
    j.key("dynamics").raw(rackopt::dynamics_json(d));
    j.key("files").begin_object();
    for (const auto& [role, path] : files.listed) j.key(role).value(path);
    j.end_object();
    j.key("total_ms").value(total_ms);
    j.end_object();
    std::cerr << text;
    std::cout << j.str() << "\n";
  } else {
    std::cout << text;
  }
  return kOk;
}

}  // namespace rackopt::cli
