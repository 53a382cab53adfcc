#include "rackopt/problem/drive_sections.hpp"

#include <cmath>

#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void read_faults(const SectionReader& top, Drive& drive) {
  const PinionSpec& pin = drive.pinion;
  const RackSpec& rack = drive.rack;
  const double pitch = kPi * pin.module;
  if (const MarkedNode* faults = top.get("faults")) {
    if (faults->type != MarkedNode::Type::kSequence) {
      throw InputError(
          faults->mark, "faults",
          "expected a list of faults (- {type: spall, member: pinion, tooth: 0, ...}), found " + faults->type_name());
    }
    const int rack_teeth =
        rack.tooth_offset <= rack.span ? static_cast<int>(std::floor((rack.span - rack.tooth_offset) / pitch)) + 1 : 0;
    for (std::size_t i = 0; i < faults->items.size(); ++i) {
      const MarkedNode& item = faults->items[i];
      const std::string path = "faults[" + std::to_string(i) + "]";
      if (!item.is_map()) {
        throw InputError(
            item.mark, path,
            "expected a map {type: spall, member, tooth, start, length, width, depth}, found " + item.type_name());
      }
      const SectionReader f = problem_section(&item, path, "faults[]", item.mark,
                                              {"type", "name", "member", "tooth", "start", "length", "width", "depth"});
      if (!f.has("type")) f.missing("type", "the fault type: spall");
      f.choice("type", {"spall"}).value_or("spall");
      Spall s;
      s.name = f.text("name", "spall " + std::to_string(i + 1));
      s.member = f.choice("member", {"pinion", "rack"}).value_or("pinion") == "rack" ? Member::kRack : Member::kPinion;
      s.tooth = f.whole("tooth", std::nullopt);
      if (s.member == Member::kPinion) {
        f.check_range("tooth", s.tooth, {0, static_cast<double>(pin.teeth - 1), false, false},
                      " (pinion teeth are numbered 0..z-1)");
      } else {
        f.check_range("tooth", s.tooth, {0, static_cast<double>(rack_teeth - 1), false, false},
                      " (rack teeth of one span are numbered 0.." + std::to_string(rack_teeth - 1) + ")");
      }
      s.start = f.number("start", std::nullopt);
      s.length = f.number("length", std::nullopt);
      s.width = f.number("width", std::nullopt);
      s.depth = f.number("depth", std::nullopt);
      drive.spalls.push_back(s);
    }
  }
}

}  // namespace rackopt
