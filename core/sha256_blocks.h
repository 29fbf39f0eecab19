// The SHA-256 compression function over whole 64-byte blocks, in two ways: portable C++ and
// the x86 SHA extensions. `arbc build` hashes every monitor it writes (10,050 files, 12 MB on
// the 10,000-rule benchmark), and the portable loop took 8 % of the build's instructions;
// the SHA extensions do the same work in a fraction of the time (docs/benchmarks.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace arbc::sha256_detail {

using State = std::array<uint32_t, 8>;

// The round constants K (FIPS 180-4, 4.2.2), aligned to load four at a time.
alignas(16) extern const uint32_t kRound[64];

// FIPS 180-4, 6.2.2, for each of `blocks` consecutive 64-byte blocks at `data`.
void compress_portable(State& h, const uint8_t* data, size_t blocks);

// The same with the SHA extensions; only where sha_extensions_available().
void compress_sha_extensions(State& h, const uint8_t* data, size_t blocks);

// Whether this processor has the SHA extensions (and the SSSE3 and SSE4.1 they are used with).
bool sha_extensions_available();

}  // namespace arbc::sha256_detail
