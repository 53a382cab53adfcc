#include "rackopt/problem/drive_sections.hpp"

#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/core/text.hpp"

#include "rackopt/problem/random_input_reader.hpp"

namespace rackopt {

void read_reliability(const SectionReader& top, Drive& drive) {
  const SectionReader r =
      problem_section(top.get("reliability"), "reliability", "reliability", top.key_mark("reliability"),
                      {"samples", "seed", "sampling", "R", "times", "ks_level", "bootstrap_replicates", "life_table",
                       "life_table_tolerance", "random"});
  ReliabilitySpec& rel = drive.reliability;
  const ReliabilitySpec defaults;
  rel.samples = r.whole("samples", defaults.samples);
  rel.seed = static_cast<unsigned long>(r.whole("seed", static_cast<int>(defaults.seed)));
  rel.sobol = r.choice("sampling", {"pseudo", "sobol"}).value_or(defaults.sobol ? "sobol" : "pseudo") == "sobol";
  for (const auto& v : schema_quantity_list(r, "R", "reliability.R[]")) rel.reliabilities.push_back(v.si);
  for (const auto& v : schema_quantity_list(r, "times", "reliability.times[]")) rel.times.push_back(v.si);
  rel.ks_level = r.number("ks_level", defaults.ks_level);
  rel.bootstrap_replicates = r.whole("bootstrap_replicates", defaults.bootstrap_replicates);
  rel.life_table = r.flag("life_table", defaults.life_table);
  rel.life_table_tolerance = r.number("life_table_tolerance", defaults.life_table_tolerance);
  const MarkedNode* random = r.get("random");
  if (random == nullptr) return;
  if (random->type != MarkedNode::Type::kSequence) {
    throw InputError(random->mark, "reliability.random",
                     "expected a list of random inputs (- {input: contact_ratio, distribution: normal, sd: 0.02}), "
                     "found " +
                         random->type_name());
  }
  for (std::size_t i = 0; i < random->items.size(); ++i) {
    const std::string path = "reliability.random[" + std::to_string(i) + "]";
    RandomInput input = read_random_input(random->items[i], path);
    for (std::size_t j = 0; j < rel.inputs.size(); ++j) {
      if (rel.inputs[j].key == input.key) {
        const MarkedNode* written = random->items[i].find("input");
        throw InputError(written->mark, path + ".input",
                         "'" + written->scalar + "' is already random in reliability.random[" + std::to_string(j) +
                             "]; each input may appear once");
      }
    }
    rel.inputs.push_back(input);
  }
}

}  // namespace rackopt
