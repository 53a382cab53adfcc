// Weights that turn the pair loads at the sampled mesh positions into the
// load a flank point sees (docs/models/wear.md, "Load seen by a point").
//
// The pair load along the path of contact is piecewise linear between load
// nodes: node k sits at LOA coordinate c[k], and the nodes are grouped into
// intervals (one pair over one zone), each a list of node indices with
// non-decreasing c. A point's load is a weighted sum over nodes,
//   <w> = sum_k val[k] P[idx[k]],
// with the weights appended to (idx, val) by one of:
//   * pointwise_weights: the load of the pair whose contact is at c (linear
//     between the two nodes around it; the first interval and segment that
//     hold c win, so a zone transition takes its left limit);
//   * band_weights: the elliptic-pressure (semicircle) weighted mean of the
//     load over the band [c - L, c + L], zero outside the path, exact for the
//     piecewise-linear load.
//
// Both visit only the segments that can hold the point or meet the band: a
// binary search finds the first one, the walk stops at the first segment past
// it. The weights are those of a visit of every segment of every interval, bit
// for bit (the skipped segments contribute nothing; tests/wear/band_weights_test.cpp
// compares with that full visit), at O(log M + band) cost instead of O(M) per
// point for M nodes: with 240 profile points this was most of a wear life.
//
// Example:
//   std::vector<int> idx; std::vector<double> val;
//   band_weights(node_c, intervals, s_i, L_i, idx, val);   // point i's weights
#pragma once

#include <vector>

namespace rackopt {

using LoadIntervals = std::vector<std::vector<int>>;

// True when every interval's node coordinates are non-decreasing (the
// precondition of both functions below).
bool load_intervals_sorted(const std::vector<double>& node_c, const LoadIntervals& intervals);

// Appends the two weights (1 - t, t) of the first segment [c_a, c_b], c_b > c_a,
// with c_a <= c <= c_b; nothing when no segment holds c.
void pointwise_weights(const std::vector<double>& node_c, const LoadIntervals& intervals, double c,
                       std::vector<int>& idx, std::vector<double>& val);

// Appends the weights of the band of half-length L > 0 around c. A node shared
// by two consecutive segments of one interval gets one merged weight.
void band_weights(const std::vector<double>& node_c, const LoadIntervals& intervals, double c, double L,
                  std::vector<int>& idx, std::vector<double>& val);

}  // namespace rackopt
