// libFuzzer target over every YAML input path (input_fuzz_case.hpp).
// Built only with -DRACKOPT_FUZZ=ON and clang; run with ./dev.sh fuzz
// (docs/input_limits.md, "Fuzzing"). An input that crashes, trips a
// sanitizer or lets an unexpected exception escape is a bug: add it to
// tests/fuzz/regressions/ so the regular test suite replays it.
#include <cstddef>
#include <cstdint>

#include "input_fuzz_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rackopt::fuzz::run_input_fuzz_case(std::string_view(reinterpret_cast<const char*>(data), size),
                                     RACKOPT_SOURCE_DIR "/studies");
  return 0;
}
