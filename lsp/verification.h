// Verification on save: the spec's text lowered and proved as `arbc verify` does; each
// finding becomes a diagnostic, and each counterexample one diagnostic on every rule it
// involves, with the event state in which they conflict.
#pragma once

#include <string>

#include "lsp/document_store.h"
#include "lsp/parser_gate.h"

namespace arbc::lsp {

// `timeout_seconds` bounds the solver for the whole app (as `arbc verify --timeout`).
Verification verify_text(const std::string& text, int version, const std::string& file,
                         const std::string& script_dir, ParserGate& gate, double timeout_seconds);

}  // namespace arbc::lsp
