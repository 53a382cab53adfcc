// The real gear bodies as FE meshes: the cutter-generated pinion (every
// tooth with its involute flanks, trochoidal fillets and, where the cutter
// undercuts it, the undercut) around its bore, and a rack segment of N
// straight-sided teeth on its body. The curves come from geometry/
// (pinion_generation.hpp, the same outline pinion_section.hpp integrates for
// the pinion mass) as polylines, so the meshed area is exactly the polyline's
// and differs from the true outline only by the chords' sag.
#pragma once

#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/gmsh_mesher.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt::fe {

// An outline to mesh: the outer polygon and its holes (the bore), with the
// node-set names on their edges (gmsh_mesher.hpp).
struct BodyOutline {
  Polygon2D outer;
  std::vector<Polygon2D> holes;
};

// Where a gear-body mesh is fine. The default meshes the whole body at the
// level's element size (gear_element_size).
struct MeshGrading {
  // Teeth meshed at the level's size together with their fillets and root
  // up to the middle of the spaces on either side (pinion: 0..z-1, rack:
  // 0..teeth-1): a disc of that size over each, growing to the coarse size
  // over a further disc radius (so the neighbours' near flanks are finer
  // too). Elsewhere the body takes the coarse size
  // min(coarse_factor * size, module), and the pinion's outline away from the
  // focus teeth is spaced at half of it (at least 2 chords per curve, the
  // bore a polygon of at least 72 sides). Empty: no grading. A
  // coarse_factor below 1 throws std::invalid_argument.
  std::vector<int> focus_teeth;
  double coarse_factor = 4;
  // Extra discs of finer mesh (loaded patches, read points), passed to the
  // mesher as they are, graded or not.
  std::vector<Refinement> refinements;
};

// The disc a focus tooth is meshed fine in (its centre on the tooth centre
// line halfway up the tooth, its radius reaching the farthest point of the
// tooth's outline between the two space middles), size `size`. Pinion: the
// frame of pinion_body_outline; rack: that of rack_segment_outline.
Refinement pinion_focus_disc(const PinionSpec& pinion, const MeshGeometry& geometry, int tooth, double size);
Refinement rack_focus_disc(const MeshGeometry& geometry, int tooth, double size);

// Element size of refinement level `level` (0 = coarsest, module / 6; each
// level halves it). Throws std::invalid_argument for a level outside 0..6.
double gear_element_size(double module, int level);

// Outline of the whole pinion of `pinion` (radii from `geometry`, which
// build_mesh_geometry made from the same pinion), counter-clockwise, centre
// at the origin, tooth 0's centre line along +y and tooth k's turned by
// 2 pi k / z counter-clockwise. Each tooth: root arc, fillet (cutter tip
// round) up to the form circle, involute up to the tip circle, tip arc, and
// back down the other side. Each curved piece is a polyline of chords of at
// most about `spacing` [m] (estimated arc length / intervals, at least 8
// intervals per piece). Sets:
//   "BORE"          the bore circle (a polygon of at least 180 sides;
//                   no hole when bore_radius = 0, a solid disc)
//   "T<k>_FLANK_R"  involute of tooth k on its +x side in the tooth frame
//                   (pinion_generation.hpp), i.e. clockwise of its centre line
//   "T<k>_FLANK_L"  the other involute of tooth k
// Throws DesignError "bore_beyond_root" when bore_radius >= the root radius
// (no rim left), std::invalid_argument for a negative or non-finite bore or
// a non-positive spacing. No Gmsh work is done here.
// With `focus_teeth` given, only those teeth take `spacing`; the others (and
// the bore) take `other_spacing` (0: `spacing`) with at least 2 intervals per
// curve piece and 72 bore sides. A focus tooth index outside
// 0..z-1 throws std::invalid_argument.
BodyOutline pinion_body_outline(const PinionSpec& pinion, const MeshGeometry& geometry, double bore_radius,
                                double spacing, const std::vector<int>& focus_teeth = {}, double other_spacing = 0);

// pinion_body_outline meshed with quadratic triangles of
// gear_element_size(module, level), the outline points spaced at half that,
// graded as `grading` says. Errors: those of pinion_body_outline (before any
// Gmsh work), then those of mesh_polygon_with_holes.
Mesh2D mesh_pinion_body(const PinionSpec& pinion, const MeshGeometry& geometry, double bore_radius, int level = 0,
                        const MeshGrading& grading = {});

// Outline of a rack segment of `teeth` teeth (counter-clockwise): x along the
// rack from the middle of the tooth space left of tooth 0 to the middle of
// the space right of tooth teeth-1 (length teeth * pitch), y up with the
// datum line at 0, the tip line at addendum, the root line at -dedendum and
// the body's bottom edge body_height below the root line. The teeth are the
// straight-sided trapezoids of geometry.rack (flanks at the pressure angle,
// half thickness w_f at the root line, as stiffness/rack_tooth.hpp models
// them), each root corner rounded by an arc of radius `root_radius`
// tangent to the flank and to the root line (RackSpec.root_radius; 0 = the
// pinion cutter tip radius geometry.pinion.cutter_tip_radius, a sharp
// corner when that is 0 too), as 12 chords. The round reaches
// t = rho / tan(45 deg + a0 / 2) along both lines from the corner, up to
// the height rho (1 - sin a0) on the flank.
// Sets: "BASE" (bottom edge), "LEFT_END", "RIGHT_END" (the body's cut
// faces, x = 0 and x = teeth * pitch), "T<k>_FLANK_L" / "T<k>_FLANK_R" (the
// straight flanks of tooth k facing -x / +x, from their round up to the tip).
// Throws DesignError "pointed_tooth" (tip half thickness <= 0),
// "rack_root_closed" (no root left between the teeth) or "rack_root_round"
// (two rounds overlap on the root line, or a round runs past the tip),
// std::invalid_argument for teeth < 1, a non-positive body height or a
// negative root radius.
BodyOutline rack_segment_outline(const MeshGeometry& geometry, int teeth, double body_height,
                                 double root_radius = 0);

// Teeth a rack segment carries on either side of its loaded teeth. The
// segment's cut ends are free: a short segment on a deep body shears and
// bends as a block under the load's component along the rack, which the
// continuous rack does not. So the segment reaches 3 body depths beyond the
// loaded teeth, at least one tooth: the compliance then moves by about 1e-3
// with more (docs/models/fe_reference.md; 3 teeth on the gantry axis's 31 mm
// body read 1.8 times the converged value). Used by the single-tooth and the
// mesh-position solves alike, so that both see the same rack.
int rack_teeth_each_side(double body_depth, double pitch);

// rack_segment_outline meshed with quadratic triangles of
// gear_element_size(module, level) (module = pitch / pi), graded as
// `grading` says (a focus tooth outside 0..teeth-1 throws
// std::invalid_argument).
Mesh2D mesh_rack_segment(const MeshGeometry& geometry, int teeth, double body_height, int level = 0,
                         const MeshGrading& grading = {}, double root_radius = 0);

}  // namespace rackopt::fe
