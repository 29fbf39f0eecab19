// The front end's public entry point: a spec's text or file -> checked AST + diagnostics.
//
//   arbc::frontend::CheckResult r = arbc::frontend::check_file("specs/table_clean.spec");
//   if (!r.ok()) { print render_diagnostics(r.diagnostics, ...); return 2; }
//   const arbc::ast::Spec& spec = *r.spec;   // every "sema:" field filled (ast.h)
//
// Errors are values: nothing here throws on bad input.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/frontend/ast.h"
#include "compiler/frontend/parse.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

struct CheckResult {
  // The checked AST. Null when the file could not be read or has lexical/syntax errors; when
  // only semantic errors occurred it is present but must not be lowered.
  std::unique_ptr<ast::Spec> spec;
  std::vector<Diagnostic> diagnostics;  // sorted by position
  std::string source;                   // the text that was checked (for quoting lines)
  // A tests file (`tests for`, tests_file.h): `spec` is the app it names with its tests added;
  // these are the app's spec file and text. Empty for any other spec.
  std::string app_file, app_source;

  // True when no diagnostic is an error: the spec may be lowered.
  bool ok() const;
};

// Parses and checks spec text; `file` names it in diagnostics. A tests file is checked with
// the app it names, read from disk. `script_dir` as for check_spec
// (sema.h): where `script` paths are relative to, by default the folder of `file` on disk.
// `two_thread_bytes` as for parse_spec (parse.h); the result does not depend on it, which the
// tests and the fuzz target check by giving 0 (two threads wherever the text can be cut).
CheckResult check_text(std::string_view text, const std::string& file,
                       const std::string& script_dir = "",
                       size_t two_thread_bytes = kTwoThreadParseBytes);

// Reads and checks a spec file. A missing file, a directory, an unreadable or oversized file
// (over kMaxSpecBytes) is a diagnostic with id "io".
CheckResult check_file(const std::string& path);

inline constexpr size_t kMaxSpecBytes = 64u << 20;  // 64 MiB
inline constexpr size_t kMaxReportedErrors = 50;

// `arbc import ros2-msg` (docs/cli.md): the `type` declarations `use ros2` makes for `messages`
// ("pkg/msg/Name", each with every message it uses), as spec text: each after the messages it
// uses, under a comment naming its message. `first`: folders searched before the message path;
// `file` names the input in diagnostics (id "ros2-message"), which go to `diagnostics`.
std::string ros2_types_text(const std::vector<std::string>& messages,
                            const std::vector<std::string>& first, const std::string& file,
                            std::vector<Diagnostic>* diagnostics);

// Renders diagnostics like a compiler, quoting source lines from `sources` (may be null). After
// `cap` errors the rest are counted in one final line instead of printed.
std::string render_diagnostics(const std::vector<Diagnostic>& diagnostics, SourceCache* sources,
                               size_t cap = kMaxReportedErrors);

}  // namespace arbc::frontend
