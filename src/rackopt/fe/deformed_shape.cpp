#include "rackopt/fe/deformed_shape.hpp"

#include <stdexcept>

namespace rackopt::fe {

DeformedShape make_deformed_shape(const ContactModel& model, const ContactStepResult& last,
                                  const MeshPlacement& placement, double module, int level, double hub_rotation) {
  if (model.bodies.size() != 2 || last.displacements.size() != 2) {
    throw std::invalid_argument("deformed shape: needs the pinion and the rack with their displacements");
  }
  DeformedShape s;
  s.travel = placement.travel;
  s.module = module;
  s.level = level;
  s.pinion_centre = placement.pinion_centre;
  s.hub_rotation = hub_rotation;
  s.contacts = placement.contacts;
  const char* names[2] = {"pinion", "rack"};
  for (std::size_t b = 0; b < 2; ++b) {
    if (last.displacements[b].size() != model.bodies[b].mesh.nodes.size()) {
      throw std::invalid_argument("deformed shape: displacements of the " + std::string(names[b]) +
                                  " do not match its mesh");
    }
    s.bodies.push_back({names[b], model.bodies[b].mesh, last.displacements[b]});
  }
  return s;
}

}  // namespace rackopt::fe
