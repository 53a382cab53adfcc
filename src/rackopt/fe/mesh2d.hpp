// A 2-D finite-element mesh of 6-node (quadratic) triangles, the input of
// the CalculiX deck writer (ccx_deck.hpp). Coordinates in metres.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace rackopt::fe {

struct Point2 {
  double x = 0;
  double y = 0;
};

// Node indices are 0-based here (the deck numbers them index + 1).
// A triangle lists its corners counter-clockwise, then the mid-side nodes of
// the edges corner0-corner1, corner1-corner2, corner2-corner0: the node order
// of CalculiX's CPS6 and Gmsh's 6-node triangle alike.
using Triangle6 = std::array<int, 6>;

// A point located in a mesh: the triangle holding it and its barycentric
// (area) coordinates there, weights of corners 0, 1, 2 (summing to 1).
struct MeshLocation {
  int triangle = -1;
  std::array<double, 3> barycentric{};
};

// Nodes, triangles and named node sets (a boundary edge's or a vertex's
// nodes, by the names the mesher was given). Set names are what the deck
// uses: letters, digits and '_' only, at most 60 characters, unique without
// regard to case (CalculiX upper-cases them).
struct Mesh2D {
  std::vector<Point2> nodes;
  std::vector<Triangle6> triangles;
  std::map<std::string, std::vector<int>> node_sets;

  // The set called `name`; throws std::out_of_range naming it and the sets
  // there are when there is none.
  const std::vector<int>& node_set(const std::string& name) const;
  // The node nearest to `p` (ties: the lowest index). Throws on an empty mesh.
  int nearest_node(Point2 p) const;
  // Sum of the triangles' areas (straight-sided: the corners' triangle).
  double area() const;
  // Longest corner-to-corner edge of any triangle (the mesh size h).
  double largest_edge() const;

  // The triangle holding `p`. The triangles are straight-sided (mid-side
  // nodes on the chords, as the mesher makes them), so the barycentric
  // coordinates are the element's exact natural coordinates. A point on an
  // edge shared by two triangles (within 1e-9 of the triangle's size) gets
  // either. Throws std::out_of_range naming the point (in mm) when it lies
  // outside every triangle. A linear search: for a few points per solve.
  MeshLocation locate(Point2 p) const;
  // `field` (one value per node) at `p`, by the 6-node triangle's quadratic
  // shape functions (corners L_i (2 L_i - 1), mid-sides 4 L_i L_j): exact
  // for a field quadratic in x and y. Throws std::invalid_argument when the
  // field's size is not the node count, and as locate() does.
  Point2 interpolate(const std::vector<Point2>& field, Point2 p) const;
  double interpolate(const std::vector<double>& field, Point2 p) const;
};

// Throws std::invalid_argument when `name` is not a valid set name (above).
void check_set_name(const std::string& name);

}  // namespace rackopt::fe
