// Point location and quadratic interpolation on a Mesh2D: a field that
// 6-node triangles hold exactly (any quadratic in x and y) must come back
// exactly anywhere, and a point off the mesh is an error.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "rackopt/fe/gmsh_mesher.hpp"

namespace rackopt::fe {
namespace {

Point2 quadratic_field(Point2 p) {
  const double x = p.x * 100, y = p.y * 100;  // order-one numbers on the cm-sized mesh
  return {1 + 2 * x - 3 * y + 0.5 * x * x - 1.5 * x * y + 2.5 * y * y, -4 + x * y - 2 * y * y + 0.25 * x};
}

// An L-shaped plate with a notch, so the search crosses a non-convex outline.
Mesh2D l_plate() {
  Polygon2D p;
  p.vertices = {{0, 0}, {0.03, 0}, {0.03, 0.01}, {0.012, 0.01}, {0.012, 0.025}, {0, 0.025}};
  return mesh_polygon(p, 0.003);
}

TEST(MeshInterpolation, QuadraticFieldIsReproducedExactly) {
  const Mesh2D m = l_plate();
  std::vector<Point2> field;
  for (const Point2& n : m.nodes) field.push_back(quadratic_field(n));
  std::vector<double> first;
  for (const Point2& v : field) first.push_back(v.x);
  for (const Point2 p : {Point2{0.001, 0.001}, Point2{0.0213, 0.0071}, Point2{0.005, 0.0234}, Point2{0.0119, 0.0121},
                         Point2{0.029999, 0.005}, Point2{0.0, 0.0125}}) {
    const Point2 exact = quadratic_field(p);
    const Point2 got = m.interpolate(field, p);
    EXPECT_NEAR(got.x, exact.x, 1e-11) << p.x << " " << p.y;
    EXPECT_NEAR(got.y, exact.y, 1e-11) << p.x << " " << p.y;
    EXPECT_NEAR(m.interpolate(first, p), exact.x, 1e-11);
  }
  // A linear field is not special-cased: the located triangle holds the point.
  const Point2 p{0.0213, 0.0071};
  const MeshLocation at = m.locate(p);
  ASSERT_GE(at.triangle, 0);
  double x = 0, y = 0, sum = 0;
  for (int k = 0; k < 3; ++k) {
    EXPECT_GE(at.barycentric[k], -1e-12);
    x += at.barycentric[k] * m.nodes[m.triangles[at.triangle][k]].x;
    y += at.barycentric[k] * m.nodes[m.triangles[at.triangle][k]].y;
    sum += at.barycentric[k];
  }
  EXPECT_NEAR(sum, 1, 1e-12);
  EXPECT_NEAR(x, p.x, 1e-15);
  EXPECT_NEAR(y, p.y, 1e-15);
  // At a node the interpolant is the nodal value.
  const int node = m.nearest_node({0.02, 0.005});
  EXPECT_NEAR(m.interpolate(field, m.nodes[node]).y, field[node].y, 1e-12);
}

TEST(MeshInterpolation, PointOutsideTheMeshIsAnError) {
  const Mesh2D m = l_plate();
  std::vector<Point2> field(m.nodes.size());
  EXPECT_THROW(m.locate({0.02, 0.02}), std::out_of_range);  // in the notch
  EXPECT_THROW(m.interpolate(field, {-0.001, 0.005}), std::out_of_range);
  try {
    m.locate({0.02, 0.02});
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("(20, 20) mm is outside the mesh"), std::string::npos) << e.what();
  }
  EXPECT_THROW(m.interpolate(std::vector<Point2>(3), {0.001, 0.001}), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt::fe
