// libFuzzer target over the writers of plot scripts, report.md and
// report.html (writer_fuzz_case.hpp). Built only with -DRACKOPT_FUZZ=ON and
// clang; run with ./dev.sh fuzz (docs/input_limits.md, "Fuzzing"). An input
// that breaks a rule, crashes or trips a sanitizer is a bug: add it to
// tests/fuzz/writer_corpus/ so the regular test suite replays it.
#include <cstddef>
#include <cstdint>

#include "writer_fuzz_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rackopt::fuzz::run_writer_fuzz_case(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
