// Verification on save: the spec's text lowered and proved as `arbc verify` does; each
// finding becomes a diagnostic, and each conflict between rules (two rules of a port selected
// in one event state, or a resource two rules both use) one diagnostic on every rule it
// involves, each rule found by its port and name; a counterexample with its event state.
#pragma once

#include <string>

#include "lsp/document_store.h"
#include "lsp/parser_gate.h"

namespace arbc::lsp {

// `timeout_seconds` bounds the solver for the whole app (as `arbc verify --timeout`).
Verification verify_text(const std::string& text, int version, const std::string& file,
                         const std::string& script_dir, ParserGate& gate, double timeout_seconds);

}  // namespace arbc::lsp
