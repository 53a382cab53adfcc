// Plausibility of a life at reliability R against the design's nominal life.
//
// For R >= 0.5 the life at R is a life that at least half of the built drives
// exceed. Above the nominal (deterministic) life of the design it says that
// the random inputs describe a better drive than the design itself: typically
// an absolute distribution that does not follow the design (a coefficient or
// a contact ratio fixed while the design moved) or a favourable shift. That
// is worth a warning, not an error: a deliberately favourable scatter is
// possible (docs/models/reliability.md, "Scatter that follows the design").
#pragma once

#include <optional>
#include <string>

namespace rackopt {

// The warning text when `life_years` (the life at reliability R, or for a
// sampled result the lower end of its confidence interval, so that sampling
// noise around a median-1 scatter does not trigger it) exceeds
// `nominal_years` by more than 1e-6 relative, for R >= 0.5; nullopt
// otherwise (and when the nominal life is not positive). `how` names where the
// life at R came from ("exact quantile", "Monte Carlo fit", ...).
std::optional<std::string> life_at_R_above_nominal(double R, double life_years, double nominal_years,
                                                   const std::string& how);

}  // namespace rackopt
