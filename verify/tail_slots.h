// How many stand-ins past the capacity each list of a source's message gets (SymValue::tail):
// one per read that scans a whole list (min_by, max_by, min and max of a list) in the bodies
// of the rules reading that source, so that those reads are exact for lists of any length
// (docs/checks.md#lists-of-any-length). A read inside a lambda runs once per element and would need
// as many slots: it is not counted, and the encodings that make it assume the list bound.
#pragma once

#include <string>

#include "core/app_model.h"

namespace arbc::verify {

// At most this many slots per list: each one is a whole element of constants.
inline constexpr int kMaxTailSlots = 4;

// The scanning reads outside lambdas in `body`.
int scanning_reads(const model::Body& body);

// The slots for lists of `source`'s message: the scanning reads of the rules reading it,
// at most kMaxTailSlots.
int tail_slots(const model::App& app, const std::string& source);

}  // namespace arbc::verify
