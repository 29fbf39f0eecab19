#include "compiler/lower/compile_spec.h"

#include <filesystem>

#include "compiler/frontend/frontend.h"
#include "compiler/lower/lower.h"

namespace arbc::lower {

namespace {

// Lowers what the front end checked; appends lowering's own diagnostics.
CompiledSpec finish(frontend::CheckResult checked, const std::string& file,
                    const std::string& script_dir) {
  CompiledSpec out;
  out.sources.add(file, checked.source);
  std::string dir = script_dir;
  if (!checked.app_file.empty()) {  // a tests file: the app is in its own spec
    out.sources.add(checked.app_file, checked.app_source);
    std::filesystem::path parent = std::filesystem::path(checked.app_file).parent_path();
    dir = parent.empty() ? std::filesystem::path(".") : parent;
  }
  bool checked_ok = checked.ok() && checked.spec;  // before the diagnostics move out
  out.diagnostics = std::move(checked.diagnostics);
  if (!checked_ok) return out;
  std::shared_ptr<const ast::Spec> spec(std::move(checked.spec));
  LowerOptions options;
  options.script_dir = dir;
  LowerResult lowered = lower_spec(spec, options);
  for (Diagnostic& d : lowered.diagnostics) out.diagnostics.push_back(std::move(d));
  if (!lowered.ok) return out;
  lowered.lowered->spec_text =
      std::move(checked.app_file.empty() ? checked.source : checked.app_source);
  out.lowered = std::move(lowered.lowered);
  out.ok = true;
  return out;
}

}  // namespace

CompiledSpec compile_spec_text(std::string_view text, const std::string& file,
                               const std::string& script_dir) {
  return finish(frontend::check_text(text, file, script_dir), file, script_dir);
}

CompiledSpec compile_spec(const std::string& path) {
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  return finish(frontend::check_file(path), path, dir.empty() ? "." : dir.string());
}

}  // namespace arbc::lower
