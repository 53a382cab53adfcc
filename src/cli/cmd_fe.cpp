// rackopt fe: the analytic mesh model against the FE reference at N travel
// positions over one mesh period (rackopt/fe/fe_comparison.hpp, docs/fe.md).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/progress_bar.hpp"
#include "rackopt/fe/ccx_runner.hpp"
#include "rackopt/fe/gmsh_library.hpp"
#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/fe/fe_comparison_report.hpp"
#include "rackopt/fe/shape_plot.hpp"
#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/folder_lock.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::cli {
namespace {

// --pictures: the mesh and the deformed shape of the first position. It lies
// p/(2N) after a pair enters mesh, in the multi-pair zone for a contact
// ratio above 1 + 1/(2N) (docs/fe.md, "Pictures"), so one picture shows the
// load shared between pairs and the refinement at every contact; the meshes
// of the other positions follow the same rules.
void draw_pictures(const fe::FeComparison& c, const std::string& title, const std::string& dir, fe::FeFiles& files,
                   std::vector<std::string>& warnings) {
  if (c.rows.empty() || !c.rows.front().shape) {
    warnings.push_back("no FE shape came back from the first position: no pictures");
    return;
  }
  const fe::DeformedShape& shape = *c.rows.front().shape;
  fe::ShapeScale scale;
  try {
    scale = fe::shape_scale(shape, fe::shape_window(shape));
  } catch (const std::runtime_error& e) {  // nothing moved in view: a picture is a convenience, not a result
    warnings.push_back(std::string("no pictures: ") + e.what());
    return;
  }
  files.pictures.asked = true;
  files.pictures.travel = shape.travel;
  files.pictures.displacement_scale = scale.factor;
  files.pictures.largest_displacement = scale.largest;
  namespace fs = std::filesystem;
  write_file_atomic((fs::path(dir) / "fe_mesh.gp").string(), fe::mesh_gnuplot(shape, title, "fe_mesh.png.tmp"));
  files.mesh_png = render_plot(dir, "fe_mesh.gp", "fe_mesh.png", warnings);
  write_file_atomic((fs::path(dir) / "fe_deformed.gp").string(),
                    fe::deformed_gnuplot(shape, title, "fe_deformed.png.tmp"));
  files.deformed_png = render_plot(dir, "fe_deformed.gp", "fe_deformed.png", warnings);
}

}  // namespace

int cmd_fe(const Args& a) {
  const Drive drive = load_problem(a.file, a.overrides);
  fe::FeComparisonOptions opt;
  opt.positions = a.positions > 0 ? a.positions : 4;
  opt.fe.level = a.level >= 0 ? a.level : 0;
  opt.fe.extended_contact = a.extended_contact;
  opt.fe.keep_shape = a.pictures;
  opt.fe.rack_on_supports = a.rack_supports;
  opt.threads = a.threads > 0 ? static_cast<unsigned>(a.threads) : 0u;
  opt.stop = [] { return stop_requested(); };

  // Checked before the output folder is made, so that an impossible design
  // or a missing solver leaves nothing behind.
  std::vector<std::string> warnings = MeshStiffnessModel(fe::fe_reference_drive(drive)).warnings();
  (void)fe::find_ccx(opt.fe.ccx);
  (void)fe::gmsh_api();

  namespace fs = std::filesystem;
  const fs::path dir = a.out_dir.empty() ? fs::path("out") / (fs::path(a.file).stem().string() + "_fe")
                                         : fs::path(a.out_dir);
  const FolderLock lock(dir.string());  // before the long part: a folder in use is refused at once
  report_stale_temporaries(lock);
  std::cerr << "rackopt: FE at " << opt.positions << " position" << (opt.positions == 1 ? "" : "s") << ", level "
            << opt.fe.level << " (mesh-position and single-tooth solves with ccx)...\n";
  ProgressBar bar(0, "FE solves");
  opt.progress = [&](std::size_t done, std::size_t total) {
    bar.update(static_cast<long>(done), static_cast<long>(total), "");
  };
  // Nothing is written before every solve has ended: a failure or Ctrl-C
  // leaves no partial result.
  const fe::FeComparison c = fe::compare_with_fe(drive, opt);
  bar.finish(true);  // finish the progress line before printing
  throw_if_stop_requested("fe");

  const std::string title = drive.name.empty() ? fs::path(a.file).stem().string() : drive.name;
  fe::FeFiles files;
  files.csv = (dir / "fe.csv").string();
  write_file_atomic(files.csv, fe::fe_comparison_csv(c));
  write_file_atomic((dir / "fe_stiffness.gp").string(), fe::fe_comparison_gnuplot(c, title, "fe_stiffness.png.tmp"));
  files.plot = render_plot(dir.string(), "fe_stiffness.gp", "fe_stiffness.png", warnings);
  if (a.pictures) draw_pictures(c, title, dir.string(), files, warnings);
  files.json = (dir / "fe.json").string();
  const std::string json = fe::fe_comparison_json(drive, c, files, warnings);
  write_file_atomic(files.json, json + "\n");
  throw_if_stop_requested("fe");  // the tables are complete; the plot may not have been drawn

  std::string text = title + "\n" + fe::fe_comparison_summary(c);
  text += "  wrote " + files.csv + ", " + files.json + "\n";
  text += files.plot.empty() ? "  no plot (see warnings)\n" : "  plot  " + files.plot + "\n";
  if (a.pictures) {
    text += files.mesh_png.empty() ? "  no mesh picture (see warnings)\n" : "  mesh  " + files.mesh_png + "\n";
    text += files.deformed_png.empty()
                ? "  no deformed-shape picture (see warnings)\n"
                : "  deformed shape " + files.deformed_png + " (displacements x " +
                      std::to_string(static_cast<long long>(files.pictures.displacement_scale + 0.5)) + ")\n";
  }
  for (const std::string& w : warnings) text += "  warning: " + w + "\n";
  set_immediate_stop_output("");  // our own output follows
  if (a.json) {
    std::cerr << text;
    std::cout << json << "\n";
  } else {
    std::cout << text;
  }
  return kOk;
}

}  // namespace rackopt::cli
