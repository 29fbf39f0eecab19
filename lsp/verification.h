// Verification on save: the spec's text lowered and proved as `arbc verify` does; each
// finding becomes a diagnostic, and each conflict between rules (two rules of a port selected
// in one event state, or a resource two rules both use) one diagnostic on every rule it
// involves, each rule found by its port and name; a counterexample with its event state. An
// assert that can fail is shown on its rule too; a property over time that is violated or
// undecided is shown at the property, with its trace.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "compiler/lower/lowered_app.h"
#include "lsp/document_store.h"
#include "lsp/parser_gate.h"
#include "verify/verify.h"

namespace arbc::lsp {

// What replays counterexamples as `arbc verify` does: message data through the Lua monitors,
// runs over time on the runtime. Both live outside this library, so `arbc lsp` supplies them.
// Without a test replayer a violation over time found in the model stays unknown.
struct Replayers {
  std::unique_ptr<verify::MonitorRunner> monitors;
  std::unique_ptr<verify::TestReplayer> runs;
};
using MakeReplayers = std::function<Replayers(std::shared_ptr<const lower::LoweredApp>)>;

// `timeout_seconds` bounds the solver for the whole app (as `arbc verify --timeout`).
// `make_replayers` may be empty: no replays.
Verification verify_text(const std::string& text, int version, const std::string& file,
                         const std::string& script_dir, ParserGate& gate, double timeout_seconds,
                         const MakeReplayers& make_replayers = {});

}  // namespace arbc::lsp
