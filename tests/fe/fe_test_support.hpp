// Shared by the FE tests: the closed-form problems of Timoshenko & Goodier,
// Theory of Elasticity (3rd ed., 1970), built as plane-stress models.
#pragma once

#include <cmath>

#include "rackopt/fe/edge_loads.hpp"
#include "rackopt/fe/gmsh_mesher.hpp"
#include "rackopt/fe/plane_stress_model.hpp"

namespace rackopt::fe::testing {

constexpr double kE = 210e9;
constexpr double kNu = 0.3;

// Cantilever of depth 2c and length L (x from the loaded end 0 to the root
// L, y in [-c, c]), end load P (N/m) as the parabolic shear of T&G section 21:
//   sigma_x = -P x y / I, sigma_y = 0, tau_xy = -P (c^2 - y^2) / (2 I),
// I = 2 c^3 / 3. The root's nodes are held at the exact displacements of
// that solution with the "vertical element at the root centroid fixed"
// constants (u = v = du/dy = 0 at (L, 0)), so the FE problem has the exact
// solution below and the tip deflection (of the axis, at (0, 0)) is
//   delta = P L^3 / (3 E I) + P c^2 L / (2 I G).
struct Cantilever {
  double c = 0.01, length = 0.1, load = 1e5;  // m, m, N/m
  double inertia() const { return 2 * c * c * c / 3; }
  double shear_modulus() const { return kE / (2 * (1 + kNu)); }
  double tip_deflection() const {
    return load * length * length * length / (3 * kE * inertia()) +
           load * c * c * length / (2 * inertia() * shear_modulus());
  }
  Point2 exact_displacement(Point2 p) const {
    const double P = load, I = inertia(), G = shear_modulus(), L = length, x = p.x, y = p.y;
    const double e = P * L * L / (2 * kE * I);
    const double d = -P * L * L / (2 * kE * I) - P * c * c / (2 * I * G);
    const double h = tip_deflection();
    return {-P * x * x * y / (2 * kE * I) - kNu * P * y * y * y / (6 * kE * I) + P * y * y * y / (6 * I * G) + e * y,
            kNu * P * x * y * y / (2 * kE * I) + P * x * x * x / (6 * kE * I) + d * x + h};
  }
  PlaneStressModel model(double size) const {
    Polygon2D p;
    p.vertices = {{0, -c}, {length, -c}, {length, 0}, {length, c}, {0, c}, {0, 0}};
    p.edge_names = {"", "ROOT", "ROOT", "", "FREE_END", "FREE_END"};
    p.vertex_names = {"", "", "", "", "", "TIP"};
    PlaneStressModel m;
    m.mesh = mesh_polygon(p, size);
    m.youngs_modulus = kE;
    m.poisson_ratio = kNu;
    for (int n : m.mesh.node_set("ROOT")) {
      const Point2 u = exact_displacement(m.mesh.nodes[n]);
      m.supports.push_back({n, 1, u.x});
      m.supports.push_back({n, 2, u.y});
    }
    const double P = load, I = inertia(), cc = c;
    m.loads = edge_traction_loads(m.mesh, "FREE_END", [=](Point2 q) {
      return Point2{0, P * (cc * cc - q.y * q.y) / (2 * I)};  // -tau_xy on the face whose normal is -x
    });
    return m;
  }
};

// Simply supported beam of span 2l and depth 2c under a uniform load q (N/m
// per metre of length and of thickness) on its top, T&G section 22, half of
// it by symmetry (x in [0, l], u = 0 on x = 0). The end x = l carries the
// exact tractions (the parabolic shear reaction and the self-equilibrated
// sigma_x = -(q/I)(y^3/3 - c^2 y/5)), so only rigid motion needs a support:
// v = 0 at the end's axis point (l, 0), which then carries no force. The
// deflection of the centre (0, 0) below the ends' axis is
//   delta = 5 q l^4 / (24 E I) [1 + (12/5) (c^2/l^2) (4/5 + nu/2)].
struct SimplySupportedBeam {
  double c = 0.01, half_span = 0.1, load = 1e6;  // m, m, N/m^2
  double inertia() const { return 2 * c * c * c / 3; }
  double centre_deflection() const {
    const double l = half_span;
    return 5 * load * l * l * l * l / (24 * kE * inertia()) * (1 + 12.0 / 5 * c * c / (l * l) * (0.8 + kNu / 2));
  }
  PlaneStressModel model(double size) const {
    const double l = half_span;
    Polygon2D p;
    p.vertices = {{0, -c}, {l, -c}, {l, 0}, {l, c}, {0, c}, {0, 0}};
    p.edge_names = {"", "END", "END", "TOP", "SYMMETRY", "SYMMETRY"};
    p.vertex_names = {"", "", "END_AXIS", "", "", "CENTRE"};
    PlaneStressModel m;
    m.mesh = mesh_polygon(p, size);
    m.youngs_modulus = kE;
    m.poisson_ratio = kNu;
    fix_node_set(m, "SYMMETRY", 1);
    fix_node_set(m, "END_AXIS", 2);
    const double q = load, I = inertia(), cc = c;
    m.loads = edge_traction_loads(m.mesh, "TOP", [=](Point2) { return Point2{0, -q}; });
    const std::vector<NodeLoad> end = edge_traction_loads(m.mesh, "END", [=](Point2 r) {
      const double y = r.y;
      return Point2{-(q / I) * (y * y * y / 3 - cc * cc * y / 5), q / (2 * I) * l * (cc * cc - y * y)};
    });
    m.loads.insert(m.loads.end(), end.begin(), end.end());
    return m;
  }
};

}  // namespace rackopt::fe::testing
