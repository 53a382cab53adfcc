#include "rackopt/wear_reliability/design_scatter.hpp"

#include "rackopt/core/error.hpp"

namespace rackopt {

double design_value(const Drive& d, const std::string& key, double nominal_contact_ratio) {
  if (key == "contact_ratio") return nominal_contact_ratio;
  if (key == "wear.coefficient") return d.wear.coefficient;
  if (key == "load") return d.load.force;
  if (key == "surface_hardness") {
    const double h = d.wear.rack_hardness.surface > 0 ? d.wear.rack_hardness.surface : d.wear.pinion_hardness.surface;
    if (!(h > 0)) {
      throw InputError({d.source_file, 0, 0}, "reliability.random",
                       "surface_hardness needs a surface hardness in wear.hardness");
    }
    return h;
  }
  throw InputError({d.source_file, 0, 0}, "reliability.random",
                   "unknown random input '" + key + "' (allowed: contact_ratio, wear_coefficient, load, surface_hardness)");
}

statistics::Distribution input_distribution(const RandomInput& in, double v0) {
  if (in.absolute) return statistics::to_distribution(in);
  RandomInput abs = in;
  abs.absolute = true;
  switch (in.distribution) {
    case RandomInput::Distribution::kNormal:
      abs.a = v0 + in.a;
      abs.b = in.cv > 0 ? in.cv * v0 : in.b;
      break;
    case RandomInput::Distribution::kLognormal:
      abs.a = v0 * in.a;  // median factor times the design's value
      break;
    case RandomInput::Distribution::kUniform:
      abs.a = v0 + in.a;
      abs.b = v0 + in.b;
      break;
    case RandomInput::Distribution::kWeibull:
      throw InputError(SourceMark{}, "reliability.random",
                       "a weibull " + in.key + " is only available in the absolute form (absolute: true)");
  }
  // A contact ratio below 1 only makes its samples fail at once; a negative
  // load, wear coefficient or hardness has no meaning.
  if (in.key != "contact_ratio" && !(abs.a > 0)) {
    throw DesignError("random_input_not_positive",
                      "the scatter of " + in.key + " around this design's value " + std::to_string(v0) +
                          " has a non-positive " + (in.distribution == RandomInput::Distribution::kUniform
                                                         ? "lower end"
                                                         : "centre") +
                          " (" + std::to_string(abs.a) + "): its shift is larger than the design's value");
  }
  return statistics::to_distribution(abs);
}

}  // namespace rackopt
