#include "lsp/analysis.h"

#include <chrono>

#include "compiler/frontend/frontend.h"
#include "compiler/lower/lower.h"

namespace arbc::lsp {

std::shared_ptr<const Analysis> analyze(const std::string& text, int version,
                                        const std::string& file, const std::string& script_dir,
                                        const Analysis* previous) {
  auto start = std::chrono::steady_clock::now();
  auto a = std::make_shared<Analysis>();
  a->version = version;
  a->text = text;
  frontend::CheckResult check = frontend::check_text(text, file, script_dir);
  bool ok = check.ok();  // before the diagnostics move out
  a->diagnostics = std::move(check.diagnostics);
  if (check.spec) {
    std::shared_ptr<const ast::Spec> spec = std::move(check.spec);
    a->spec = spec;
    a->index = build_index(*spec, file);
    a->index_text = text;
    a->app_file = std::move(check.app_file);
    a->app_text = std::move(check.app_source);
    a->current = true;
    if (ok) {
      lower::LowerOptions options;
      if (!script_dir.empty()) options.script_dir = script_dir;
      lower::LowerResult lowered = lower::lower_spec(spec, options);
      // Lowering's own errors (a test's event state over several containers) are `arbc
      // check`'s too (lower::compile_spec): the editor shows what the command line says.
      for (Diagnostic& d : lowered.diagnostics) a->diagnostics.push_back(std::move(d));
      if (lowered.ok) {
        a->lowered = std::move(lowered.lowered);
        a->lowered_current = true;
      }
    }
  } else if (previous) {
    a->spec = previous->spec;
    a->index = previous->index;
    a->index_text = previous->index_text;
    a->app_file = previous->app_file;
    a->app_text = previous->app_text;
  }
  if (!a->lowered && previous) a->lowered = previous->lowered;
  a->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return a;
}

}  // namespace arbc::lsp
