#include "compiler/lower/compile_spec.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/frontend/parse.h"
#include "compiler/frontend/sema.h"
#include "compiler/lower/lower.h"

namespace arbc::lower {

namespace {

bool has_error(const std::vector<Diagnostic>& ds) {
  return std::any_of(ds.begin(), ds.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

void sort_by_location(std::vector<Diagnostic>& ds) {
  std::stable_sort(ds.begin(), ds.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.loc.line, a.loc.column) < std::tie(b.loc.line, b.loc.column);
  });
}

}  // namespace

CompiledSpec compile_spec_text(std::string_view text, const std::string& file,
                               const std::string& script_dir) {
  CompiledSpec out;
  out.sources.add(file, std::string(text));
  frontend::ParseResult parsed = frontend::parse_spec(text, file);
  out.diagnostics = std::move(parsed.diagnostics);
  if (!parsed.spec || has_error(out.diagnostics)) {
    sort_by_location(out.diagnostics);
    return out;
  }
  frontend::check_spec(*parsed.spec, out.diagnostics);
  sort_by_location(out.diagnostics);
  if (has_error(out.diagnostics)) return out;

  std::shared_ptr<const ast::Spec> spec(std::move(parsed.spec));
  LowerOptions options;
  options.script_dir = script_dir;
  LowerResult lowered = lower_spec(spec, options);
  for (Diagnostic& d : lowered.diagnostics) out.diagnostics.push_back(std::move(d));
  if (!lowered.ok) return out;
  lowered.lowered->spec_text = std::string(text);
  out.lowered = std::move(lowered.lowered);
  out.ok = true;
  return out;
}

CompiledSpec compile_spec(const std::string& path) {
  std::error_code ec;
  bool is_dir = std::filesystem::is_directory(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (!in || is_dir) {
    CompiledSpec out;
    Diagnostic d;
    d.loc.file = path;
    d.id = "io";
    d.message = "cannot read the spec: " +
                std::string(is_dir ? "it is a directory" : std::strerror(errno)) +
                "; check the path (specs live in specs/*.spec)";
    out.diagnostics.push_back(std::move(d));
    return out;
  }
  std::ostringstream text;
  text << in.rdbuf();
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  return compile_spec_text(text.str(), path, dir.empty() ? "." : dir.string());
}

}  // namespace arbc::lower
