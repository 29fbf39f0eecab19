#include "compiler/docs/markdown_docs.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "compiler/docs/decision_table.h"
#include "compiler/docs/event_lifetimes.h"
#include "compiler/docs/monitor_summary.h"
#include "core/artifact_path.h"
#include "core/join.h"

namespace arbc::docs {

std::string cell(std::string_view text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|')
      out += "\\|";
    else if (ch == '\n')
      out += ' ';
    else
      out += ch;
  }
  return out.empty() ? "" : out;
}

namespace {

std::string code(std::string_view text) { return "`" + cell(text) + "`"; }

std::string ports_of(const model::Module& m, model::Direction d) {
  std::string s;
  for (const model::Port& p : m.ports) {
    if (p.direction != d) continue;
    if (!s.empty()) s += ", ";
    s += code(p.name + ": " + (p.type ? p.type->to_string() : "?"));
  }
  return s.empty() ? "-" : s;
}

void modules_section(const model::App& app, std::ostream& out) {
  out << "## Modules\n\n| module | inputs | outputs | description |\n|---|---|---|---|\n";
  for (const model::Module& m : app.modules)
    out << "| " << cell(m.name) << " | " << ports_of(m, model::Direction::In) << " | "
        << ports_of(m, model::Direction::Out) << " | " << cell(m.doc) << " |\n";
  out << "\n";
}

void connections_section(const model::App& app, std::ostream& out) {
  out << "## Connections\n\n"
         "| connection | source | destination | constraint | monitor | written by |\n"
         "|---|---|---|---|---|---|\n";
  for (const model::Connection& c : app.connections)
    out << "| " << cell(c.name) << " | " << cell(c.source) << " | " << cell(c.destination) << " | "
        << code(c.constraint.to_string()) << " | " << cell(monitor_summary(c)) << " | "
        << (c.generated ? "arbc" : "user") << " |\n";
  out << "\n";
}

void events_section(const model::App& app, std::ostream& out) {
  std::map<std::string, std::set<std::string>> set_by, read_by;
  std::set<std::string> activity;     // `by priority`: set by the runtime as the rule delivers
  std::set<std::string> on_delivery;  // `then set`: likewise
  for (const model::Connection& c : app.connections) {
    for (const std::string& e : c.sets) set_by[e].insert(c.destination + " / " + c.name);
    if (!c.activity_event.empty()) activity.insert(c.activity_event);
    on_delivery.insert(c.delivery_sets.begin(), c.delivery_sets.end());
    std::set<std::string> read;
    c.constraint.collect_events(read);
    for (const std::string& e : read) read_by[e].insert(c.destination + " / " + c.name);
  }
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    for (const model::Assertion& a : p.asserts) {
      std::set<std::string> read;
      a.property.collect_events(read);
      for (const std::string& e : read) read_by[e].insert(p.port + " / assert " + a.rule);
    }
  }
  auto cells = [](const std::set<std::string>& items) {
    std::vector<std::string> out;
    for (const std::string& i : items) out.push_back(cell(i));
    return out.empty() ? std::string("-") : join(out);
  };
  out << "## Events\n\n| event | source | lifetime | set by | read by |\n|---|---|---|---|---|\n";
  for (const model::Event& e : app.events)
    out << "| " << code(e.name) << " | "
        << (!e.source.empty()           ? cell(e.source)
            : activity.count(e.name)    ? "each delivery (by priority)"
            : on_delivery.count(e.name) ? "each delivery (`then set`)"
                                        : "monitor code")
        << " | " << cell(event_lifetime_cell(e, app)) << " | " << cells(set_by[e.name]) << " | "
        << cells(read_by[e.name]) << " |\n";
  out << "\n";
}

void decision_section(const model::App& app, std::ostream& out) {
  if (app.arbitrated_ports.empty()) return;
  // One pass over the connections: looking them up per port would be quadratic.
  std::map<std::string, std::vector<const model::Connection*>, std::less<>> into;
  for (const model::Connection& c : app.connections) into[c.destination].push_back(&c);
  out << "## Arbitrated ports\n\n"
         "Each rule is compared by its effective guard: its constraint plus the events its own\n"
         "monitor sets on every accepting path.\n\n";
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    DecisionTable t = decision_table(p, into[p.port]);
    out << "### " << p.port;
    if (p.by_priority) out << " (by priority)";
    if (p.complete) out << " (complete)";
    out << "\n\n";
    decision_table_markdown(t, out);
    out << "\n";
    if (p.by_priority) {
      // What the proof of a `by priority` port says (docs/design.md#priorities-and-holds): the
      // table's rows are single decisions, and a higher rule's hold starts when it delivers.
      out << "Under `by priority` a rule's activity event is set as it delivers, for its hold:\n"
             "after each delivery no rule below it is selected until the hold ends. Before\n"
             "that, in one state, a lower rule may deliver and a higher one right after it.\n\n";
    }
    bool effects = std::any_of(into[p.port].begin(), into[p.port].end(), [](const auto* c) {
      return !c->delivery_sets.empty() || !c->delivery_unsets.empty();
    });
    if (effects) {
      out << "Rules with `then set` / `then unset` change these events as they deliver, before\n"
             "the next decision: two rules that hold in one row may still keep each other out\n"
             "(`arbc verify` lists such pairs as exclusive by delivery).\n\n";
    }
  }
}

}  // namespace

void decision_table_markdown(const DecisionTable& t, std::ostream& out) {
  out << "| rule | effective guard |\n|---|---|\n";
  for (const RuleGuard& r : t.rules)
    out << "| " << cell(r.rule) << " | " << code(r.guard) << " |\n";
  out << "\n";
  if (!t.tabulated) {
    out << "With " << t.events.size() << " events (more than " << kMaxTableEvents
        << "), the guards in disjunctive normal form:\n\n| rule | guard (DNF) |\n|---|---|\n";
    for (const RuleGuard& r : t.rules)
      out << "| " << cell(r.rule) << " | " << code(r.dnf) << " |\n";
    return;
  }
  out << "|";
  for (const std::string& e : t.events) out << " " << cell(e) << " |";
  out << " selects |\n|";
  for (size_t i = 0; i <= t.events.size(); ++i) out << "---|";
  out << "\n";
  for (const DecisionRow& row : t.rows) {
    out << "|";
    for (bool present : row.present) out << (present ? " 1 |" : " 0 |");
    std::string selected = join(row.selected);
    if (row.selected.size() > 1) selected = "**" + selected + "** (conflict)";
    out << " " << (selected.empty() ? "-" : selected) << " |\n";
  }
}

std::string render_index_markdown(const DocsInput& input) {
  const model::App& app = *input.app;
  std::ostringstream out;
  out << "# " << app.name << "\n\n";
  if (!app.description.empty()) out << app.description << "\n\n";
  if (!app.spec_file.empty())
    out << "Generated by `arbc docs` from `" << artifact_path(app.spec_file)
        << "`; do not edit by hand.\n\n";
  if (!input.diagram_svg.empty()) out << "![" << app.name << "](" << input.diagram_svg << ")\n\n";
  if (!input.diagram_note.empty()) out << input.diagram_note << "\n\n";
  modules_section(app, out);
  connections_section(app, out);
  events_section(app, out);
  decision_section(app, out);
  if (!input.verification.empty()) {
    // The verifier's own words, not a summary of them: a summary said "proved" for every port
    // of an app whose resource was refuted (issue 39).
    out << "## Verification\n\nWhat `arbc verify` says of this app: every claim with its verdict, "
           "and what each rests on.\n\n```text\n"
        << input.verification << "```\n";
  }
  return out.str();
}

}  // namespace arbc::docs
