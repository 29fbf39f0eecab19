// What the server knows about one version of a document: the front end's diagnostics (the
// same as `arbc check`), the checked AST and its symbol index, and the lowered model. A text
// with syntax errors has no AST; navigation then answers from the last version that parsed
// (docs/editors.md#what-the-server-does).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/frontend/ast.h"
#include "compiler/lower/lowered_app.h"
#include "core/diagnostic.h"
#include "lsp/symbol_index.h"

namespace arbc::lsp {

struct Analysis {
  int version = 0;
  std::string text;                     // the text analysed
  std::vector<Diagnostic> diagnostics;  // check_text's
  // From this text when `current`, else from the last version that parsed (maybe none).
  std::shared_ptr<const ast::Spec> spec;
  std::shared_ptr<const SymbolIndex> index;
  std::string index_text;  // the text spec and index locations refer to
  // A tests file (`tests for "app.spec";`): the app's spec, where the app's names are
  // declared (docs/testing.md). Empty for any other document.
  std::string app_file, app_text;
  bool current = false;
  // The last version without errors, lowered (effective guards, decision tables).
  std::shared_ptr<const lower::LoweredApp> lowered;
  bool lowered_current = false;
  double seconds = 0;  // time taken
};

// Checks `text` as `file` (script paths relative to `script_dir`, as `arbc check` does for a
// file on disk) and indexes it, keeping what `previous` (may be null) had where this text does
// not parse. The caller serialises calls with every other parse (ParserGate).
std::shared_ptr<const Analysis> analyze(const std::string& text, int version,
                                        const std::string& file, const std::string& script_dir,
                                        const Analysis* previous);

}  // namespace arbc::lsp
