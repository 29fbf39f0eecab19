// SHA-256 (FIPS 180-4), for the digests app.json records of its monitor files
// (docs/app-json.md, "Monitor digests") and for the proof record: GNU Nettle's, a maintained
// library Debian ships (nettle-dev), which uses the processor's SHA extensions where it has
// them. It replaced arbc's own implementation, and is no slower:
// docs/benchmarks.md#sha-256-from-nettle-issue-40. sha256_test.cc checks the FIPS vectors.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace arbc {

using Sha256Digest = std::array<uint8_t, 32>;

Sha256Digest sha256(std::string_view bytes);

// The digest as 64 lower-case hexadecimal digits (what `sha256sum` prints).
std::string sha256_hex(std::string_view bytes);

}  // namespace arbc
