// `by priority` reserves a name per rule above the lowest: its activity event act_<rule>
// (docs/lowering.md, "by priority"). A declared event of that name would be the same entry in
// the port's container for the user's code and the generated code, so it is an error here, in
// the front end, where `arbc check` reports it (not only when lowering for `build`).
//
// It also bounds the rules of one `by priority` port. Rule k's constraint reads the activity
// events of the k-1 rules above it, so the model, app.json and the proof grow with the square
// of the rules: 1,000 rules verify in under a second and 200 MB, 4,000 took 15 s and 2.4 GB,
// and 20,000 ended in std::bad_alloc (docs/benchmarks.md#rules-by-priority-issue-40). Past the
// bound the spec is refused with that reason, before lowering builds anything.
#include "compiler/frontend/sema.h"
#include "core/check_ids.h"

namespace arbc::frontend {

namespace {

void check_rule_count(const ast::ArbitrateDecl& a, std::vector<Diagnostic>& out) {
  if (a.rules.size() <= kMaxPriorityRules) return;
  Diagnostic d;
  d.loc = a.loc;
  d.id = diag::Priority.text();
  d.message = a.port.qualified() + " has " + std::to_string(a.rules.size()) +
              " rules by priority; at most " + std::to_string(kMaxPriorityRules) +
              " can be checked: each rule's constraint names the activity event of every "
              "rule above it, so the model grows with the square of the rules";
  Diagnostic note;
  note.severity = Severity::Note;
  note.message =
      "split the rules over several ports, or merge rules that differ only in their `when` "
      "into one rule whose body tells the cases apart";
  d.notes.push_back(std::move(note));
  out.push_back(std::move(d));
}

}  // namespace

void check_activity_names(const ast::Spec& spec, std::vector<Diagnostic>& out) {
  for (const ast::ArbitrateDecl& a : spec.arbitrations) {
    if (!a.by_priority) continue;
    check_rule_count(a, out);
    for (size_t k = 0; k + 1 < a.rules.size(); ++k) {
      const ast::Rule& r = a.rules[k];
      std::string activity = ast::activity_event_name(r.name);
      const ast::EventSymbol* clash = spec.find_event(activity);
      if (!clash) continue;
      Diagnostic d;
      d.loc = r.loc;
      d.id = diag::Priority.text();
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
