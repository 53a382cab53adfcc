#include "rackopt/record/record_checksum.hpp"

#include <bit>

#include "rackopt/core/fnv1a.hpp"

namespace rackopt::record {

std::int64_t row_checksum(const RowBytes& r) {
  std::uint64_t h = kFnv1aOffsetBasis;
  auto number = [&h](std::uint64_t v) {
    char bytes[8];
    for (int b = 0; b < 8; ++b) bytes[b] = static_cast<char>((v >> (8 * b)) & 0xffu);
    h = fnv1a64(std::string_view(bytes, 8), h);
  };
  auto field = [&](std::string_view bytes) {
    number(bytes.size());
    h = fnv1a64(bytes, h);
  };
  number(static_cast<std::uint64_t>(r.x_hash));
  for (std::string_view f : {r.phase, r.x, r.objectives, r.inequality, r.equality, r.metric_ids, r.metric_values})
    field(f);
  number(static_cast<std::uint64_t>(r.ok));
  field(r.message);
  number(static_cast<std::uint64_t>(r.gradient_probe));
  number(std::bit_cast<std::uint64_t>(r.seconds));
  field(r.warnings);
  field(r.models);
  return std::bit_cast<std::int64_t>(h);
}

}  // namespace rackopt::record
