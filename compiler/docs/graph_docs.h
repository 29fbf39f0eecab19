// Diagrams of an application, drawn like the paper's figures: modules as boxes, one box per
// arbitrated port naming the port and listing its rules in order (highest first under
// `by priority`) with each rule's `when` and hold, and the event feeds arbc generates into it
// (dashed). Rules and feeds are rows of that box, so edges need no labels: nothing for an
// arrowhead to cover. Graphviz lays the graph out left to right (sources, arbitrators,
// destinations); feed edges do not constrain the layout, so a module's status feeding back
// into its own arbitrator does not push the drawing wider.
#pragma once

#include <cstddef>
#include <string>

#include "core/app_model.h"

namespace arbc::docs {

// Above this many modules, arbitrated ports and connections together, `arbc docs` draws no
// diagram: Graphviz needs minutes for tens of thousands of nodes, and no one reads such a
// drawing. (table_clean has 8 + 4 + 14.)
inline constexpr size_t kMaxDiagramElements = 2000;

size_t diagram_elements(const model::App& app);

std::string render_dot(const model::App& app);      // Graphviz
std::string render_mermaid(const model::App& app);  // renders on code-hosting pages

// Runs Graphviz `dot -Tsvg` on `dot_text`. On failure returns false and says why in *error
// (e.g. Graphviz is not installed, and how to install it).
bool render_svg(const std::string& dot_text, std::string* svg, std::string* error);

}  // namespace arbc::docs
