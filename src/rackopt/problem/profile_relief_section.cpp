#include "rackopt/problem/drive_sections.hpp"

#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {

ProfileRelief read_relief(const SectionReader& member, const std::string& key, const std::string& schema_path,
                          double module) {
  ProfileRelief out;
  if (!member.has(key)) return out;
  const SectionReader b = problem_section(member.get(key), member.child_path(key), schema_path, member.key_mark(key),
                                          {"amount", "length", "shape"});
  out.amount = b.number("amount", std::nullopt);
  b.check_range("amount", out.amount, {0, 0.1 * module, false, false},
                " (a tenth of the module; reliefs are tens of micrometres: write e.g. 20 um)");
  if (const auto text = b.scalar("length", "a multiple of the module (e.g. 0.3) or a length (e.g. 8 mm)")) {
    // A bare number is a multiple of the module, a number with a unit a length.
    double coef = 0;
    try {
      coef = parse_quantity(text->first, QuantityKind::kDimensionless, text->second, b.child_path("length"));
    } catch (const InputError&) {
      coef = parse_quantity(text->first, QuantityKind::kLength, text->second, b.child_path("length")) / module;
    }
    b.check_range("length", coef, {0, 5, true, false},
                  " (multiples of the module, 5 m = " + format_length_mm(5 * module) + ")");
    out.length = coef * module;
  } else if (out.amount > 0) {
    b.missing("length",
              "the relief length along the line of action: a multiple of the module (e.g. 0.3) or a "
              "length (e.g. 8 mm)");
  }
  out.shape = b.choice("shape", {"linear", "parabolic"}).value_or("linear") == "parabolic"
                  ? ProfileRelief::Shape::kParabolic
                  : ProfileRelief::Shape::kLinear;
  return out;
}

}  // namespace rackopt
