// The FE rack on its hinged supports: the rack body as the real beam between
// the two hinges of its span, as the analytic rack-span model
// (stiffness/rack_span.hpp, docs/models/rack_span.md) idealises it.
//
// Where the hinges act: rack_span.hpp carries each contact force to the
// neutral axis and supports the beam there (its axial law, pin-pin or
// pin-roller, is that of the neutral axis), so the FE hinges act at the
// neutral axis too: on each end face of the body, at the depth of the
// section's centroid (half the FE body depth below the root line).
//
// A hinge on one node would be a point support in a 2-D continuum: the
// displacement under it is log-singular, so the compliance would depend on
// the element size there. The hinge is therefore a short patch of the end
// face, |y - y_axis| <= c, tied as a rigid line that may turn freely about
// the axis point A: every patch node has v = 0 (a distributed vertical
// support, which a turning vertical line does not resist), and the
// horizontal displacement of each patch node follows the rigid turn of the
// line through A and the top patch node T, u_i = (1 - w_i) u_A + w_i u_T,
// w_i = (y_i - y_A) / (y_T - y_A) (CalculiX *EQUATION, coefficients summing
// to 0: the tie passes no net force). A pin also holds u_A = 0; a roller
// leaves u_A free. The only stiffening left is that of a rigid end plate
// of height 2c (plane sections stay plane over it), which the beam model
// assumes anyway; docs/models/fe_reference.md ("Rack on its supports")
// measures how little c matters.
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_options.hpp"
#include "rackopt/fe/gmsh_mesher.hpp"
#include "rackopt/fe/mesh_placement.hpp"
#include "rackopt/fe/plane_stress_model.hpp"

namespace rackopt::fe {

// The supports and ties of one hinge, in the node numbering of its mesh.
struct HingeConstraints {
  std::vector<PrescribedDisplacement> supports;  // all zero
  std::vector<NodeEquation> equations;
};

// The hinge whose patch is the node set `patch_set` (nodes on a vertical
// end face) with axis node set `axis_set` (one node, on the same face).
// hold_x: a pin (u_A = 0); false: a roller. Throws std::invalid_argument
// when the axis set is not one node, the patch has no node above the axis
// or its nodes are not on one vertical line (to 1e-9 of the patch height).
HingeConstraints hinge_constraints(const Mesh2D& mesh, const std::string& patch_set, const std::string& axis_set,
                                   bool hold_x);

// A plain rectangular beam x in [0, length], y in [-depth/2, depth/2] (the
// axis at y = 0) with hinge patches of half height `patch_half_height` on
// both end faces: edge sets HINGE_L / HINGE_R (the patches), vertex sets
// HINGE_L_AXIS / HINGE_R_AXIS, edge sets TOP and BOTTOM; the top face has
// vertices at load_from and load_to (0 < from < to < length), its edge
// between them named LOAD. For the closed-form check of the hinges.
Polygon2D hinged_beam_outline(double length, double depth, double patch_half_height, double load_from,
                              double load_to);

// The rack of a mesh position along its whole span: the segment `placement`
// holds (the teeth in mesh, their neighbours, the redrawn flanks and their
// sets, unchanged) continued by the other teeth of the span on both sides,
// all on one body of `depth` below the root line, cut by the end faces at
// the hinges x_left = segment * span and x_right = x_left + span (rack-fixed
// frame of mesh_placement.hpp). A partial tooth cell at an end is left
// without its tooth (root line to the end face). The other teeth's outline
// points closer than `far_spacing` are dropped (their root rounds drawn
// with a few chords: they only stiffen the beam a little, away from the
// contacts). Hinge patches of half
// height `patch_half_height` about the axis depth y_axis = -dedendum -
// depth / 2, sets as hinged_beam_outline. Throws std::invalid_argument when
// the placement's segment reaches past a hinge (the position is too near
// it; a contact's own tooth and one each side must lie within the span).
struct SpanRackOutline {
  BodyOutline outline;
  double x_left = 0, x_right = 0;  // hinges [m]
  double y_axis = 0;               // their height [m]
  int teeth = 0;                   // teeth on the span
};
SpanRackOutline rack_span_outline(const Drive& drive, const MeshGeometry& geometry, const MeshPlacement& placement,
                                  int segment, double depth, double patch_half_height, double far_spacing);

}  // namespace rackopt::fe

namespace rackopt::fe {

// Depth of the FE rack body below the root line: options.rack_body_depth,
// else rack.body_height, else twice the section's neutral-axis depth.
// Throws std::invalid_argument when none is positive.
double fe_rack_body_depth(const Drive& drive, const FeOptions& options);

// The contact width the FE results are scaled by: min(pinion, rack face
// width), as the analytic model's.
double fe_contact_width(const Drive& drive);

// `drive` with the rack body the FE rack on its supports has: the coupled
// rack-span model (effects.rack_span = kCoupled) on the rectangular section
// of the FE body (fe_contact_width wide, fe_rack_body_depth deep, shear
// area A / 1.2, neutral axis at half the depth), the span, supports and
// every other effect as given. For the shipped problems the section is the
// drive's own (a rectangular body as wide as the teeth).
Drive rack_on_supports_drive(const Drive& drive, const FeOptions& options);

// The span rack of a mesh position, meshed: rack_span_outline with hinge
// patches of half height patch_fraction * depth, the element size at most
// `body_size` in the body and depth / 6 (six quadratic elements through the
// depth: the bending of the hinged beam within 0.5 %, docs), discs
// `refinements` (the loaded teeth and contacts) and c / 2 at the hinges;
// the hinges as rack.supports says (the left one a pin; the right one a pin
// for pin-pin, a roller for pin-roller).
struct SpanRackMesh {
  Mesh2D mesh;
  HingeConstraints hinges;  // both hinges, in the mesh's numbering
  SpanRackOutline geometry;
};
SpanRackMesh mesh_span_rack(const Drive& drive, const MeshGeometry& geometry, const MeshPlacement& placement,
                            int segment, double depth, double body_size, double far_spacing,
                            const std::vector<Refinement>& refinements, double patch_fraction);

}  // namespace rackopt::fe
