// Pictures of a solved FE mesh position (`rackopt fe --pictures`): the mesh
// and the deformed shape of the pinion and the rack around the contacts, as
// gnuplot scripts with their data inline (render_plot turns them into PNGs).
// Lengths on the axes in mm, in the rack-fixed frame of mesh_placement.hpp.
#pragma once

#include <string>

#include "rackopt/fe/deformed_shape.hpp"

namespace rackopt::fe {

// The part of the plane a picture shows [m]: the theoretical contacts'
// bounding box widened by 2.2 modules each side along the rack and 2 modules
// up and down, which takes in the teeth in contact with their fillets and
// roots, the neighbouring teeth and a strip of the rack body.
struct ShapeWindow {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};
ShapeWindow shape_window(const DeformedShape& shape);

// The largest displacement drawn is this fraction of the module: a tenth of
// a module is well visible beside a tooth (about 2 m thick) and still small
// enough that the deformed teeth keep their shape.
constexpr double kDrawnDisplacementPerModule = 0.1;

// How the deformed picture magnifies the displacements.
struct ShapeScale {
  double largest = 0;  // largest displacement of a node in the window [m]
  double factor = 0;   // drawn displacement / true displacement: kDrawnDisplacementPerModule * m / largest
};
// Throws std::runtime_error when no node in the window moved (largest 0 or
// not finite): there would be nothing to draw.
ShapeScale shape_scale(const DeformedShape& shape, const ShapeWindow& window);

// The mesh: every element edge in the window (pinion blue, rack red), the
// theoretical contacts marked. Writes `png_name` (relative).
std::string mesh_gnuplot(const DeformedShape& shape, const std::string& title, const std::string& png_name);

// The deformed shape: the element edges moved by factor x displacement,
// coloured by the displacement's magnitude, over the undeformed outlines
// (grey); the scale written on the picture. Writes `png_name` (relative).
std::string deformed_gnuplot(const DeformedShape& shape, const std::string& title, const std::string& png_name);

}  // namespace rackopt::fe
