// The local compliance of one rack-pinion tooth pair at its contact: the
// pinion tooth (bending, shear, axial), the pinion's fillet foundation, the
// rack tooth, the rack tooth's foundation in its body and the local contact
// term, each switched by drive.effects. This is the one place the pair is
// assembled: the mesh model (mesh_stiffness.hpp) and the wear model's load
// sharing (wear/wear_life.hpp) both ask it, so an effect added here reaches
// both. The rack body's bending on its supports is not a pair property
// (rack_span.hpp couples the pairs through it).
//
// Example:
//   const MeshGeometry geo = build_mesh_geometry(drive);
//   PairCompliance pair(drive, geo);
//   PairTeeth t = pair.teeth(s);                          // no contact term
//   double c = t.total() + pair.contact(s, force);        // m/N at the pair force
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/tooth_compliance.hpp"

namespace rackopt {

class PinionToothCompliance;
class RackToothCompliance;

// Depth of the rack body below the root line [m]: rack.body_height, or twice
// the neutral-axis depth when the section was given explicitly (0 when
// neither is known).
double rack_body_depth(const RackSpec& rack);

// The tooth parts of a pair [m/N], a part switched off is 0.
struct PairTeeth {
  ToothCompliance pinion;
  double fillet = 0;           // pinion fillet foundation (Sainsot et al. 2004) + its FE calibration
  ToothCompliance rack;
  double rack_foundation = 0;  // rack tooth foundation (rack_foundation.hpp)
  double total() const { return pinion.total() + fillet + rack.total() + rack_foundation; }
};

// The local contact term of one contact as a function of the pair force:
// c(f) = c_ref - slope ln(max(f, floor) / f_ref) [m/N]. Exact for the
// Weber-Banaschek term (its half-width grows as sqrt(f)), constant for the
// others (slope 0).
struct ContactLaw {
  double c_ref = 0;    // at f_ref [m/N]
  double f_ref = 1;    // [N]
  double slope = 0;    // -dc/d ln f [m/N]
  double floor = 0;    // forces below it count as it [N]
  // Throws DesignError "hertz_out_of_range" where the law leaves no
  // positive compliance (a strip wider than the teeth). Defined here: the
  // two-pair load sharing calls it several times per curve sample.
  double at(double force) const {
    if (slope == 0) return c_ref;
    // f_ref is 1 N for any contact narrower than 1 m (contact_law: the
    // larger of 1 N and the floor of 1 N per metre of width). Dividing by
    // it is exact, so skipping it changes nothing but the time: it sits on
    // the critical path of the two-pair Newton iteration.
    const double f = std::max(force, floor);
    const double c = c_ref - slope * std::log(f_ref == 1.0 ? f : f / f_ref);
    if (!(c > 0)) strip_too_wide(force);
    return c;
  }
  // at(force) from the term at a nearby force it was evaluated at, without
  // the logarithm: c(f) = c(f0) - slope ln(1 + u), u = f/f0 - 1, by the
  // series to u^6 (error below u^7/7 < 2e-22 for |u| <= 1e-3, far below
  // the rounding of the logarithm itself). Falls back on at() farther away,
  // at the floor or where the term would not stay positive. The two-pair
  // Newton's steps after its first are this small: they cost no logarithm.
  double at_near(double force, double known_force, double known_term) const {
    const double u = (force - known_force) / known_force;
    if (known_force > floor && force > floor && std::abs(u) <= 1e-3) {
      const double ln1p = u * (1.0 - u * (0.5 - u * (1.0 / 3 - u * (0.25 - u * (0.2 - u * (1.0 / 6))))));
      const double c = known_term - slope * ln1p;
      if (c > 0) return c;
    }
    return at(force);
  }
  // -dc/d ln f at `force` (0 below the floor).
  double slope_at(double force) const { return force > floor ? slope : 0.0; }
  [[noreturn]] static void strip_too_wide(double force);
};

class PairCompliance {
 public:
  // Builds the tooth models the effects ask for (nothing else is built).
  // Throws InputError / DesignError as the tooth models do (e.g. a pointed
  // tooth, a bore outside the root circle, a rack without body depth while
  // rack_foundation is on).
  PairCompliance(const Drive& drive, const MeshGeometry& geometry);
  ~PairCompliance();
  PairCompliance(PairCompliance&&) noexcept;
  PairCompliance& operator=(PairCompliance&&) noexcept;

  // Tooth parts at LOA coordinate s for the drive's own rack datum. A spall
  // band reduces the section of the member it lies on; face_width (> 0) is
  // the width that carries the load (less than the contact width while a
  // spall is under the contact: the fillet foundation scales with it).
  PairTeeth teeth(double s, const SpallBand* pinion_spall = nullptr, const SpallBand* rack_spall = nullptr,
                  double face_width = 0) const;
  // The same with the rack contact at height y_c above its root line (the
  // wear model moves the rack datum with the clearance): the pinion parts at
  // s, the rack parts at y_c.
  PairTeeth teeth_at(double s, double rack_height, double face_width = 0) const;

  // Local contact term [m/N] at LOA coordinate s for the pair force `force`
  // [N] (secant: approach / force), contact width face_width (0: the
  // drive's contact width), the rack contact at height rack_height above
  // its root line (< 0: the drive's own rack datum). effects.hertz:
  //   off: 0;  linear: 2/(pi b E*) (Yang & Lin), force-independent;
  //   weber_banaschek: plane-stress Weber-Banaschek between the two tooth
  //   centre lines, measured along the load line (docs/models/contact.md);
  //   it grows as -ln(force) and the force is floored at 1 N/m of width.
  // Throws DesignError "hertz_out_of_range" for a contact strip wider than
  // the teeth.
  double contact(double s, double force, double face_width = 0, double rack_height = -1) const;
  // The same term as a law in the force at this contact: one logarithm per
  // evaluation instead of the geometry and the square root.
  ContactLaw contact_law(double s, double face_width = 0, double rack_height = -1) const;
  // True when contact() depends on the force.
  bool contact_depends_on_force() const;

  // Height of the rack contact above the rack root line at s for the
  // drive's own datum [m].
  double rack_contact_height(double s) const;
  double contact_width() const;

  // The tooth models in use (null when switched off), for callers that
  // validate spall bands against them.
  const PinionToothCompliance* pinion_tooth() const;
  const RackToothCompliance* rack_tooth() const;

  // Warnings of the models built (e.g. outside a fitted range).
  const std::vector<std::string>& warnings() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace rackopt
