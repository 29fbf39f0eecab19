#include "compiler/frontend/frontend.h"

#include <algorithm>
#include <tuple>

#include "compiler/frontend/desugar_locks.h"
#include "compiler/frontend/parse.h"
#include "compiler/frontend/ros2_uses.h"
#include "compiler/frontend/sema.h"
#include "compiler/frontend/tests_file.h"

namespace arbc::frontend {

bool CheckResult::ok() const {
  return std::none_of(diagnostics.begin(), diagnostics.end(),
                      [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

namespace {

// By line and column; for a tests file, its own diagnostics before those of the app it names
// (`app_file`, empty for any other spec).
void sort_by_position(std::vector<Diagnostic>& diagnostics, const std::string& app_file) {
  auto key = [&](const Diagnostic& d) {
    return std::make_tuple(!app_file.empty() && d.loc.file == app_file, d.loc.line, d.loc.column);
  };
  std::stable_sort(diagnostics.begin(), diagnostics.end(),
                   [&](const Diagnostic& a, const Diagnostic& b) { return key(a) < key(b); });
  // The same words at the same place once: a lock is two events over one port
  // (desugar_locks.h), and a mistake in that port was said for each.
  auto same = [](const Diagnostic& a, const Diagnostic& b) {
    return a.loc.file == b.loc.file && a.loc.line == b.loc.line && a.loc.column == b.loc.column &&
           a.id == b.id && a.message == b.message;
  };
  diagnostics.erase(std::unique(diagnostics.begin(), diagnostics.end(), same), diagnostics.end());
}

// Editors on Windows may start a UTF-8 file with a byte-order mark: it is not part of the text
// (and, kept, would be an invisible "unexpected character" at 1:1).
std::string_view without_bom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.substr(0, kBom.size()) == kBom) text.remove_prefix(kBom.size());
  return text;
}

}  // namespace

CheckResult check_text(std::string_view text, const std::string& file,
                       const std::string& script_dir, size_t two_thread_bytes) {
  text = without_bom(text);
  CheckResult result;
  result.source = std::string(text);
  ParseResult parsed = parse_spec(text, file, two_thread_bytes);
  result.diagnostics = std::move(parsed.diagnostics);
  if (parsed.spec && parsed.spec->tests_for) {
    parsed.spec = merge_with_app(std::move(parsed.spec), file, result.diagnostics, &result.app_file,
                                 &result.app_source);
    if (!parsed.spec) result.app_file.clear();
  }
  if (parsed.spec) {
    declare_ros2_uses(*parsed.spec, result.diagnostics);
    desugar_locks(*parsed.spec, result.diagnostics);
    // The app's scripts are relative to the app's spec, wherever its tests live.
    check_spec(*parsed.spec, result.diagnostics, result.app_file.empty() ? script_dir : "");
    result.spec = std::move(parsed.spec);
  }
  sort_by_position(result.diagnostics, result.app_file);
  return result;
}

CheckResult check_file(const std::string& path) {
  std::string text;
  Diagnostic problem;
  if (!read_spec_file(path, &text, &problem)) {
    CheckResult result;
    result.diagnostics.push_back(std::move(problem));
    return result;
  }
  return check_text(text, path);
}

std::string render_diagnostics(const std::vector<Diagnostic>& diagnostics, SourceCache* sources,
                               size_t cap) {
  std::string out;
  size_t errors = 0, hidden = 0;
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Error && ++errors > cap) {
      ++hidden;
      continue;
    }
    out += render(d, sources);
  }
  if (hidden > 0)
    out += "... and " + std::to_string(hidden) + " more error" + (hidden == 1 ? "" : "s") +
           " (only the first " + std::to_string(cap) + " are shown)\n";
  return out;
}

}  // namespace arbc::frontend
