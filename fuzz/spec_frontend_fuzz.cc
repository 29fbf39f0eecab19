// Fuzzes the spec front end: UTF-8 validation, lexing, parsing, AST building and the semantic
// checks (frontend::check_text), then renders the diagnostics as `arbc check` does.
// Invariants checked (a violation aborts, so the fuzzer records it):
//  - nothing throws and nothing overflows the stack (ASan reports it), whatever the bytes;
//  - a spec with no AST has an error that says why; a result that is "ok" has an AST;
//  - every diagnostic has a message and a check id and points into the text (line 1 to the
//    line after the last, column 0 or more) or at the whole file (line 0, column 0);
//  - checking the same text twice renders the same diagnostics (no hidden state).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "compiler/frontend/frontend.h"

namespace {

const std::string kFile = "fuzz.spec";

bool points_into(const arbc::Diagnostic& d, int lines) {
  if (d.message.empty()) return false;
  if (d.loc.line == 0) return d.loc.column == 0;  // about the whole file ("the spec is empty")
  if (d.loc.line < 0 || d.loc.line > lines + 1 || d.loc.column < 0) return false;
  return std::all_of(d.notes.begin(), d.notes.end(),
                     [](const arbc::Diagnostic& note) { return !note.message.empty(); });
}

std::string render(const arbc::frontend::CheckResult& result) {
  arbc::SourceCache sources;
  sources.add(kFile, result.source);
  return arbc::frontend::render_diagnostics(result.diagnostics, &sources);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  arbc::frontend::CheckResult result = arbc::frontend::check_text(text, kFile);
  if (!result.spec && result.ok()) std::abort();
  const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
  for (const arbc::Diagnostic& d : result.diagnostics) {
    if (d.id.empty() || !points_into(d, lines)) std::abort();
  }
  std::string first = render(result);
  if (!result.diagnostics.empty() && first.empty()) std::abort();
  if (render(arbc::frontend::check_text(text, kFile)) != first) std::abort();
  return 0;
}
