#include "cli/heap_reserve.h"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace arbc::cli {

namespace {

constexpr size_t kThreshold = 256u << 10;  // smaller specs parse in milliseconds anyway
constexpr size_t kBytesPerSpecByte = 128;  // measured peak heap / spec size, rounded up
constexpr size_t kMaxReserve = 2048u << 20;
constexpr size_t kHugePage = 2u << 20;
// A Z3 4.8 context: two ast_managers (the second for pretty-printing), each with a 8.5 MB
// table, plus what a small proof allocates; the larger blocks must come from the heap.
constexpr size_t kSolverReserve = 24u << 20;
constexpr size_t kSolverMmapThreshold = 16u << 20;

bool reserved = false;

}  // namespace

void reserve_heap_for_spec(size_t spec_bytes, bool will_prove) {
  if (reserved || (spec_bytes < kThreshold && !will_prove)) return;
  reserved = true;
  size_t want = spec_bytes * kBytesPerSpecByte;
  if (want / kBytesPerSpecByte != spec_bytes || want > kMaxReserve) want = kMaxReserve;
  if (will_prove && want < kSolverReserve) want = kSolverReserve;
  // Keep freed memory in the heap, and serve this one block from the heap (brk), not mmap.
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(kMaxReserve));
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMaxReserve));
  void* block = std::malloc(want);
  // Later allocations: glibc's default threshold, or the solver's tables from the heap.
  mallopt(M_MMAP_THRESHOLD, will_prove ? static_cast<int>(kSolverMmapThreshold) : 128 * 1024);
  if (!block) return;
  uintptr_t start = (reinterpret_cast<uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
  uintptr_t end = (reinterpret_cast<uintptr_t>(block) + want) & ~(kHugePage - 1);
  if (end > start) madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);
  std::free(block);  // back into the heap's top chunk, marked for huge pages
}

size_t input_file_bytes(std::span<char*> args) {
  size_t total = 0;
  for (const char* arg : args) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(arg, ec)) {
      uintmax_t size = std::filesystem::file_size(arg, ec);
      if (!ec) total += static_cast<size_t>(size);
    }
  }
  return total;
}

}  // namespace arbc::cli
