// What `rackopt wear` writes: wear along both profiles at snapshot times, the
// life samples, the reliability table, their gnuplot scripts, the JSON
// summary and the readable summary (columns and fields: docs/output.md).
#pragma once

#include <string>

#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt {

// member,fraction_of_life,years,contact_ratio,s_m,position_m,radius_or_height_m,depth_m
std::string wear_profile_csv(const WearLifeResult& nominal);
// sample,<inputs...>,life_years,status,criterion,message
std::string life_samples_csv(const WearReliabilityResult& r);
// t_years,R_fit,R_empirical on a grid spanning the lives plus the requested times
std::string reliability_csv(const Drive& drive, const WearReliabilityResult& r);
// Histogram of the lives in `bins` bins with the chosen fit's pdf scaled to counts:
// bin_left_years,bin_right_years,count,fit_count
std::string life_histogram_csv(const WearReliabilityResult& r, int bins = 30);

// The wear profiles of `nominal` at 25, 50, 75 and 100 % of the life, rack
// and pinion panels. The points are inline, one datablock per member and
// fraction, in the units drawn (mm: the CSV's digits parsed and scaled by
// 1e3, written to parse back to that double), so gnuplot evaluates no
// expression per point (docs/performance.md, "Plots of a small study").
std::string wear_profile_gnuplot(const std::string& title, const WearLifeResult& nominal);
std::string life_histogram_gnuplot(const std::string& title);
std::string reliability_gnuplot(const std::string& title);

std::string wear_summary(const Drive& drive, const WearReliabilityResult& r);

struct WearFiles {
  std::string wear_profile_csv, life_samples_csv, reliability_csv, histogram_csv;
  std::string wear_profile_png, histogram_png, reliability_png;  // "" when not drawn
};
// One JSON object, SI units except the *_years fields: life_cycles,
// life_years, criterion, life_at_R (R -> years), reliability ([{t_years, R}]),
// fit, exact (when available), warnings, timings, files.
std::string wear_json(const Drive& drive, const WearReliabilityResult& r, const WearFiles& files, double total_ms);

}  // namespace rackopt
