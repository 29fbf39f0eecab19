// Semantic analysis of monitor bodies: the statements of a rule or a `connect`, their scopes,
// where each statement may appear, the events they set, and the emitted values' types
// (the paper's first integration rule: both sides of a connection carry the same type).
#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/frontend/lua_syntax.h"
#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/type_rules.h"

namespace arbc::frontend {

using namespace ast;

namespace {

const char* local_kind(NameKind kind) {
  switch (kind) {
    case NameKind::Message:
      return "the incoming message";
    case NameKind::Let:
      return "a `let` value";
    case NameKind::Param:
      return "a lambda parameter";
    case NameKind::Const:
      return "a constant";
    default:
      return "not a variable";
  }
}

}  // namespace

const Binding* Scope::find(const std::string& name) const {
  for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame) {
    auto it = frame->find(name);
    if (it != frame->end()) return &it->second;
  }
  return nullptr;
}

std::vector<std::string> Scope::names() const {
  std::vector<std::string> out;
  for (const auto& frame : frames_)
    for (const auto& [name, binding] : frame) out.push_back(name);
  return out;
}

std::string Scope::message_name() const {
  for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame) {
    for (const auto& [name, binding] : *frame) {
      if (binding.kind == ast::NameKind::Message && !binding.message_unavailable &&
          !binding.other_port)
        return name;
    }
  }
  return {};
}

// The script is read at build time, relative to the spec's folder (or the script folder
// check_spec was given); a missing one, or one that does not compile as Lua, is caught now.
// Specs checked from memory without a script folder skip the check.
void Sema::check_script_file(const Stmt& s) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path spec_path(spec_.file);
  fs::path base = script_dir_;
  if (script_dir_.empty()) {
    if (spec_.file.empty() || !fs::is_regular_file(spec_path, ec)) return;
    base = spec_path.parent_path();
  }
  fs::path script = base / s.text;
  if (fs::path(s.text).is_absolute()) script = s.text;
  if (!fs::is_regular_file(script, ec)) {
    std::string where = script.string() == s.text ? "" : "looked for " + script.string() + "; ";
    error(s.loc,
          "script file '" + s.text + "' not found (" + where +
              "a script path is relative to the spec's folder)",
          diag::ScriptMissing);
    return;
  }
  std::ifstream in(script, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) {
    error(s.loc, "cannot read script file '" + script.string() + "': check its permissions",
          diag::Script);
  } else if (auto d = lua_syntax_diagnostic(text.str(), script.string(), s.loc)) {
    out_.push_back(std::move(*d));
  }
}

bool Sema::definitely_emits(const Block& body) {
  for (const auto& s : body) {
    if (s->kind == Stmt::Kind::Emit) return true;
    if (s->kind == Stmt::Kind::If && s->has_else && definitely_emits(s->body) &&
        definitely_emits(s->else_body))
      return true;
  }
  return false;
}

void Sema::check_body(Block& body, Scope& scope, BodyContext& ctx) {
  check_script_alone(body, ctx);
  scope.push();
  for (auto& owned : body) check_stmt(*owned, scope, ctx);
  scope.pop();
}

void Sema::check_script_alone(const Block& body, const BodyContext& ctx) {
  bool has_script = false;
  for (const auto& s : body) has_script |= s->kind == Stmt::Kind::Script;
  if (!has_script || body.size() <= 1 || !ctx.top_level) return;
  for (const auto& s : body) {
    if (s->kind != Stmt::Kind::Script) {
      error(s->loc,
            "a body with `script` holds nothing else: the script's accept/update replace "
            "the generated monitor",
            diag::ScriptAlone);
      return;
    }
  }
}

void Sema::check_stmt(Stmt& s, Scope& scope, BodyContext& ctx) {
  switch (s.kind) {
    case Stmt::Kind::Let:
    case Stmt::Kind::Var:
      return check_local(s, scope, ctx);
    case Stmt::Kind::Assign:
      return check_assign(s, scope);
    case Stmt::Kind::Accept:
      if (ctx.in_every) {
        error(s.loc, "`accept` filters messages; an `every` body runs on a timer",
              diag::StatementContext);
      }
      check_condition(*s.expr, scope, "the condition of `accept`", diag::TypeMismatch);
      return;
    case Stmt::Kind::Set:
    case Stmt::Kind::Unset:
      return check_set(s);
    case Stmt::Kind::If:
      return check_if(s, scope, ctx);
    case Stmt::Kind::Emit:
      return check_emit(s, scope, ctx);
    case Stmt::Kind::Throttle:
      return check_throttle(s, ctx);
    case Stmt::Kind::Every:
      return check_every(s, scope, ctx);
    case Stmt::Kind::Script:
      if (!ctx.top_level) {
        error(s.loc, "`script` replaces the whole body: put it at the top level",
              diag::StatementContext);
      }
      check_script_file(s);
      return;
  }
}

// `let` / `var`: a new name in this scope (never a constant's or an outer local's); `var` only
// at the top level, outside `every`.
void Sema::check_local(Stmt& s, Scope& scope, const BodyContext& ctx) {
  check_expr(*s.expr, scope);
  if (s.kind == Stmt::Kind::Var && (!ctx.top_level || ctx.in_every)) {
    error(s.loc, "`var` declares monitor state: put it at the top level of the body",
          diag::StatementContext);
  }
  if (const Binding* existing = scope.find(s.name); existing && !existing->other_port) {
    error(s.name_loc,
          "'" + s.name + "' is already defined here as " + local_kind(existing->kind) +
              "; choose another name",
          diag::Duplicate);
  } else if (consts_.count(s.name)) {
    error(s.name_loc, "'" + s.name + "' is already a constant; choose another name",
          diag::Duplicate);
  }
  Binding b;
  b.kind = s.kind == Stmt::Kind::Let ? NameKind::Let : NameKind::Var;
  // A `var` holds what the body computes later, so a sized number's state is its promoted type
  // (`var n = m.seq;` of an int32 holds an int: `n = n + 1` is allowed), as core/body_types.cc.
  b.type = b.kind == NameKind::Var ? promoted(s.expr->type) : s.expr->type;
  b.is_duration = s.expr->is_duration;
  b.local = &s;
  scope.define(s.name, b);
}

// `name = value;`: name is a `var` in scope and the value fits its type.
void Sema::check_assign(Stmt& s, Scope& scope) {
  check_expr(*s.expr, scope);
  const Binding* b = scope.find(s.name);
  if (!b) {
    if (consts_.count(s.name)) {
      error(s.name_loc, "'" + s.name + "' is a constant; only `var` variables can be assigned",
            diag::Assign);
    } else {
      Diagnostic& d = unknown(s.name_loc, "unknown variable '" + s.name + "'", diag::UnknownName,
                              s.name, scope.names());
      if (d.notes.empty()) {  // no close name: state is declared before it is assigned
        Diagnostic note;
        note.severity = Severity::Note;
        note.message =
            "declare it first, at the top level of the body: `var " + s.name + " = VALUE;`";
        d.notes.push_back(std::move(note));
      }
    }
    return;
  }
  if (b->kind != NameKind::Var) {
    error(s.name_loc,
          "'" + s.name + "' is " + local_kind(b->kind) + "; only `var` variables can be assigned",
          diag::Assign);
    return;
  }
  s.var_decl = b->local;
  if (b->type && s.expr->type)  // a constant in range fits, as in an emit (value_fit.h)
    check_value_fits(
        *s.expr, b->type,
        "'" + s.name + "' holds " + describe(b->type) + ", not " + describe(s.expr->type),
        diag::TypeMismatch);
}

// `set` / `unset`: a declared event that monitor code may set (not one a feed sets).
void Sema::check_set(Stmt& s) {
  auto it = events_.find(s.name);
  if (it == events_.end()) {
    unknown_event(s.name_loc, s.name, true);
  } else {
    const EventSymbol& event = spec_.event_symbols[it->second];
    if (event.kind != EventSymbol::Kind::Manual) {
      error(s.name_loc,
            "event '" + s.name + "' is fed from " + event.source +
                "; monitor code sets only events declared with `event " + s.name + ";`",
            diag::SetFedEvent);
    }
  }
  if (s.duration) check_duration(*s.duration, "the lifetime of `set`");
}

// `if`: a bool condition; both branches are nested bodies.
void Sema::check_if(Stmt& s, Scope& scope, BodyContext& ctx) {
  check_condition(*s.expr, scope, "the condition of `if`", diag::TypeMismatch);
  BodyContext inner = ctx;
  inner.top_level = false;
  check_body(s.body, scope, inner);
  check_body(s.else_body, scope, inner);
  ctx.saw_throttle |= inner.saw_throttle;
  ctx.saw_every |= inner.saw_every;
}

// `emit`: not in an `every` body; the value fits the destination port.
void Sema::check_emit(Stmt& s, Scope& scope, const BodyContext& ctx) {
  check_expr(*s.expr, scope);
  if (ctx.in_every) {
    error(s.loc, "`emit` delivers a message; an `every` body runs on a timer and has none",
          diag::StatementContext);
    return;
  }
  if (s.expr->type && ctx.destination_type)
    check_value_fits(*s.expr, ctx.destination_type,
                     ctx.owner + " emits " + describe(s.expr->type) + ", but " + ctx.destination +
                         " takes " + describe(ctx.destination_type),
                     diag::EmitType);
}

// `throttle D`: once, at the top level, outside `every`.
void Sema::check_throttle(Stmt& s, BodyContext& ctx) {
  check_duration(*s.duration, "the `throttle` period");
  if (!ctx.top_level || ctx.in_every) {
    error(s.loc, "`throttle` limits the whole connection: put it at the top level of the body",
          diag::StatementContext);
  } else if (ctx.saw_throttle) {
    error(s.loc, "a body has at most one `throttle`", diag::StatementContext);
  }
  ctx.saw_throttle = true;
}

// `every D { ... }`: once, at the top level; its body runs on a timer, without the message.
void Sema::check_every(Stmt& s, Scope& scope, BodyContext& ctx) {
  check_duration(*s.duration, "the `every` period");
  if (!ctx.top_level || ctx.in_every) {
    error(s.loc, "`every` must be at the top level of the body", diag::StatementContext);
  } else if (ctx.saw_every) {
    error(s.loc, "a body has at most one `every`", diag::StatementContext);
  }
  ctx.saw_every = true;
  BodyContext inner = ctx;
  inner.in_every = true;
  inner.top_level = false;
  scope.push();
  // The message does not exist in a timer callback; shadow it with a marker.
  for (const std::string& name : scope.names()) {
    const Binding* b = scope.find(name);
    if (b && b->kind == NameKind::Message) {
      Binding hidden;
      hidden.message_unavailable = true;
      scope.define(name, hidden);
    }
  }
  check_body(s.body, scope, inner);
  scope.pop();
}

}  // namespace arbc::frontend
