// Fuzzes the two-thread parse of large specs (compiler/frontend/parse_halves.h) against the
// one-thread parse. arbc parses in two halves only from kTwoThreadParseBytes up, far above what
// a fuzzer feeds; here every input that can be cut is parsed in two halves, whatever its size.
// Invariants checked (a violation aborts, so the fuzzer records it):
//  - the two parses render the same diagnostics, in the same order;
//  - either both give an AST or neither does;
//  - a spec that checks lowers to the same app.json and the same monitors' Lua either way.
// Separate from spec_frontend_fuzz because each input costs about four times as much here (two
// threads whose DFA caches start cold, lowering and code generation).
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "compiler/codegen/monitor_writer.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/lower.h"
#include "core/app_json.h"

namespace {

const std::string kFile = "fuzz.spec";
constexpr size_t kOneThread = SIZE_MAX;
constexpr size_t kTwoThreadsWhereverItCuts = 0;

std::string render(const arbc::frontend::CheckResult& result) {
  arbc::SourceCache sources;
  sources.add(kFile, result.source);
  return arbc::frontend::render_diagnostics(result.diagnostics, &sources);
}

// What a spec that checks compiles to: app.json and every monitor's Lua, or lowering's
// diagnostics; empty for a spec that does not check.
std::string compiled(arbc::frontend::CheckResult result, std::string_view text) {
  if (!result.ok() || !result.spec) return "";
  arbc::lower::LowerResult lowered =
      arbc::lower::lower_spec(std::shared_ptr<const arbc::ast::Spec>(std::move(result.spec)));
  if (!lowered.ok) return arbc::frontend::render_diagnostics(lowered.diagnostics, nullptr);
  std::string out = arbc::model::to_app_json(lowered.lowered->app);
  arbc::codegen::SpecLines lines(text);
  for (const auto& plan : lowered.lowered->monitors)
    out += arbc::codegen::write_monitor(*lowered.lowered, plan, lines).text;
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  arbc::frontend::CheckResult one = arbc::frontend::check_text(text, kFile, "", kOneThread);
  arbc::frontend::CheckResult two =
      arbc::frontend::check_text(text, kFile, "", kTwoThreadsWhereverItCuts);
  if (render(two) != render(one)) std::abort();
  if (!two.spec != !one.spec) std::abort();
  if (compiled(std::move(two), text) != compiled(std::move(one), text)) std::abort();
  return 0;
}
