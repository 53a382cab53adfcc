#include "rackopt/studyfile/study_section_reader.hpp"

#include <algorithm>
#include <cctype>

#include "rackopt/core/suggest.hpp"

namespace rackopt::studyfile {

std::optional<std::string> near_miss(std::string_view word, const std::vector<std::string>& candidates) {
  if (auto best = closest_name(word, candidates)) return best;
  // An abbreviation ("max_evals" for "max_evaluations"): a long common start.
  const std::string* longest = nullptr;
  std::size_t longest_prefix = 0;
  for (const auto& c : candidates) {
    std::size_t k = 0;
    while (k < word.size() && k < c.size() &&
           std::tolower(static_cast<unsigned char>(word[k])) == std::tolower(static_cast<unsigned char>(c[k]))) {
      ++k;
    }
    if (k > longest_prefix) {
      longest = &c;
      longest_prefix = k;
    }
  }
  if (longest != nullptr && longest_prefix >= std::max<std::size_t>(4, (2 * word.size() + 2) / 3)) return *longest;
  return std::nullopt;
}

ReaderStyle study_reader_style() {
  ReaderStyle style;
  style.suggest = near_miss;
  style.digits = 10;
  style.count_digits = 17;
  return style;
}

SectionReader study_section(const MarkedNode* node, std::string path, const SourceMark& fallback,
                            std::vector<std::string> allowed, const std::string& example) {
  return SectionReader(node, std::move(path), fallback, std::move(allowed), study_reader_style(), example);
}

std::string item_path(const std::string& list, std::size_t i) {
  return list + "[" + std::to_string(i) + "]";
}

std::string format_in(double si, QuantityKind kind, std::string_view unit) {
  if (kind == QuantityKind::kCount || kind == QuantityKind::kDimensionless) return format_number(si, 10);
  return format_quantity(si, kind, unit, 10);
}

std::string expected_kind_text(QuantityKind kind) {
  return "a " + std::string(kind_name(kind));
}

ValueSite read_value(const MarkedNode& node, const std::string& path, QuantityKind kind) {
  if (node.type != MarkedNode::Type::kScalar) {
    throw InputError(node.mark, path, "expected a single value, found " + node.type_name());
  }
  return ValueSite{parse_quantity(node.scalar, kind, node.mark, path), node.scalar, node.mark, path};
}

}  // namespace rackopt::studyfile
