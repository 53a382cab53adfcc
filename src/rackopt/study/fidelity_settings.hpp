// The fidelity knobs a study's models ran with, as the report lists them
// (docs/accuracy.md measures what each costs and buys).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/study/study_spec.hpp"

namespace rackopt::study {

// (setting, value as text) for `drive` (the best or the start design) under
// the spec's metric options: the stiffness quadrature and travel sampling
// always; the wear profile and block settings when the problem has a wear
// section; the life-at-R settings in effect (samples, seed, sampling,
// bootstrap, life table, exact quantile) when a metric asks for a life at R.
std::vector<std::pair<std::string, std::string>> fidelity_settings(const Drive& drive, const StudySpec& spec);

}  // namespace rackopt::study
