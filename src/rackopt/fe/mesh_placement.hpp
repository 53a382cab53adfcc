// Where the FE bodies of a mesh position sit: the whole pinion and a rack
// segment, in the rack-fixed frame of the analytic model (x along the rack
// from the left support of the studied segment, y up, rack datum at y = 0),
// placed so that every pair MeshStiffnessModel::at(X) has in mesh touches at
// its theoretical contact, unloaded. Pure geometry: no Gmsh, no ccx.
//
// Kinematics (docs/models/mesh.md): the pitch point is P = (X, x m + Delta),
// the pinion centre O = (X, r + x m + Delta); the line of action runs
// through P along n = (cos a0, -sin a0), and the contact of LOA coordinate s
// is C(s) = P + (s - s_P) n, at radius sqrt(r_b^2 + s^2) on the pinion. The
// mesh force pushes the rack along +x, so the loaded flanks are the rack
// teeth's -x facing flanks (rack outline set T<k>_FLANK_L) and the pinion
// teeth's counter-clockwise flanks (pinion outline set T<k>_FLANK_L, which
// faces +x on a tooth pointing down): a counter-clockwise hub rotation loads
// the mesh.
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/gear_bodies.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::fe {

// One pair of flanks that may touch.
struct FlankContact {
  int rack_tooth = 0;       // global rack tooth (MeshStiffnessModel numbering)
  int pinion_tooth = 0;     // 0..z-1 (rack tooth j meshes with pinion tooth j mod z)
  double s = 0;             // LOA coordinate of the pair (outside the path for a neighbour)
  bool theoretical = true;  // false: a neighbouring pair (extended contact), not in mesh at X
  Point2 contact;           // theoretical contact C(s) in the global frame (theoretical pairs)
  std::string pinion_set;   // flank set in the pinion outline ("T<k>_FLANK_L")
  std::string rack_set;     // flank set in the rack outline ("T<i>_FLANK_L", i = rack_tooth - first_rack_tooth)
};

// How finely the outlines are drawn.
struct PlacementSpacing {
  double outline = 0;  // point spacing of the outlines away from the contacts [m]
  double contact = 0;  // point spacing at the theoretical contacts [m] (<= outline)
  double growth = 0.25;  // the spacing grows by this fraction of the distance from the contact
  double far = 0;        // point spacing of the pinion teeth not in or next to the mesh [m] (<= outline: outline)
};

struct MeshPlacement {
  double travel = 0;
  Point2 pinion_centre;         // O [m]
  double pinion_rotation = 0;   // turn of pinion_body_outline's frame, counter-clockwise [rad]
  double rack_shift = 0;        // x of rack_segment_outline's origin [m]
  int first_rack_tooth = 0;     // global rack tooth of segment tooth 0
  int rack_teeth = 0;           // teeth in the segment
  double rack_body_depth = 0;   // below the root line [m]
  double bore_radius = 0;       // of the pinion outline [m]
  std::vector<int> focus_pinion_teeth;  // the pinion teeth in mesh and one each side
  Point2 loa_direction;         // n = (cos a0, -sin a0): the mesh force on the rack
  BodyOutline pinion;           // both outlines in the global frame
  BodyOutline rack;
  // The theoretical pairs (s descending, as MeshState), then, when asked,
  // the neighbours: the pair about to enter (rack tooth j_lo - 1) and the
  // pair just left (j_hi + 1).
  std::vector<FlankContact> contacts;
};

// Places the bodies of `drive` at travel X. `model` is the analytic model of
// the same drive (its geometry and its pairs at X). The rack segment holds
// every pair in mesh plus `rack_side_teeth` teeth each side (0: as many as
// rack_teeth_each_side in gear_bodies.hpp asks for, the free-ended segment
// of a held rack; a rack whose span is drawn around the segment needs only
// one); its body is `rack_body_depth`
// deep below the root line (> 0), its root corners rounded by
// drive.rack.root_radius as rack_segment_outline does. The pinion's bore is drive.pinion.bore_radius
// (0: half the root radius, the loader's default). Each theoretical contact
// is a vertex of both outlines, the loaded flanks of the pairs in mesh are
// drawn at spacing.contact there, graded to spacing.outline. Throws
// DesignError from the outlines, std::invalid_argument for bad spacings or a
// non-positive depth, std::runtime_error when no pair is in mesh at X.
MeshPlacement place_mesh(const Drive& drive, const MeshStiffnessModel& model, double travel,
                         const PlacementSpacing& spacing, double rack_body_depth, bool neighbours,
                         int rack_side_teeth = 0);

// Distance from `p` to the polygon's boundary (its closed polyline) [m].
double distance_to_polygon(const Polygon2D& polygon, Point2 p);
// Whether `p` is inside the polygon (even-odd rule).
bool inside_polygon(const Polygon2D& polygon, Point2 p);

}  // namespace rackopt::fe
