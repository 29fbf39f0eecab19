// Backs the heap with transparent huge pages before a large spec is parsed.
//
// Why: on this project's virtual machines a page fault costs microseconds, and the ANTLR token
// stream, parse trees and AST of a large spec touch ~100 bytes of fresh heap per byte of
// input. With 4 KiB pages, page faults were half of `arbc check`'s time on a 10,000-rule spec;
// with 2 MiB pages they vanish (measured: 850 ms -> 390 ms CPU, docs/benchmarks.md).
#pragma once

#include <cstddef>
#include <span>

namespace arbc::cli {

// For specs above a threshold, grows the malloc heap once by an estimate of what parsing
// `spec_bytes` needs, marks that range MADV_HUGEPAGE and keeps it (trimming is disabled so
// the range is reused rather than returned). Best effort: any failure leaves the heap as it
// was. It changes malloc's settings for the whole process, so only main() calls it; a cheap
// no-op for small specs.
void reserve_heap_for_spec(size_t spec_bytes);

// The total size of the regular files among a command's arguments: what it will parse at most.
size_t input_file_bytes(std::span<char*> args);

}  // namespace arbc::cli
