#include "core/sha256_blocks.h"

#if defined(__x86_64__)
#include <cpuid.h>
#include <immintrin.h>
#endif

namespace arbc::sha256_detail {

#if defined(__x86_64__)

bool sha_extensions_available() {
  unsigned eax, ebx, ecx, edx;
  if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) return false;
  bool ssse3 = ecx & (1u << 9), sse41 = ecx & (1u << 19);
  if (!__get_cpuid_count(7, 0, &eax, &ebx, &ecx, &edx)) return false;
  bool sha = ebx & (1u << 29);
  return ssse3 && sse41 && sha;
}

// sha256rnds2 does two rounds on the working variables split as {A, B, E, F} and {C, D, G, H}
// (A and C in the top lanes); sha256msg1 and sha256msg2 extend the message schedule four words
// at a time.
__attribute__((target("sha,sse4.1,ssse3"))) void compress_sha_extensions(State& h,
                                                                         const uint8_t* data,
                                                                         size_t blocks) {
  // Each message word is big-endian: reverse the bytes of every 32-bit lane.
  const __m128i byte_swap = _mm_set_epi64x(0x0c0d0e0f08090a0bULL, 0x0405060700010203ULL);
  __m128i abcd = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&h[0]));  // lanes A B C D
  __m128i efgh = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&h[4]));  // lanes E F G H
  abcd = _mm_shuffle_epi32(abcd, 0xB1);                                     // B A D C
  efgh = _mm_shuffle_epi32(efgh, 0x1B);                                     // H G F E
  __m128i abef = _mm_alignr_epi8(abcd, efgh, 8);                            // F E B A
  __m128i cdgh = _mm_blend_epi16(efgh, abcd, 0xF0);                         // H G D C

  for (size_t block = 0; block < blocks; ++block, data += 64) {
    const __m128i abef_before = abef, cdgh_before = cdgh;
    __m128i w[4];  // w[i % 4]: schedule words 4i .. 4i+3
    for (int i = 0; i < 16; ++i) {
      __m128i& words = w[i % 4];
      if (i < 4) {
        words = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(data + 16 * i)),
                                 byte_swap);
      } else {
        // W[t] = s1(W[t-2]) + W[t-7] + s0(W[t-15]) + W[t-16] for t = 4i .. 4i+3.
        const __m128i& last = w[(i + 3) % 4];
        __m128i with_s0 = _mm_sha256msg1_epu32(words, w[(i + 1) % 4]);
        __m128i with_w7 = _mm_add_epi32(with_s0, _mm_alignr_epi8(last, w[(i + 2) % 4], 4));
        words = _mm_sha256msg2_epu32(with_w7, last);
      }
      __m128i wk =
          _mm_add_epi32(words, _mm_load_si128(reinterpret_cast<const __m128i*>(&kRound[4 * i])));
      cdgh = _mm_sha256rnds2_epu32(cdgh, abef, wk);
      abef = _mm_sha256rnds2_epu32(abef, cdgh, _mm_shuffle_epi32(wk, 0x0E));
    }
    abef = _mm_add_epi32(abef, abef_before);
    cdgh = _mm_add_epi32(cdgh, cdgh_before);
  }

  __m128i abef_in_order = _mm_shuffle_epi32(abef, 0x1B);  // A B E F
  __m128i ghcd = _mm_shuffle_epi32(cdgh, 0xB1);           // G H C D
  abcd = _mm_blend_epi16(abef_in_order, ghcd, 0xF0);      // A B C D
  efgh = _mm_alignr_epi8(ghcd, abef_in_order, 8);         // E F G H
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&h[0]), abcd);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&h[4]), efgh);
}

#else

bool sha_extensions_available() { return false; }
void compress_sha_extensions(State& h, const uint8_t* data, size_t blocks) {
  compress_portable(h, data, blocks);
}

#endif

}  // namespace arbc::sha256_detail
