// FNV-1a, 64 bit (Fowler, Noll, Vo): the hash of the evaluation store's index
// keys and of the study fingerprint.
#pragma once

#include <cstdint>
#include <string_view>

namespace rackopt {

// The published 64-bit offset basis.
inline constexpr std::uint64_t kFnv1aOffsetBasis = 14695981039346656037ull;

// The basis the study fingerprint has always used (the published one with a
// digit lost). Fingerprints stored in existing evaluations.sqlite files were
// made with it, so the fingerprint keeps it: changing it would make every
// stored study look like another one and refuse --resume.
inline constexpr std::uint64_t kStudyFingerprintBasis = 1469598103934665603ull;

// FNV-1a of `bytes` starting from `basis`.
constexpr std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t basis = kFnv1aOffsetBasis) {
  std::uint64_t h = basis;
  for (char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace rackopt
