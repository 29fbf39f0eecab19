#include "core/sha256.h"

#include <nettle/sha2.h>

namespace arbc {

Sha256Digest sha256(std::string_view bytes) {
  sha256_ctx ctx;
  sha256_init(&ctx);
  sha256_update(&ctx, bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data()));
  Sha256Digest out;
  sha256_digest(&ctx, out.size(), out.data());
  return out;
}

std::string sha256_hex(std::string_view bytes) {
  static const char kDigits[] = "0123456789abcdef";
  std::string out;
  for (uint8_t b : sha256(bytes)) {
    out += kDigits[b >> 4];
    out += kDigits[b & 15];
  }
  return out;
}

}  // namespace arbc
