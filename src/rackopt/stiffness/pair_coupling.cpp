#include "rackopt/stiffness/pair_coupling.hpp"

namespace rackopt {

// `fe_calibration --fit coupling tests/data/fe/period.csv`
// (docs/models/fe_calibration.md).
// PAIR_COUPLING_FIT
double pair_coupling_share() { return 0.3526; }

double adjacent_pair_coupling(double foundations_j, double foundations_k) {
  return pair_coupling_share() * 0.5 * (foundations_j + foundations_k);
}

}  // namespace rackopt
