// Every sample of a problem's full stiffness curve with 17 significant digits
// (the CSV of `rackopt stiffness` keeps 9): for comparing two builds of a
// change that is meant to move results only at rounding or quadrature level.
//
//   ./build/curve_digits problems/X.yaml [key=value ...]
//
// Prints "k k_min k_max k_mean travel_at_min travel_at_max", then one line per
// sample: "s travel stiffness approach local_stiffness" followed by each
// pair's load share and local compliance. bench/compare_curves.py runs two such
// programs over the shipped problems and prints the largest differences.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: curve_digits problem.yaml [key=value ...]\n");
    return 2;
  }
  try {
    const std::vector<std::string> overrides(argv + 2, argv + argc);
    const rackopt::MeshStiffnessModel model(rackopt::load_problem(argv[1], overrides));
    const rackopt::StiffnessCurve c = model.curve();
    std::printf("k %.17g %.17g %.17g %.17g %.17g\n", c.k_min, c.k_max, c.k_mean, c.travel_at_min,
                c.travel_at_max);
    for (const rackopt::MeshState& s : c.samples) {
      std::printf("s %.17g %.17g %.17g %.17g", s.travel, s.stiffness, s.approach, s.local_stiffness);
      for (const rackopt::PairState& p : s.pairs) std::printf(" %.17g %.17g", p.load_share, p.local());
      std::printf("\n");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "curve_digits: %s\n", e.what());
    return 1;
  }
  return 0;
}
