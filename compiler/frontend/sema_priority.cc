// `by priority` reserves a name per rule above the lowest: its activity event act_<rule>
// (docs/lowering.md, "by priority"). A declared event of that name would be the same entry in
// the port's container for the user's code and the generated code, so it is an error here, in
// the front end, where `arbc check` reports it (not only when lowering for `build`).
#include "compiler/frontend/sema.h"

namespace arbc::frontend {

void check_activity_names(const ast::Spec& spec, std::vector<Diagnostic>& out) {
  for (const ast::ArbitrateDecl& a : spec.arbitrations) {
    if (!a.by_priority) continue;
    for (size_t k = 0; k + 1 < a.rules.size(); ++k) {
      const ast::Rule& r = a.rules[k];
      std::string activity = ast::activity_event_name(r.name);
      const ast::EventSymbol* clash = spec.find_event(activity);
      if (!clash) continue;
      Diagnostic d;
      d.loc = r.loc;
      d.id = "priority";
      d.message = "rule '" + r.name + "' of " + a.port.qualified() + " needs the activity event '" +
                  activity +
                  "' (by priority), but an event of that name is declared; rename the event "
                  "or the rule";
      Diagnostic note;
      note.severity = Severity::Note;
      note.loc = clash->loc;
      note.message = "'" + activity + "' is declared here";
      d.notes.push_back(std::move(note));
      out.push_back(std::move(d));
    }
  }
}

}  // namespace arbc::frontend
