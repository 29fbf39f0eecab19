// Diagrams of an application, drawn like the paper's figures: modules as boxes, an arbitrator
// mark on arbitrated ports, a monitor mark (M) on monitored connections, event feeds dashed.
#pragma once

#include <string>

#include "core/app_model.h"

namespace arbc::docs {

std::string render_dot(const model::App& app);      // Graphviz
std::string render_mermaid(const model::App& app);  // renders on code-hosting pages

// Runs Graphviz `dot -Tsvg` on `dot_text`. On failure returns false and says why in *error
// (e.g. Graphviz is not installed, and how to install it).
bool render_svg(const std::string& dot_text, std::string* svg, std::string* error);

}  // namespace arbc::docs
