#include "rackopt/problem/drive_sections.hpp"

#include <cmath>

#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {

void read_load(const SectionReader& top, Drive& drive) {
  const PinionSpec& pin = drive.pinion;
  const SectionReader load =
      problem_section(top.get("load"), "load", "load", top.mark(),
                      {"force", "torque", "thrust", "speed", "efficiency", "application_factor", "dynamic_factor",
                       "face_load_factor", "face_load_factor_bending", "transverse_load_factor"});
  {
    std::vector<std::string> given;
    for (const char* k : {"force", "torque", "thrust"}) {
      if (load.has(k)) given.emplace_back(k);
    }
    if (given.size() > 1) {
      throw InputError(load.key_mark(given[1]), "load." + given[1],
                       "give one of load.force (normal mesh force), load.torque (pinion torque) or load.thrust "
                       "(rack thrust), not load." +
                           given[0] + " and load." + given[1]);
    }
    if (given.empty()) {
      load.missing("force",
                   "load.force (normal mesh force along the line of action, e.g. 50 kN), load.torque "
                   "(pinion torque, e.g. 453 kN*m) or load.thrust (tangential force on the rack, e.g. 12 kN)");
    }
  }
  // The normal force acts along the line of action, tangent to the base
  // circle: F = T / r_b with r_b = m z cos(a0) / 2 (profile shift does not
  // change r_b); the rack's operating pressure angle is a0, so F = F_t / cos a0.
  if (load.has("force")) {
    drive.load.force = load.number("force", std::nullopt);
  } else if (load.has("torque")) {
    drive.load.torque = load.number("torque", std::nullopt);
    const double base_radius = 0.5 * pin.module * pin.teeth * std::cos(pin.pressure_angle);
    drive.load.force = drive.load.torque / base_radius;
  } else {
    drive.load.thrust = load.number("thrust", std::nullopt);
    drive.load.force = drive.load.thrust / std::cos(pin.pressure_angle);
  }
  drive.load.speed = load.number("speed", 0.0);
  drive.load.efficiency = load.number("efficiency", 1.0);
  {
    const std::string why = " (ISO 6336 load factors are >= 1; 1 = no extra load)";
    const Load ld;
    drive.load.application_factor = load.number("application_factor", ld.application_factor, why);
    drive.load.dynamic_factor = load.number("dynamic_factor", ld.dynamic_factor, why);
    drive.load.face_load_factor = load.number("face_load_factor", ld.face_load_factor, why);
    // Absent: 0, derived from K_Hbeta and the tooth proportions where the
    // stresses are computed (so it follows a varied module or face width).
    drive.load.face_load_factor_bending = load.number("face_load_factor_bending", 0.0, why);
    drive.load.transverse_load_factor = load.number("transverse_load_factor", ld.transverse_load_factor, why);
  }
}

}  // namespace rackopt
