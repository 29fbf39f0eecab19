// Semantic checks of properties over time (docs/language.md#properties-over-time): the rule a
// property names exists and is unambiguous, and its window is a positive duration.
#include <string>
#include <vector>

#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

void Sema::check_never(NeverDecl& n) {
  check_duration(n.window, "the `within` window");
  std::vector<const Rule*> found;
  std::vector<std::string> all;
  for (const ArbitrateDecl& a : spec_.arbitrations) {
    for (const Rule& r : a.rules) {
      all.push_back(r.name);
      if (r.name == n.rule) found.push_back(&r);
    }
  }
  if (found.empty()) {
    unknown(n.rule_loc, "no rule is named '" + n.rule + "'", "unknown-rule", n.rule, all);
    return;
  }
  if (found.size() > 1) {
    // Rule names are per port; a property over time must say which rule it is about.
    error(n.rule_loc,
          "rule name '" + n.rule + "' is used by " + std::to_string(found.size()) +
              " ports; a `never` property can name only a rule whose name is unique: rename one",
          "temporal-rule");
    return;
  }
  n.rule_decl = found.front();
}

}  // namespace arbc::frontend
