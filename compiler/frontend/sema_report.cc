// Sema's reporting: errors, unknown names with "did you mean", unknown events with what to
// declare, and type mismatches that name the stray field (the other sema_*.cc files report
// through these).
#include <optional>
#include <string>

#include "compiler/frontend/field_mismatch.h"
#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/stray_field.h"
#include "compiler/frontend/type_rules.h"
#include "compiler/frontend/value_fit.h"
#include "core/suggest.h"

namespace arbc::frontend {

using namespace ast;

namespace {

bool same_place(const Loc& a, const Loc& b) {
  return a.file == b.file && a.line == b.line && a.column == b.column;
}

}  // namespace

Diagnostic& Sema::error(const Loc& loc, std::string message, DiagId id) {
  Diagnostic d;
  d.loc = loc;
  d.message = std::move(message);
  d.id = id.text();
  out_.push_back(std::move(d));
  return out_.back();
}

Diagnostic& Sema::unknown(const Loc& loc, std::string message, DiagId id, const std::string& name,
                          const std::vector<std::string>& candidates) {
  Diagnostic& d = error(loc, std::move(message), std::move(id));
  if (auto best = closest_name(name, candidates)) did_you_mean(d, *best);
  return d;
}

// `act_face_neck` read outside the port of rule face_neck: an activity event is an entry of
// its own port's container only, and declaring it would clash with the rule's (sema_priority).
// What the rule reacts to is what another port can read, through a derived event.
static std::optional<std::string> activity_elsewhere(const Spec& spec, const std::string& name) {
  if (name.rfind("act_", 0) != 0) return std::nullopt;
  for (const ArbitrateDecl& a : spec.arbitrations) {
    if (!a.by_priority) continue;
    for (size_t k = 0; k + 1 < a.rules.size(); ++k) {
      const Rule& r = a.rules[k];
      if (activity_event_name(r.name) != name) continue;
      return "'" + name + "' is the activity event of rule '" + r.name + "', present only in " +
             a.port.qualified() + "'s events (each arbitrated port has its own), so it cannot " +
             "be read here, nor declared; to react here to what '" + r.name +
             "' reacts to, derive an event from its source: `event e_" + r.name + " = " +
             r.source.qualified() + " : PREDICATE for D;`";
    }
  }
  return std::nullopt;
}

Diagnostic& Sema::unknown_event(const Loc& loc, const std::string& name, bool set_by_code) {
  Diagnostic& d =
      unknown(loc, "unknown event '" + name + "'", diag::UnknownEvent, name, event_names_);
  if (!d.notes.empty()) return d;  // "did you mean": most likely a misspelling
  Diagnostic note;
  note.severity = Severity::Note;
  if (auto activity = activity_elsewhere(spec_, name)) {
    note.message = *activity;
    d.notes.push_back(std::move(note));
    return d;
  }
  note.message =
      set_by_code ? "declare it: `event " + name + ";` (monitor code sets the events declared so)"
                  : "declare it: `event " + name +
                        ";` for monitor code to set, a status flag in "
                        "`events from Module.port { " +
                        name + " } lifetime D;`, or a derived event `event " + name +
                        " = Module.port : PREDICATE;`";
  d.notes.push_back(std::move(note));
  return d;
}

void Sema::did_you_mean(Diagnostic& d, const std::string& meant) {
  Diagnostic note;
  note.severity = Severity::Note;
  note.message = "did you mean '" + meant + "'?";
  d.notes.push_back(std::move(note));
}

Diagnostic& Sema::value_type_error(const Expr& value, const TypePtr& want, std::string message,
                                   DiagId id) {
  if (auto stray = stray_field(value, want)) {
    const std::string& name = stray->name->name;
    message += "; " + describe(stray->record) + " has no field '" + name + "'";
    if (!stray->via)
      return unknown(stray->name->loc, std::move(message), std::move(id), name, stray->missing);
    // A literal bound by a `let` may be used on several paths (`if ... { emit c; } else
    // { emit c; }`): one error at its field, with a note at each use.
    Diagnostic note;
    note.severity = Severity::Note;
    note.loc = stray->via->loc;
    note.message =
        "'" + stray->via->text + "' has the type of that record literal; it is used here";
    for (Diagnostic& d : out_) {
      if (d.id == id.text() && d.message == message && same_place(d.loc, stray->name->loc)) {
        d.notes.push_back(std::move(note));
        return d;
      }
    }
    Diagnostic& d =
        unknown(stray->name->loc, std::move(message), std::move(id), name, stray->missing);
    d.notes.push_back(std::move(note));
    return d;
  }
  if (auto field = field_mismatch(value, want)) {
    if (!field->value) {
      return error(
          field->literal->loc,
          message + "; field '" + field->field + "' (" + describe(field->want) + ") is missing",
          std::move(id));
    }
    std::optional<std::string> size = size_miss(*field->value, field->want);
    Diagnostic& d =
        error(field->value->loc,
              message + "; field '" + field->field + "' is " + describe(field->value->type) +
                  " where " + describe(field->want) + " is expected" + (size ? ": " + *size : ""),
              std::move(id));
    narrowing_note(d, field->value->type, field->want);
    return d;
  }
  if (std::optional<std::string> size = size_miss(value, want)) message += ": " + *size;
  Diagnostic& d = error(value.loc, std::move(message), std::move(id));
  narrowing_note(d, value.type, want);
  return d;
}

// A number where a narrower sized number is expected: arithmetic promoted it (int8 + 1 is an
// int), and arbc converts nothing silently; say both, once.
void Sema::narrowing_note(Diagnostic& d, const TypePtr& got, const TypePtr& want) {
  bool numbers = got && want && (got->kind == Type::Kind::Int || got->kind == Type::Kind::Float) &&
                 (want->kind == Type::Kind::Int || want->kind == Type::Kind::Float);
  if (!numbers || !want->narrow()) return;
  Diagnostic note;
  note.severity = Severity::Note;
  note.message =
      "arithmetic computes sized numbers as int or float, and arbc narrows no computed "
      "value: give a value of " +
      want->to_string() +
      " (a field of that type, or a "
      "constant in its range; docs/language.md#sized-numbers)";
  d.notes.push_back(std::move(note));
}

std::string Sema::describe(const TypePtr& t) const {
  if (t) {
    auto it = type_names_.find(t.get());
    if (it != type_names_.end()) return it->second;
  }
  return type_name(t);
}

}  // namespace arbc::frontend
