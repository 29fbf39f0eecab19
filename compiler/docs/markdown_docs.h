// index.md for `arbc docs`: the app's description, a modules table like the paper's Table I,
// connections, events, a decision table per arbitrated port, and the verification verdicts.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::docs {

struct DocsInput {
  const model::App* app = nullptr;
  // One line per verified port ("PickAndPlace.cmd: proved, 2 rules, 3 events"), or findings.
  // Empty when the verifier did not run.
  std::vector<std::string> verdicts;
  std::string diagram_svg;   // file name of the diagram to embed, e.g. "app.svg"; empty: none
  std::string diagram_note;  // shown instead of the diagram when there is none (why not)
};

std::string render_index_markdown(const DocsInput& input);

// A Markdown table cell: pipes escaped, newlines folded, so every row keeps its column count.
std::string cell(std::string_view text);

}  // namespace arbc::docs
