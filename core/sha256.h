// SHA-256 (FIPS 180-4), for the digests app.json records of its monitor files
// (docs/app-json.md, "Monitor digests"). Our own few lines rather than a crypto library: the
// digest only has to notice that a file changed since `arbc build` wrote it, the core library
// stays free of dependencies, and sha256_test.cc checks it against the FIPS test vectors.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace arbc {

using Sha256Digest = std::array<uint8_t, 32>;

// Fastest: the processor's SHA extensions where it has them (sha256_blocks.h). Portable: plain
// C++ everywhere; the two give the same digest, which sha256_test.cc checks.
enum class Sha256Path { Fastest, Portable };

Sha256Digest sha256(std::string_view bytes, Sha256Path path = Sha256Path::Fastest);

// The digest as 64 lower-case hexadecimal digits (what `sha256sum` prints).
std::string sha256_hex(std::string_view bytes);

}  // namespace arbc
