// Hertzian contact compliance of a rack-pinion tooth pair (physics.md 4).
#pragma once

#include "rackopt/core/drive.hpp"

namespace rackopt {

// 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 -> returns E* [Pa].
double effective_modulus(const Material& a, const Material& b);

// Linearised 2-D contact (Yang & Lin): c_h = 2 / (pi b E*), load independent.
double hertz_linear_compliance(double e_star, double face_width);

// Weber & Banaschek (physics.md 4.2): secant compliance delta_H / F for the
// pair force `force` [N], effective radius R' [m] (= s for a rack-pinion
// contact) and distances h1, h2 [m] from the contact to the two tooth centre
// lines. Finite and positive for force > 0; force <= 0 returns the value at a
// small reference load.
double hertz_weber_banaschek_compliance(const Material& a, const Material& b, double face_width,
                                        double force, double effective_radius, double h1, double h2);

}  // namespace rackopt
