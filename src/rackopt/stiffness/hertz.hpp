// Hertzian contact compliance of a rack-pinion tooth pair (physics.md 4).
#pragma once

#include "rackopt/core/drive.hpp"

namespace rackopt {

// 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 -> returns E* [Pa].
// Throws InputError for a non-positive modulus or nu outside (-1, 0.5].
double effective_modulus(const Material& a, const Material& b);

// Linearised 2-D contact (Yang & Lin 1987, physics.md 4.1): c_h = 2/(pi b E*)
// [m/N], load and curvature independent. Throws InputError for b <= 0 or
// E* <= 0.
double hertz_linear_compliance(double e_star, double face_width);

// Weber & Banaschek (1953), physics.md 4.2, generalised to two materials by
// summing the per-body approaches:
//   delta = F/(pi b) sum_i (1-nu_i^2)/E_i [2 ln(2 h_i / a) - nu_i/(1-nu_i)],
//   a = sqrt(4 F R'/(pi b E*)),
// which for equal materials is 2F(1-nu^2)/(pi E b)[ln(2h1/a) + ln(2h2/a) - nu/(1-nu)].
// Returns the secant compliance delta/F [m/N] for the pair force `force` [N],
// effective radius R' [m] (= s for a rack-pinion contact) and distances h1, h2
// [m] from the contact to the two tooth centre lines (about the half tooth
// thicknesses at the contact). The force is floored at 1 N per metre of face
// width (so force <= 0 returns the value at that tiny reference load: the
// compliance grows only logarithmically as F -> 0, and 0 would give infinity).
// Throws InputError for b, R', h1 or h2 <= 0; DesignError
// "hertz_out_of_range" when the contact half-width is so large that the
// bracket is not positive (a > ~2h: outside the model).
double hertz_weber_banaschek_compliance(const Material& a, const Material& b, double face_width,
                                        double force, double effective_radius, double h1, double h2);

}  // namespace rackopt
