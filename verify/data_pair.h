// Two rules of one source, asked about the same message (docs/checks.md#message-data): exclusive by
// data, or a concrete message both accept, replayed through the runtime's monitors.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "verify/data_query.h"
#include "verify/report.h"
#include "verify/verify.h"

namespace arbc::verify {

struct DataPair {
  enum class Kind {
    NotApplicable,  // different sources, or a body opaque for data (notes say which)
    Exclusive,      // no message is accepted by both: `text` says why
    Overlap,        // `example` is a message both accept (replayed)
    Unknown,        // the solver gave no answer: `text`
    Internal,       // the replay disagrees with Z3: `text`
  };
  Kind kind = Kind::NotApplicable;
  std::string text;
  std::optional<MessageExample> example;
  std::optional<Value> message;  // Overlap: the example's message, when a fresh monitor takes it
  std::vector<Note> notes;
  int queries = 0;
};

DataPair same_message_pair(DataQuery& data, const MonitorRunner* runner, const model::Connection& a,
                           const model::Connection& b);

// "accepts on lines 33, 34 of 'take'": the part of an unsat core that belongs to one rule.
std::string core_lines_text(const std::vector<int>& lines, const std::string& rule);

// Replays `message` through each rule's monitor; each must accept (and, with `emitted`,
// deliver that value). Adds one line per rule to `example`; false and `*why` on a
// disagreement (an internal error).
bool replay_accepts(const model::App& app, const MonitorRunner* runner,
                    const std::vector<const model::Connection*>& rules,
                    const std::vector<Value>& messages, const std::vector<int>& message_of,
                    MessageExample& example, std::string* why);

// An `internal` finding: the runtime's monitors and Z3 disagree on a message.
Finding internal_data_error(const std::string& port, const model::SourceLocation& loc,
                            const std::string& what);

}  // namespace arbc::verify
