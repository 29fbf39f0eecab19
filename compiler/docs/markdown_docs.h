// index.md for `arbc docs`: the app's description, a modules table like the paper's Table I,
// connections, events, a decision table per arbitrated port, and the verification verdicts.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "compiler/docs/decision_table.h"
#include "core/app_model.h"

namespace arbc::docs {

struct DocsInput {
  const model::App* app = nullptr;
  // What `arbc verify` says of the app, as its text report prints it: every claim (ports,
  // asserts, resources, properties over time) with its verdict, the assumptions and rates each
  // rests on, and the counterexample of each refuted one. Empty when the verifier did not run.
  std::string verification;
  std::string diagram_svg;   // file name of the diagram to embed, e.g. "app.svg"; empty: none
  std::string diagram_note;  // shown instead of the diagram when there is none (why not)
};

std::string render_index_markdown(const DocsInput& input);

// One port's decision table as Markdown: each rule's effective guard, then a row per event
// state (or the guards in DNF when the port has more than kMaxTableEvents events). Shared by
// index.md and the language server's hover.
void decision_table_markdown(const DecisionTable& t, std::ostream& out);

// A Markdown table cell: pipes escaped, newlines folded, so every row keeps its column count.
std::string cell(std::string_view text);

}  // namespace arbc::docs
