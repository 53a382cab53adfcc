// What `rackopt check` and `rackopt stiffness` show and write: the geometry
// summary, the stiffness CSV (columns in docs/output.md), the JSON summary and
// the gnuplot script for the plot.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/mesh_ripple.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/transmission_error.hpp"

namespace rackopt {

// Human-readable geometry: radii, path of contact, contact ratio, zones,
// undercut/interference, warnings. Lengths in mm, angles in deg.
std::string geometry_summary(const Drive& drive, const MeshGeometry& geometry);

// ISO 6336-1's single stiffness c' (iso_single_stiffness.hpp) beside this
// model's single pair at the pitch point with a rigid rack body, one line
// (part of geometry_summary).
std::string iso_single_stiffness_line(const Drive& drive, const MeshGeometry& geometry);
// 1 / (the pair's tooth compliances + its contact term at the drive's load)
// at the pitch point [N/m]. Throws as PairCompliance does.
double single_pair_stiffness_at_pitch_point(const Drive& drive, const MeshGeometry& geometry);

// Human-readable stiffness result (MN/m), plus where files went.
std::string stiffness_summary(const StiffnessCurve& curve);

// Human-readable mesh ripple and static transmission error (um) lines.
std::string mesh_dynamics_summary(const MeshRipple& ripple, const TransmissionError& te);

// One row per sample; per-pair columns repeated for slots 0..max_pairs-1.
// SI units throughout (m, N/m, m/N).
std::string stiffness_csv(const StiffnessCurve& curve);

// The same text in pieces of about 64 KiB, each passed to `write` in order:
// what stiffness.csv is written from, so a curve of 150 000 samples is never
// held as one string of 60 MB beside the curve.
void write_stiffness_csv(const StiffnessCurve& curve, const std::function<void(std::string_view piece)>& write);

struct Timings {
  double model_ms = 0;  // geometry + tooth models
  double curve_ms = 0;  // the whole-span curve
  double total_ms = 0;
};

// Exactly one JSON object (SI units): contact_ratio, k_min, k_max, k_mean,
// k_fluctuation, mesh_ripple, transmission_error, zones, warnings, timings, ...
std::string stiffness_json(const Drive& drive, const MeshGeometry& geometry, const StiffnessCurve& curve,
                           const MeshRipple& ripple, const TransmissionError& te, const Timings& timings,
                           const std::string& csv_path, const std::string& plot_path);

// The columns of the stiffness plot in the units it draws, one row per
// sample, space-separated: travel [m] (the CSV's digits, %.9g), stiffness
// and rigid-body stiffness [MN/m], transmission error [um] (each the CSV's
// digits parsed and scaled by 1e6, written to parse back to that double),
// then per pair slot q (0..max_pairs-1) its load share (the CSV's digits), or
// NaN when the slot is not in mesh. Every sample is kept.
std::string stiffness_plot_data(const StiffnessCurve& curve);

// gnuplot script that draws the stiffness plot into `png_name` from
// stiffness_plot_data, inline as a datablock (gnuplot parses 4 + max_pairs
// columns instead of the CSV's 60, once per image, and evaluates no
// expression per point); `csv_name` is named in
// its first line as the table the data comes from.
std::string stiffness_gnuplot(const StiffnessCurve& curve, const std::string& title, const std::string& csv_name,
                              const std::string& png_name);

}  // namespace rackopt
