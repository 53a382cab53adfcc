// Meshing a plane polygon into 6-node triangles with Gmsh (its C API,
// Debian libgmsh-dev, opened at the first call: gmsh_library.hpp). Only this
// file's .cpp calls Gmsh.
//
// Gmsh keeps one global session (gmshInitialize ... gmshFinalize) that is
// not thread-safe: every call here takes one process-wide mutex and runs a
// whole session inside it (initialize, build, mesh, read back, finalize), so
// calls from several threads are serialized and never see each other's model.
// Nothing else in rackopt may use the Gmsh API while a call runs.
#pragma once

#include <string>
#include <vector>

#include "rackopt/fe/mesh2d.hpp"

namespace rackopt::fe {

// A simple polygon (not self-intersecting; either orientation), straight
// edges. edge_names[i] names edge i (from vertex i to vertex i+1, the last
// one closing to vertex 0): its nodes become node set edge_names[i] ("" = no
// set; the same name on several edges joins them). vertex_names[i] names the
// one-node set of vertex i ("" = none). Either list may be shorter than the
// vertex list (the rest unnamed).
struct Polygon2D {
  std::vector<Point2> vertices;
  std::vector<std::string> edge_names;
  std::vector<std::string> vertex_names;
};

// A disc where the mesh is finer: element size `size` within `radius` of
// `center`, growing linearly to the target size over a further `radius`.
struct Refinement {
  Point2 center;
  double radius = 0;
  double size = 0;
};

// Meshes `polygon` with 6-node triangles of about `target_size` (m),
// finer where `refinements` ask. Mid-side nodes lie on the straight edges.
// Triangles come out counter-clockwise. Throws std::invalid_argument for
// fewer than 3 vertices, a non-positive size or a bad set name, and
// std::runtime_error with Gmsh's message when Gmsh fails, GmshNotFound
// (gmsh_library.hpp) when the Gmsh library cannot be opened.
Mesh2D mesh_polygon(const Polygon2D& polygon, double target_size,
                    const std::vector<Refinement>& refinements = {});

// Meshes the region inside `outer` and outside each of `holes` (simple
// polygons strictly inside `outer`, apart from each other; either
// orientation), as mesh_polygon does; the holes' edge and vertex names make
// node sets as the outer polygon's do. Same errors as mesh_polygon.
Mesh2D mesh_polygon_with_holes(const Polygon2D& outer, const std::vector<Polygon2D>& holes, double target_size,
                               const std::vector<Refinement>& refinements = {});

// The rectangle [x0, x0 + length] x [y0, y0 + height] with edge sets
// "BOTTOM", "RIGHT", "TOP", "LEFT" and corner sets "BOTTOM_LEFT",
// "BOTTOM_RIGHT", "TOP_RIGHT", "TOP_LEFT".
Mesh2D mesh_rectangle(double x0, double y0, double length, double height, double target_size,
                      const std::vector<Refinement>& refinements = {});

}  // namespace rackopt::fe
