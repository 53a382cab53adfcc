// What `rackopt fe` writes and shows of an FeComparison (and what a study's
// `verify: fe` puts in its report): fe.csv, the JSON object of fe.json /
// --json, the gnuplot script of fe_stiffness.png, the summary for people and
// the Markdown table of report.md. Columns and keys: docs/fe.md.
#pragma once

#include <string>

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_comparison.hpp"

namespace rackopt::fe {

// One row per position, SI units in the column names (m, N/m, m/N, s); per
// pair slot 0..slots-1 the pair's teeth, s, the shares FE / analytic /
// difference and the pinion and rack compliances FE / analytic / relative
// error. A slot not in mesh has in_mesh 0 and empty cells; an undefined
// error is an empty cell.
std::string fe_comparison_csv(const FeComparison& c);

// What `--pictures` drew: the position and how the deformed picture
// magnifies the displacements (fe/shape_plot.hpp).
struct FePictures {
  bool asked = false;
  double travel = 0;                // the position drawn [m]
  double displacement_scale = 0;    // drawn / true displacement
  double largest_displacement = 0;  // in the picture's window [m]
};

struct FeFiles {
  std::string csv, json, plot;  // "" = not written (plot: gnuplot missing or failed)
  std::string mesh_png, deformed_png;  // the pictures; "" = not asked for or not drawn
  FePictures pictures;
};

// One JSON object (SI units): ok, problem, name, options {positions, level,
// extended_contact, rack_body_depth, threads}, conventions (the notes),
// pitch, period_start, contact_ratio, positions [{travel, k_fe, k_analytic,
// k_error, fe_force, nodes, elements, times, pairs [...], extended_pairs
// [...], extended_share_fe}], summary {max errors, times, time_ratio},
// analytic_curve [[travel, K]...], files, pictures (null unless asked),
// warnings. Errors that are undefined are null.
std::string fe_comparison_json(const Drive& drive, const FeComparison& c, const FeFiles& files,
                               const std::vector<std::string>& warnings);

// gnuplot script: the analytic K over the period as a line, the FE K at the
// positions as points (data inline); writes `png_name` (relative).
std::string fe_comparison_gnuplot(const FeComparison& c, const std::string& title, const std::string& png_name);

// For people: per position K FE / analytic / error, then the summary (max
// errors in %, times per position and their ratio) and the conventions.
std::string fe_comparison_summary(const FeComparison& c);

// Markdown: the conventions, a table per position (K and per pair shares and
// compliances with errors in %) and the summary lines.
std::string fe_comparison_markdown(const FeComparison& c);

}  // namespace rackopt::fe
