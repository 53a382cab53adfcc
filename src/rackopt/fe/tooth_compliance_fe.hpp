// Single-tooth compliances by FE, with the definition the analytic tooth
// models are compared under: the pinion (whole gear, bore fixed) or a rack
// segment (base fixed) alone, the drive's normal load at the contact of LOA
// coordinate s spread over a Hertz-sized patch (a point load has a
// log-infinite displacement under it), and the displacement read where the
// load line crosses the loaded tooth's centre line, along the load line.
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_options.hpp"
#include "rackopt/fe/mesh2d.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt::fe {

enum class ToothMember { kPinion, kRack };

// One member's compliance at one contact (m/N for the drive's face width).
struct ToothComplianceFe {
  ToothMember member = ToothMember::kPinion;
  double s = 0;              // LOA coordinate of the contact [m]
  double compliance = 0;     // FE: displacement along the load line at the read point / load
  Point2 load_point;         // where the load acts, in the member's own frame [m]
  Point2 read_point;         // where the displacement is read [m]
  double analytic = 0;       // the analytic tooth model's compliance under the same definition
  double hertz_half_width = 0;  // b_H of the loaded patch [m]
  int rack_teeth = 0;           // rack: teeth of the FE segment (the loaded one in the middle); pinion: 0
  int nodes = 0, elements = 0;
  double seconds = 0;        // wall time of mesh + solve
};

// FE single-tooth compliance of `member` of `drive` at LOA coordinate s
// (within the drive's contact path), the load the drive's load.force.
//   Pinion: the whole pinion (pinion_body_outline), both displacement
//   components of every BORE node held, meshed at the level's size on the
//   loaded tooth 0 and its two neighbours (MeshGrading), coarser elsewhere.
//   The load acts on tooth 0's +x flank at the involute point of radius
//   sqrt(r_b^2 + s^2), into the tooth along the flank normal (the line of
//   action, tangent to the base circle); the read point is where that line
//   crosses the tooth's centre line (the y axis).
//   Rack: a segment (rack_segment_outline, root rounds of
//   RackSpec.root_radius) on a body of depth H = options.rack_body_depth,
//   BASE held, its cut ends free; 2 k + 1 teeth, k = max(1, ceil(3 H / p)),
//   so that the ends lie 3 body depths beyond the loaded middle tooth (a
//   shorter segment deforms as a block: 3 teeth on the gantry axis's body
//   read 1.8 times the converged compliance), meshed at the level's size on
//   the middle tooth. The middle tooth's -x flank is loaded along F (cos a0, -sin a0), as the
//   drive loads the rack (core/drive.hpp), at the height
//   MeshGeometry::contact_height_above_datum(s); the read point is where the
//   load line crosses that tooth's centre line.
//   Both: the force per unit thickness F' = F / (the member's face width)
//   spread as a Hertz pressure over b_H = sqrt(4 F' R / (pi E*)), R the
//   involute's curvature radius s against the flat rack flank
//   (patch_curvature_radius: at least m / 10), with
//   mesh discs of b_H / 3 there; compliance = (displacement at the read
//   point . load direction) / F.
// Throws DesignError (from the geometry or the body outlines) before any FE
// work, CcxNotFound / CcxError from the solve, std::invalid_argument for bad
// options, a non-positive load, a pinion without a bore, an s outside the
// path (or, for the pinion, off its involute: pinion_contact_on_involute).
ToothComplianceFe fe_tooth_compliance(const Drive& drive, ToothMember member, double s,
                                      const FeOptions& options = {});

// Whether the pinion's contact at LOA coordinate s lies on its involute
// (s > 0 and at or above the form circle), i.e. whether a pinion
// single-tooth solve can load it. A path of contact kept as the paper's
// geometric one (interference limit off) can start below the base circle's
// tangent point, where the pinion has no involute.
bool pinion_contact_on_involute(const MeshGeometry& geometry, double s);

// The radius of curvature the Hertz patch is sized with at LOA coordinate
// s: the involute's s, but no less than m / 10 (at and below the base
// circle the involute has no curvature to speak of).
double patch_curvature_radius(double s, double module);

// The analytic model's compliance of `member` at s under the same
// definition (m/N, whole face width): pinion = tooth bending + shear + axial
// (PinionToothCompliance) + fillet foundation (FilletFoundationCompliance,
// the pinion's face width); rack = tooth bending + shear + axial
// (RackToothCompliance, the rack's face width) + the rack foundation
// (RackFoundationCompliance: the body under the tooth, calibrated on this
// very FE definition with the base held at the body depth). All from
// PairCompliance; the drive's effects switch the parts; spalls are not
// applied (the FE bodies are intact). The beam models give the displacement
// of the tooth's centre-line section under the load along the load; the
// foundation models use the same crossing of the load line with the centre
// line. Not included: the local contact term (the FE reads away from the
// patch). Throws as the stiffness models do.
double analytic_tooth_compliance(const Drive& drive, ToothMember member, double s);

}  // namespace rackopt::fe
