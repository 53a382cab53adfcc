// The FE pipeline (Gmsh mesh, CalculiX CPS6 solve, .dat read back) against
// closed forms of 2-D elasticity, Timoshenko & Goodier, Theory of
// Elasticity (3rd ed.): a plate in tension (plane stress vs plane strain),
// the end-loaded cantilever (section 21), the uniformly loaded simply
// supported beam (section 22), and the observed order of convergence.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "fe_test_support.hpp"
#include "rackopt/fe/ccx_deck.hpp"
#include "rackopt/fe/plane_stress_solve.hpp"

namespace rackopt::fe {
namespace {

using testing::Cantilever;
using testing::kE;
using testing::kNu;
using testing::SimplySupportedBeam;

struct Timed {
  PlaneStressResult result;
  double seconds = 0;
};

Timed timed_solve(const PlaneStressModel& m, double slice = 0) {
  const auto t0 = std::chrono::steady_clock::now();
  Timed t{solve_plane_stress(m, {}, slice), 0};
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return t;
}

// A plate stretched by sigma along x, free to contract in y: plane stress
// gives u = sigma L / E and v = -nu sigma H / E exactly (the quadratic
// elements reproduce the linear field); plane strain would give
// (1 - nu^2) and nu (1 + nu) times those, 9 % and 30 % off at nu = 0.3.
TEST(FeClosedForm, PlateInTensionIsPlaneStress) {
  const double L = 0.04, H = 0.02, sigma = 100e6;
  PlaneStressModel m;
  m.mesh = mesh_rectangle(0, 0, L, H, H / 3);
  m.youngs_modulus = kE;
  m.poisson_ratio = kNu;
  fix_node_set(m, "LEFT", 1);
  fix_node_set(m, "BOTTOM_LEFT", 2);
  m.loads = edge_traction_loads(m.mesh, "RIGHT", [&](Point2) { return Point2{sigma, 0}; });
  const PlaneStressResult r = solve_plane_stress(m);
  const Point2 corner = r.displacement[m.mesh.node_set("TOP_RIGHT").at(0)];
  const double u_stress = sigma * L / kE, v_stress = -kNu * sigma * H / kE;
  EXPECT_NEAR(corner.x, u_stress, 1e-5 * u_stress);
  EXPECT_NEAR(corner.y, v_stress, 1e-5 * std::abs(v_stress));
  EXPECT_GT(std::abs(corner.x - u_stress * (1 - kNu * kNu)), 0.05 * u_stress);  // not plane strain
  EXPECT_GT(std::abs(corner.y - v_stress * (1 + kNu)), 0.2 * std::abs(v_stress));
  // Reactions per unit thickness: the left edge carries sigma H.
  EXPECT_NEAR(r.total_reaction.x, -sigma * H, 1e-5 * sigma * H);
  EXPECT_NEAR(r.total_reaction.y, 0, 1e-6 * sigma * H);
}

TEST(FeClosedForm, CantileverTipDeflectionAndConvergence) {
  const Cantilever beam;
  const double exact = beam.tip_deflection();
  // Coarse levels: the finest one's error stays above the 7 significant
  // digits of the .dat output (relative resolution 4e-7 here).
  double sizes[3] = {2 * beam.c, beam.c, beam.c / 2};
  double errors[3] = {};
  double h[3] = {};
  for (int k = 0; k < 3; ++k) {
    const PlaneStressModel m = beam.model(sizes[k]);
    const Timed t = timed_solve(m);
    const int tip = m.mesh.node_set("TIP").at(0);
    errors[k] = std::abs(t.result.displacement[tip].y - exact) / exact;
    h[k] = m.mesh.largest_edge();
    std::printf("cantilever size %.4g m (largest edge %.4g m): %zu triangles, %zu nodes, tip %.7e m (exact %.7e), error %.3e, %.2f s\n",
                sizes[k], h[k], m.mesh.triangles.size(), m.mesh.nodes.size(), t.result.displacement[tip].y, exact, errors[k],
                t.seconds);
    // The root carries the whole end load.
    EXPECT_NEAR(t.result.total_reaction.y, -beam.load, 1e-4 * beam.load);
  }
  EXPECT_LT(errors[2], 0.005);
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_LT(errors[2], errors[1]);
  const double order_coarse = std::log(errors[0] / errors[1]) / std::log(sizes[0] / sizes[1]);
  const double order_fine = std::log(errors[1] / errors[2]) / std::log(sizes[1] / sizes[2]);
  std::printf("cantilever observed order %.2f (levels 1-2), %.2f (levels 2-3)\n", order_coarse, order_fine);
  // Quadratic elements: displacement error O(h^3) in the L2 norm, a
  // point value of this smooth solution at least that (we see about 4).
  EXPECT_GT(order_coarse, 2.5);
  EXPECT_GT(order_fine, 2.5);
}

TEST(FeClosedForm, SimplySupportedBeamCentreDeflection) {
  const SimplySupportedBeam beam;
  const double exact = beam.centre_deflection();
  const double sizes[3] = {2 * beam.c, beam.c, beam.c / 2};
  double errors[3] = {};
  for (int k = 0; k < 3; ++k) {
    const PlaneStressModel m = beam.model(sizes[k]);
    const Timed t = timed_solve(m);
    const double delta = -t.result.displacement[m.mesh.node_set("CENTRE").at(0)].y;
    errors[k] = std::abs(delta - exact) / exact;
    std::printf("simply supported size %.4g m: %zu triangles, %zu nodes, centre %.7e m (exact %.7e), error %.3e, %.2f s\n",
                sizes[k], m.mesh.triangles.size(), m.mesh.nodes.size(), delta, exact, errors[k], t.seconds);
    // The loads are in equilibrium by themselves: the point support carries nothing.
    EXPECT_NEAR(t.result.total_reaction.y, 0, 1e-4 * beam.load * beam.half_span);
  }
  EXPECT_LT(errors[2], 0.005);
  const double order = std::log(errors[0] / errors[2]) / std::log(sizes[0] / sizes[2]);
  std::printf("simply supported observed order %.2f (levels 1-3)\n", order);
  EXPECT_GT(order, 2.5);
}

// The trap of CalculiX's 2-D elements: a slice thick compared with the depth
// suppresses anticlastic bending and comes out stiffer than plane stress.
// The default slice (1e-3 of the part's size) is thin enough: ten times
// thinner changes nothing that the .dat's 7 digits show.
TEST(FeClosedForm, DefaultSliceIsThinAndAThickSliceIsTooStiff) {
  const Cantilever beam;
  const PlaneStressModel m = beam.model(beam.c / 2);
  const int tip = m.mesh.node_set("TIP").at(0);
  const double t_default = slice_thickness_for(m.mesh);
  const double exact = beam.tip_deflection();
  double thin = 0, thinner = 0, thick = 0;
  for (const double factor : {0.1, 1.0, 10.0, 100.0, 1000.0}) {
    const double t = factor * t_default;
    const double v = solve_plane_stress(m, {}, t).displacement[tip].y;
    std::printf("cantilever tip with slice %.3g m (%.3g x depth): %.7e m, %+.4f %% from plane stress\n", t,
                t / (2 * beam.c), v, 100 * (v / exact - 1));
    if (factor == 0.1) thinner = v;
    if (factor == 1.0) thin = v;
    if (factor == 1000.0) thick = v;
  }
  EXPECT_NEAR(thin, thinner, 2e-6 * exact);
  EXPECT_LT(thick, thin * 0.95);
}

}  // namespace
}  // namespace rackopt::fe
