// From many feasible evaluations to a front of a requested size: the
// non-dominated ones, near-duplicates dropped, thinned by crowding so that
// the kept points spread over the whole front (its extremes always stay).
#pragma once

#include <cstddef>
#include <vector>

#include "rackopt/solvers/pareto.hpp"

namespace rackopt::solvers {

// The rule of select_front on bare vectors (minimized objectives, all of one
// size): the indices into `vectors` of the kept points, sorted by their
// vectors (objective 0, then 1, ...; the earlier index on ties).
std::vector<std::size_t> select_front_indices(const std::vector<std::vector<double>>& vectors, std::size_t points,
                                              double duplicate_tolerance);

// `feasible` holds feasible points of one problem (all objectives finite,
// minimized). Returns a ParetoResult whose `front` is
//   1. the non-dominated points, earliest first among equal vectors;
//   2. without near-duplicates: a point whose every objective is within
//      duplicate_tolerance * (range of that objective over step 1) of a kept
//      one is dropped (the earlier stays);
//   3. at most `points` of them: while there are more, the point with the
//      smallest crowding distance (NSGA-II's, on objectives normalized by
//      their range; the extremes of each objective count as infinitely far)
//      is removed, the later one on ties, and the distances recomputed;
// sorted by objective 0, then 1, ...; `ideal` and `nadir` over the front.
// Nothing else of the result is set. points >= 2.
ParetoResult select_front(std::vector<ParetoPoint> feasible, std::size_t points, double duplicate_tolerance);

// NSGA-II's crowding distance of each vector of `front` (minimized
// objectives; every vector the same size): the sum over objectives of the
// normalized gap between its two neighbours in that objective; +inf for the
// first and last in any objective. All +inf for fronts of 2 or fewer.
std::vector<double> crowding_distances(const std::vector<std::vector<double>>& front);

}  // namespace rackopt::solvers
