// Coupling of two adjacent tooth pairs in mesh: a load on one tooth moves
// its loaded neighbour, through the rack body under both teeth and the
// pinion rim, which the pairs in parallel leave out. Against FE mesh
// positions over whole mesh periods (tests/data/fe/period.csv) the pairs in
// parallel are 9.5-12 % too stiff in the double-pair zone while each pair
// alone agrees within 1 %.
//
// The cross compliance of pairs j and k (adjacent teeth) is taken as a
// share of their foundations' compliances, the parts through which one
// tooth's load reaches the other:
//
//   x_jk = kappa (f_j + f_k) / 2,   f = fillet foundation (with its
//                                   calibration) + rack foundation,
//
// kappa, linear in the pressure angle, fitted on the FE periods of the
// shipped drives and of a design spread (docs/models/fe_calibration.md,
// "The pairs' coupling"). Effect `effects.pair_coupling`; the rack beam's
// own coupling (rack_span.hpp) is separate.
#pragma once

#include "rackopt/core/drive.hpp"

namespace rackopt {

// Whether adjacent pairs are coupled: effects.pair_coupling, except with
// rack_span: per_pair (the papers' method, pairs in parallel).
inline bool pairs_coupled(const Effects& effects) {
  return effects.pair_coupling && effects.rack_span != RackSpanModel::kPerPair;
}

// kappa = at_20_deg + per_deg (alpha0 [deg] - 20).
struct PairCouplingShare {
  double at_20_deg = 0;
  double per_deg = 0;
};
PairCouplingShare pair_coupling_fit();

// kappa at the pressure angle alpha0 [rad], dimensionless.
double pair_coupling_share(double pressure_angle);

// x_jk [m/N] from the two pairs' foundation compliances [m/N] at the
// pressure angle alpha0 [rad].
double adjacent_pair_coupling(double foundations_j, double foundations_k, double pressure_angle);

}  // namespace rackopt
