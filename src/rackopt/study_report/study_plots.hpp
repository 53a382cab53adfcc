// The gnuplot scripts of a study report: the Pareto front over every
// evaluation, the convergence history and the sweep's small multiples. Each
// script reads the report's CSV tables in the output folder and writes
// `<name>.png.tmp` for render_plot (output/plot.hpp) to publish.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "rackopt/study_report/design_tables.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// pareto.png from front.csv (`front`: its layout): one panel for two
// objectives, the three pairwise projections for three, the six in two rows
// for four, with one legend below all panels. Every ok, non-probe
// evaluation of `evaluations_csv` is drawn grey behind the front when that
// file has the needed columns; the chosen point is circled.
std::string pareto_gnuplot(const StudySpec& spec, const DesignTable& front, const std::string& evaluations_csv);

// history.png from history.csv: best feasible `label` so far over
// `evaluations` evaluations, in the metric's display unit.
std::string history_gnuplot(const StudySpec& spec, const std::string& label, std::size_t evaluations);
// history.png of a pareto study from hypervolume.csv: the normalized
// hypervolume of the feasible designs evaluated so far over `evaluations`.
std::string hypervolume_gnuplot(const StudySpec& spec, std::size_t evaluations);

// sweep.png from sweep.csv (`t`: its layout): one panel per (metric,
// variable), at most 6 of each, infeasible points grey behind the feasible.
std::string sweep_gnuplot(const StudySpec& spec, const DesignTable& t, const std::vector<std::string>& labels);

}  // namespace rackopt::study_report
