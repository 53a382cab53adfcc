// The checksum each row of the evaluation store carries (docs/recorder.md,
// "Row checksums"): a row whose bytes no longer give its checksum is damaged
// and recomputed on --resume instead of being reused.
#pragma once

#include <cstdint>
#include <string_view>

namespace rackopt::record {

// The fields of one evaluation_records row that --resume reads, as stored.
struct RowBytes {
  std::int64_t x_hash = 0;
  std::string_view phase, x, objectives, inequality, equality, metric_ids, metric_values;
  std::int64_t ok = 0;
  std::string_view message;
  std::int64_t gradient_probe = 0;
  double seconds = 0;
  std::string_view warnings, models;
};

// FNV-1a over every field of the row, each preceded by its length, so that a
// flipped bit anywhere (or bytes moved from one field to the next) changes
// it. Numbers enter as their 8 little-endian bytes (portable files).
std::int64_t row_checksum(const RowBytes& r);

}  // namespace rackopt::record
