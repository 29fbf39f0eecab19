// Fuzzes the constraint compiler: parse, print, re-parse, compile, evaluate.
// Invariants checked (a violation aborts, so the fuzzer records it):
//  - printing then re-parsing gives the same tree;
//  - the compiled evaluator agrees with the tree walk on a few event states.
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string_view>

#include "core/compiled_constraint.h"
#include "core/constraint.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  arbc::ConstraintParse parsed = arbc::parse_constraint(text);
  if (!parsed.ok) {
    if (parsed.offset > size) std::abort();
    return 0;
  }
  arbc::ConstraintParse again = arbc::parse_constraint(parsed.constraint.to_string());
  if (!again.ok || !(again.constraint == parsed.constraint)) std::abort();

  arbc::EventIndex index;
  arbc::CompiledConstraint compiled = arbc::CompiledConstraint::compile(parsed.constraint, index);
  // States drawn from the input bytes: event i present iff bit i of a byte is set.
  for (size_t round = 0; round < 4; ++round) {
    arbc::EventMask mask;
    std::set<std::string> present;
    for (int i = 0; i < index.size(); ++i) {
      uint8_t byte = size ? data[(i + round * 7) % size] : 0;
      if ((byte >> (i % 8)) & 1) {
        mask.set(i);
        present.insert(index.name(i));
      }
    }
    if (compiled.evaluate(mask) != arbc::evaluate(parsed.constraint, present)) std::abort();
  }
  return 0;
}
