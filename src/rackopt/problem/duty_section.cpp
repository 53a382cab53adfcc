#include "rackopt/problem/drive_sections.hpp"

#include <cmath>

#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void read_duty(const SectionReader& top, Drive& drive) {
  const SectionReader d = problem_section(
      top.get("duty"), "duty", "duty", top.key_mark("duty"),
      {"rack_meshes_per_year", "pinion_meshes_per_year", "travel_per_year", "strokes_per_year", "stroke"});
  if (d.node() == nullptr) return;  // no duty: lives in cycles only
  Duty& duty = drive.duty;
  const bool as_counts = d.has("rack_meshes_per_year");
  const bool as_travel = d.has("travel_per_year") || d.has("strokes_per_year") || d.has("stroke");
  if (as_counts && as_travel) {
    const std::string other = d.has("stroke")            ? "stroke"
                              : d.has("travel_per_year") ? "travel_per_year"
                                                         : "strokes_per_year";
    throw InputError(
        d.key_mark(other), "duty." + other,
        "give the duty either as mesh counts (duty.rack_meshes_per_year) or as travel (duty.stroke with "
        "duty.travel_per_year or duty.strokes_per_year), not both: duty.rack_meshes_per_year is also given");
  }
  // The rate kind is SI (1/s) like every value; the Drive keeps per year.
  if (!as_travel) {
    duty.rack_meshes_per_year = d.number("rack_meshes_per_year", std::nullopt) * kSecondsPerYear;
    // Absent, or 0 (docs/yaml.md: "0 = the rack's"): the rack's count.
    const double pinion =
        d.has("pinion_meshes_per_year") ? d.number("pinion_meshes_per_year", std::nullopt) * kSecondsPerYear : 0.0;
    duty.pinion_meshes_per_year = pinion > 0 ? pinion : duty.rack_meshes_per_year;
    return;
  }
  if (d.has("pinion_meshes_per_year")) {
    throw InputError(d.key_mark("pinion_meshes_per_year"), "duty.pinion_meshes_per_year",
                     "with the duty given as travel the pinion's mesh count follows from it (travel / (pi m z)); "
                     "remove duty.pinion_meshes_per_year");
  }
  if (d.has("travel_per_year") && d.has("strokes_per_year")) {
    throw InputError(d.key_mark("strokes_per_year"), "duty.strokes_per_year",
                     "give duty.travel_per_year or duty.strokes_per_year, not both (travel = strokes x stroke)");
  }
  if (!d.has("travel_per_year") && !d.has("strokes_per_year")) {
    d.missing("travel_per_year", "duty.travel_per_year (e.g. 2000 km/yr) or duty.strokes_per_year (e.g. 5000 1/yr)");
  }
  duty.stroke = d.number("stroke", std::nullopt);
  duty.travel_per_year = d.has("travel_per_year")
                             ? d.number("travel_per_year", std::nullopt) * kSecondsPerYear
                             : d.number("strokes_per_year", std::nullopt) * kSecondsPerYear * duty.stroke;
  duty.rack_meshes_per_year = duty.travel_per_year / duty.stroke;
  duty.pinion_meshes_per_year = duty.travel_per_year / (kPi * drive.pinion.module * drive.pinion.teeth);
}

}  // namespace rackopt
