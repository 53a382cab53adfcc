// Hertzian contact compliance of a rack-pinion tooth pair (docs/models/tooth.md).
#pragma once

#include "rackopt/core/drive.hpp"

namespace rackopt {

// 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 -> returns E* [Pa].
// Throws InputError for a non-positive modulus or nu outside (-1, 0.5].
double effective_modulus(const Material& a, const Material& b);

// Linearised 2-D contact (Yang & Lin 1987, docs/models/tooth.md): c_h = 2/(pi b E*)
// [m/N], load and curvature independent. Throws InputError for b <= 0 or
// E* <= 0.
double hertz_linear_compliance(double e_star, double face_width);

// The 2-D state the local contact term is written in. The tooth beams use
// E and G, i.e. plane stress, and so does the FE reference, so the mesh
// model uses plane stress; plane strain (a face much wider than the
// teeth are thick, no lateral expansion) is kept for comparison.
enum class ElasticPlane { kStress, kStrain };

// Local contact term of Weber & Banaschek (1953) (docs/models/contact.md),
// generalised to two materials by summing the per-body approaches: the
// approach of the two bodies' points at distances h1, h2 from the contact
// along the load line (where the tooth beams' deflections are taken: the
// tooth centre lines), per unit force.
//   plane stress: delta = F/(pi b) sum_i [2 ln(2 h_i / a) - nu_i] / E_i,
//                 a = sqrt(4 F R'/(pi b E*)), 1/E* = 1/E1 + 1/E2;
//   plane strain: delta = F/(pi b) sum_i (1-nu_i^2)/E_i [2 ln(2 h_i / a) - nu_i/(1-nu_i)],
//                 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
// Returns the secant compliance delta/F [m/N] for the pair force `force` [N],
// effective radius R' [m] (= s for a rack-pinion contact) and distances h1,
// h2 [m]. It falls logarithmically with the force (the strip widens). The
// force is floored at 1 N per metre of face width (so force <= 0 returns the
// value at that tiny reference load: the compliance grows only
// logarithmically as F -> 0, and 0 would give infinity).
// Throws InputError for b, R', h1 or h2 <= 0; DesignError
// "hertz_out_of_range" when the contact half-width is so large that the
// bracket is not positive (a > ~2h: outside the model).
double hertz_weber_banaschek_compliance(const Material& a, const Material& b, double face_width,
                                        double force, double effective_radius, double h1, double h2,
                                        ElasticPlane plane = ElasticPlane::kStress);

}  // namespace rackopt
