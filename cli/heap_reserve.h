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
// the range is reused rather than returned). With `will_prove` (the command creates a Z3
// context), the range is at least large enough for the context and blocks of up to 16 MiB keep
// coming from it rather than from mmap: a Z3 context allocates two 8.5 MB hash tables and
// writes every 16th byte of them, ~4,300 page faults with 4 KiB pages, two thirds of a small
// `arbc verify` (docs/benchmarks.md#start-up-and-the-front-end-issue-21). Best effort: any
// failure leaves the heap as it was. It changes malloc's settings for the whole process, so
// only main() calls it; a cheap no-op for small specs that are not proved.
void reserve_heap_for_spec(size_t spec_bytes, bool will_prove);

// The total size of the regular files among a command's arguments: what it will parse at most.
size_t input_file_bytes(std::span<char*> args);

}  // namespace arbc::cli
