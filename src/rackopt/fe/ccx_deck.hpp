// The CalculiX input deck (.inp) of a plane-stress model.
//
// The plane-stress trap: CalculiX expands each CPS6 triangle into one layer
// of 15-node wedges whose in-plane displacement is tied constant through the
// thickness. A slice as thick as the part is wide cannot bend anticlastically
// across its thickness and comes out too stiff in in-plane bending (it is
// then neither plane stress nor plane strain). A slice that is thin compared
// with its in-plane size is plane stress. So the deck models a slice of
// thickness `slice_thickness` (the caller picks it small: slice_thickness_for)
// and scales the loads by it; displacements are then those of the unit-
// thickness plane-stress body, and reactions read back divide by it
// (docs/models/fe_reference.md).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "rackopt/fe/plane_stress_model.hpp"

namespace rackopt::fe {

// Name of the node set holding every supported node (reactions are printed
// for it); reserved: the model's own sets may not use it.
inline constexpr const char* kSupportSet = "RACKOPT_SUPPORTS";

// 1e-3 times the larger side of the mesh's bounding box: thin enough that the
// through-thickness tie of the expanded elements does not matter (measured
// in docs/models/fe_reference.md), thick enough to keep the expanded
// elements' stiffness well conditioned.
double slice_thickness_for(const Mesh2D& mesh);

// The deck: nodes (NALL), CPS6 elements (EALL), the model's node sets, the
// material, *SOLID SECTION with `slice_thickness`, *BOUNDARY for the
// supports, one linear *STATIC step with *CLOAD = load x slice_thickness,
// *EQUATION for the model's equations,
// *NODE PRINT of U for NALL and of RF with totals for kSupportSet (to the
// .dat file). Nodes and elements are numbered index + 1. Numbers are
// written with 13 significant digits (CalculiX
// reads at most 20 characters per number). Calls check_model first (throws
// std::invalid_argument); also throws when a set uses the reserved name.
std::string ccx_deck(const PlaneStressModel& model, double slice_thickness);

// Writes `equations` as *EQUATION cards (nothing when empty), nodes
// numbered index + node_offset + 1.
void write_ccx_equations(std::ostream& out, const std::vector<NodeEquation>& equations, int node_offset = 0);

}  // namespace rackopt::fe
