// A tests file: `tests for "app.spec";` and `test` declarations only, kept apart from the app's
// spec (docs/testing.md, "Tests in their own file"). The front end checks its tests against the
// app as if they were written in the app's spec; every location still names the tests file.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/frontend/ast.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

// The app's spec that `tests` (a parsed tests file named `file`) names, parsed from disk, with
// the tests file's `test` declarations in place of the app's own; not yet checked. Null, with
// diagnostics in `out`, when the tests file declares anything but tests, or the app cannot be read
// or parsed. `app_file` and `app_text` receive the app spec's path and text (to quote its lines).
std::unique_ptr<ast::Spec> merge_with_app(std::unique_ptr<ast::Spec> tests, const std::string& file,
                                          std::vector<Diagnostic>& out, std::string* app_file,
                                          std::string* app_text);

// Reads a spec file's text. False, with an "io" diagnostic in `problem`, when the path is
// missing, a directory, unreadable or larger than kMaxSpecBytes.
bool read_spec_file(const std::string& path, std::string* text, Diagnostic* problem);

}  // namespace arbc::frontend
