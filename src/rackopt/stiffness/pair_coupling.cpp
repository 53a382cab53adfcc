#include "rackopt/stiffness/pair_coupling.hpp"

#include <numbers>

namespace rackopt {

// `fe_calibration --fit coupling` on tests/data/fe/period.csv and
// tests/data/fe/spread.csv together (docs/models/fe_calibration.md).
// PAIR_COUPLING_FIT
PairCouplingShare pair_coupling_fit() { return {0.3910, 0.01550}; }

double pair_coupling_share(double pressure_angle) {
  const PairCouplingShare k = pair_coupling_fit();
  return k.at_20_deg + k.per_deg * (pressure_angle * 180 / std::numbers::pi - 20);
}

double adjacent_pair_coupling(double foundations_j, double foundations_k, double pressure_angle) {
  return pair_coupling_share(pressure_angle) * 0.5 * (foundations_j + foundations_k);
}

}  // namespace rackopt
