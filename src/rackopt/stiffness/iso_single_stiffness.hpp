// ISO 6336-1 (method B) single stiffness c' of the rack-pinion pair, printed
// beside the model as the engineer's sanity check
// (docs/models/fe_calibration.md, "Beside ISO 6336-1"). It is an empirical standard value for solid steel
// gears at a working load, not a model of this drive: it knows nothing of
// the rack body, the pinion's rim or the contact's load dependence beyond a
// load factor.
//
//   q' = C1 + C2/z1 + C4 x1 + C5 x1/z1 + C8 x1^2     [mm um/N]
//        (the wheel terms C3/z2, C6 x2, C7 x2/z2, C9 x2^2 vanish for a rack:
//         z2 -> infinity, x2 = 0)
//   C1..C8 = 0.04723, 0.15551, -, -0.00635, -0.11654, -, -, 0.00529
//   c' = (1/q') C_M C_R C_B (E/E_st) [min(1, (F_t/b)/100 N/mm)]^(1/4)  [N/(mm um)]
//   C_M = 0.8, C_R = 1 (solid), C_B = [1 + 0.5 (1.2 - h_fP/m)] [1 - 0.02 (20 deg - a0)],
//   E = 2 E1 E2/(E1 + E2), E_st = 206 GPa, F_t the nominal tangential force.
#pragma once

#include "rackopt/core/drive.hpp"

namespace rackopt {

struct IsoSingleStiffness {
  double q_prime = 0;       // minimum flexibility of a tooth pair [mm um/N]
  double c_theoretical = 0; // 1/q' [N/(mm um)]
  double basic_rack_factor = 0;   // C_B
  double load_factor = 1;   // ((F_t/b)/100)^(1/4), 1 at or above 100 N/mm
  double c_prime = 0;       // [N/(mm um)]
  double stiffness = 0;     // c' b along the line of action [N/m]
};

// Throws InputError for non-positive width, modulus or teeth.
IsoSingleStiffness iso_single_stiffness(const Drive& drive);

}  // namespace rackopt
