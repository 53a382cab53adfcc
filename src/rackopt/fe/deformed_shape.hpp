// The FE meshes of a solved mesh position and their nodal displacements at
// the last load step, in the rack-fixed frame of mesh_placement.hpp: what
// `rackopt fe --pictures` draws (fe/shape_plot.hpp) and what shows that the
// bodies move the way the load drives them.
#pragma once

#include <string>
#include <vector>

#include "rackopt/fe/ccx_contact_deck.hpp"
#include "rackopt/fe/mesh2d.hpp"
#include "rackopt/fe/mesh_placement.hpp"

namespace rackopt::fe {

struct ShapeBody {
  std::string name;                  // "pinion" or "rack"
  Mesh2D mesh;                       // node sets as gear_bodies names them (BORE, T<k>_FLANK_L, BASE, ...)
  std::vector<Point2> displacement;  // per node, at the last step [m]
};

struct DeformedShape {
  double travel = 0;         // X [m]
  double module = 0;         // m [m]: the pictures' length scale
  int level = 0;             // FE refinement level
  Point2 pinion_centre;      // O [m]
  double hub_rotation = 0;   // theta of the last step, counter-clockwise [rad]
  std::vector<ShapeBody> bodies;       // the pinion, then the rack
  std::vector<FlankContact> contacts;  // the flanks in contact as placed (theoretical first)
};

// The shape of a solved mesh position: `model`'s bodies 0 (pinion) and 1
// (rack), `last` the result of its last step read with
// model.print_displacements. Throws std::invalid_argument when the model has
// not two bodies or the displacements do not match their meshes.
DeformedShape make_deformed_shape(const ContactModel& model, const ContactStepResult& last,
                                  const MeshPlacement& placement, double module, int level, double hub_rotation);

}  // namespace rackopt::fe
