// State shared by the parts of semantic analysis (sema_*.cc): the spec, the diagnostics, the
// symbol tables, and helpers that report errors with "did you mean" notes.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "compiler/frontend/ast.h"
#include "compiler/frontend/const_fold.h"
#include "core/check_ids.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

struct DeliveryOwner;  // sema_delivery.cc

// One name visible in a monitor body or predicate.
struct Binding {
  ast::NameKind kind = ast::NameKind::Unresolved;
  TypePtr type;
  bool is_duration = false;
  const ast::Stmt* local = nullptr;   // Let, Var
  const ast::Expr* lambda = nullptr;  // Param
  bool message_unavailable = false;   // the message inside an `every` body
  // A port of the source's module, bound while the source port is misspelt (bind_message);
  // a `let` may take its name.
  bool other_port = false;
};

// Nested scopes of a body: lookups go innermost first.
class Scope {
 public:
  void push() { frames_.emplace_back(); }
  void pop() { frames_.pop_back(); }
  void define(const std::string& name, Binding b) { frames_.back()[name] = std::move(b); }
  const Binding* find(const std::string& name) const;
  std::vector<std::string> names() const;
  // The name the incoming message is bound to (the source port's), or empty outside a body
  // that has one.
  std::string message_name() const;

 private:
  std::vector<std::map<std::string, Binding>> frames_{1};
};

// Where a monitor body runs, for checking its statements.
struct BodyContext {
  std::string owner;         // "rule 'take'" or "the connect into HeadControl.gaze"
  TypePtr destination_type;  // null if the destination did not resolve
  std::string destination;   // "Module.port"
  bool in_every = false;
  bool top_level = true;
  bool saw_throttle = false;
  bool saw_every = false;
};

// A monitor body and the connection it runs on: what check_monitor needs of a rule or a connect.
struct MonitorSite {
  ast::Block* body = nullptr;
  const ast::PortRef* source = nullptr;
  bool source_ok = false;    // the source resolved
  TypePtr destination_type;  // null if the destination did not resolve
  std::string destination;   // "Module.port"
  ast::Loc loc;              // the rule or connect, for "delivers its input unchanged"
};

// What to do about a name declared twice (the two may mean different things, so not "delete"),
// and where the first one is: "type 'T' is already defined at line 3: rename one of them".
inline constexpr const char* kRenameOne = ": rename one of them";
inline std::string where_defined(const ast::Loc& loc) { return "line " + std::to_string(loc.line); }

// Checks one spec (check_spec's work). Only run() is public: the passes, the symbol tables and
// the reporting helpers are its own business (sema_decls.cc, sema_types.cc, sema_report.cc,
// sema_body.cc, sema_expr.cc).
class Sema {
 public:
  Sema(ast::Spec& spec, std::vector<Diagnostic>& out, std::string script_dir)
      : spec_(spec), out_(out), script_dir_(std::move(script_dir)) {}

  void run();  // sema_decls.cc

 private:
  // ---- the passes, one per kind of declaration, in run()'s order (sema_decls.cc) ----
  // The spec starts with `app NAME;`.
  void check_app_declared();
  // Registers type, constant and module names (reporting duplicates), then resolves them.
  void declare_types();
  void declare_consts();
  void declare_modules();
  // Registers every event name once, whatever declares it (manual, status flag, derived).
  void declare_events();
  void add_event(ast::EventSymbol symbol);  // reports a name declared twice
  void declare_manual_events(ast::EventDecl& e);
  // `events from M.p { ... }`: a list<string> source, each flag mapped once.
  std::optional<Nanos> fail_open_after(std::optional<ast::FailOpen>& f);
  void declare_status_events(ast::StatusEventDecl& e);
  // After all events exist, so that a predicate naming an event gets the right message.
  void check_derived_predicates();
  bool resolve_derived_source(ast::DerivedEventDecl& e);
  // `exclusive` groups and invariants: domain knowledge for the proof.
  void check_domain();
  // An arbitrated port (once per port) and each of its rules: name, source, when, hold, body.
  void check_arbitration(ast::ArbitrateDecl& a);
  // A rule's `when` (or `otherwise`, at most one per port) into r.constraint.
  void check_rule_when(ast::Rule& r, const std::string& port, const ast::Rule*& otherwise_rule);
  // `hold` only under `by priority`, never on the lowest rule, and required on the others.
  void check_rule_hold(ast::ArbitrateDecl& a, size_t i);
  // The body of a rule or connect, and that an input delivered unchanged fits the destination.
  // `owner` names it in body messages ("rule 'take'"), `subject` in the unchanged-input one.
  void check_monitor(const MonitorSite& site, const std::string& owner, const std::string& subject);
  // `then set e` / `then unset e` on rules (sema_delivery.cc): plain events of one port, set
  // before unset, touched by no monitor body, read by no rule of another port.
  void check_delivery_effects();
  void check_delivery_owners(const std::map<std::string, DeliveryOwner>& owners);
  // A plain connection: into a port nothing else feeds and no `arbitrate` block owns.
  void check_connect(ast::ConnectDecl& c);
  // An assertion names a rule of an arbitrated port; its property is a constraint.
  void check_assert(ast::AssertDecl& a);
  // `resource` declarations (sema_resource.cc).
  void check_resources();
  TypePtr check_resource_ports(ast::ResourceDecl& r);
  void check_data_assert(ast::AssertDecl& a);

  // ---- properties over time (sema_temporal.cc) ----
  // A property over time: its rules, window, event (by kind, docs/language.md).
  void check_temporal(ast::TemporalDecl& n);
  // The one rule named `name`; null (reported) when no rule, or rules of several ports, have
  // it. `what` names the declaration in the message ("an assumption").
  const ast::Rule* unique_rule(const std::string& name, const ast::Loc& loc,
                               const std::string& what);
  void check_absence_event(ast::TemporalDecl& n);
  void check_precedence(ast::TemporalDecl& n);
  // The activity events `act_R` of `port`'s rules with a hold (none unless `by priority`).
  std::vector<std::string> activity_events(const ast::ArbitrateDecl& port) const;
  // The arbitrated port `ref` names; null (reported) when it is not one. `use` names the
  // declaration in the message ("a `stable` property").
  const ast::ArbitrateDecl* arbitrated_port(ast::PortRef& ref, const std::string& use);
  // `after OTHER [stops], RULE|M.p within D [while C];`: the answer, the trigger (a rule or an
  // event of the answer's port), the window, the condition (sema_response.cc).
  void check_response(ast::TemporalDecl& n);
  bool names_port_event(const ast::ArbitrateDecl& port, const std::string& name) const;
  void check_response_event(ast::TemporalDecl& n, const ast::ArbitrateDecl& port);
  void check_response_rule(ast::TemporalDecl& n, const ast::ArbitrateDecl& port);
  // `stable M.p for D;`: an arbitrated port and a positive period.
  void check_stability(ast::TemporalDecl& n);
  // `given M.p every D;` (sema_rates.cc).
  void check_rates();

  // ---- environment assumptions (sema_assume.cc) ----
  // `assume EVENT only after RULE [until RULE];`: a feed-owned event, two rules of one port;
  // `assume not EVENT for D after RULE;`: a feed-owned event, a positive D.
  void check_assume(ast::AssumeDecl& a);

  // ---- tests (sema_test.cc) ----
  // Every `test`: unique names, steps and expectations against the app.
  void check_tests();
  // The rule a test names (`on RULE`, `expect RULE drops`); null (reported) when none or
  // ambiguous.
  const ast::Rule* find_test_rule(const std::string& name, const ast::Loc& loc);
  // A test time: a duration >= 0 (`at 0s` is the start).
  void check_test_time(ast::Duration& d, const std::string& what);
  // A message literal: a constant value of the port's type; `at` is the step's instant (none
  // for an expected value: `now()` is then an error).
  void check_test_value(ast::Expr& e, const ast::PortRef& port, std::optional<Nanos> at);
  // Stamps written as instants (`now() - 150ms`) become `{sec, nanosec}` records
  // (sema_test_stamps.cc); false when one was reported.
  bool desugar_test_stamps(ast::Expr& e, const TypePtr& want, std::optional<Nanos> at);
  std::optional<Nanos> stamp_instant(ast::Expr& e, std::optional<Nanos> at, bool* reported);
  void check_test_step(const ast::TestDecl& t, ast::TestStep& s);
  void check_test_expect(const ast::TestDecl& t, ast::TestExpect& e);
  void check_test_claim(const ast::TestDecl& t, ast::TestExpect& e);
  void check_test_state(const ast::TestDecl& t, ast::TestExpect& e);
  void report_expects_nothing(const ast::TestDecl& t);
  void check_reason_possible(const ast::Rule& rule, const ast::TestExpect& e);
  // `at D` or `within A..B` (A <= B); `instant_only` for event states.
  void check_test_window(ast::TestWindow& w, bool instant_only);

  // ---- reporting (sema_decls.cc) ----
  Diagnostic& error(const ast::Loc& loc, std::string message, DiagId id);
  // Reports an unknown name, with "did you mean" when a candidate is close.
  Diagnostic& unknown(const ast::Loc& loc, std::string message, DiagId id, const std::string& name,
                      const std::vector<std::string>& candidates);
  // Adds the note "did you mean 'X'?" (an editor's quick fix puts X in place of `d`'s range).
  void did_you_mean(Diagnostic& d, const std::string& meant);
  // An unknown event with no close name: how to declare it, for monitor code to set
  // (`set_by_code`) or in any of the three ways.
  Diagnostic& unknown_event(const ast::Loc& loc, const std::string& name, bool set_by_code);
  // A value of the wrong type where `want` is expected (an emit, a test's message, a var):
  // reported at the value, or, when a record literal in it names a field `want` lacks, at
  // that name with "did you mean" (stray_field.h).
  Diagnostic& value_type_error(const ast::Expr& value, const TypePtr& want, std::string message,
                               DiagId id);
  // Adds the note on sized numbers when `got` is a number that `want`, a narrower one, cannot
  // take (sema_report.cc).
  void narrowing_note(Diagnostic& d, const TypePtr& got, const TypePtr& want);
  // A type as the user wrote it when it has a declared name ("Cmd"), else its structure.
  std::string describe(const TypePtr& t) const;

  // ---- types and ports (sema_decls.cc) ----
  // The structural type of a type expression (records the result in it); null on error.
  TypePtr resolve_type(ast::TypeExpr& t);
  // The type a `type` declaration names, resolving it once; reports cycles.
  TypePtr resolve_type_decl(ast::TypeDecl& decl);
  TypePtr resolve_named_type(ast::TypeExpr& t);
  // Resolves `Module.port`; `role` is "source" or "destination" (for the direction check) or
  // empty (no check). Returns false if it did not resolve.
  bool resolve_port(ast::PortRef& ref, const char* role, const std::string& use);
  // Defines the message's name (the source port's) in `scope`, typed if `resolved`; a source
  // whose port is misspelt binds the port it suggests as well (sema_message.cc).
  void bind_message(Scope& scope, const ast::PortRef& source, bool resolved);

  // ---- expressions (sema_expr.cc) ----
  // Types `e` and resolves its names (the "sema:" fields of ast::Expr); reports what is wrong.
  void check_expr(ast::Expr& e, Scope& scope);
  void check_name(ast::Expr& e, Scope& scope);
  void check_field(ast::Expr& e, Scope& scope);
  void check_index(ast::Expr& e, Scope& scope);
  void check_unary(ast::Expr& e, Scope& scope);
  void check_binary(ast::Expr& e, Scope& scope);
  void check_record(ast::Expr& e, Scope& scope);
  void check_list(ast::Expr& e, Scope& scope);
  // A condition (`accept`, `if`, a derived event's predicate): reports non-bool with `id`.
  void check_condition(ast::Expr& e, Scope& scope, const std::string& what, DiagId id);
  // Resolves a duration position to whole nanoseconds; `what` names it ("the lifetime").
  void check_duration(ast::Duration& d, const std::string& what);
  // The whole nanoseconds of `e`, a positive duration literal or constant; nullopt, with the
  // error reported, when it is not a whole number of them or longer than 100 years.
  std::optional<Nanos> duration_nanos(const ast::Expr& e, const std::string& what);
  // Turns a constraint expression into a Constraint; `otherwise_ok` allows a whole `otherwise`
  // (the caller records it). Reports anything but events, true, false, not, and, or.
  Constraint check_constraint(ast::Expr& e, const std::string& where, bool otherwise_ok);
  void check_const(size_t index);
  // A builtin call: the function exists, takes that many arguments of those types.
  void check_call(ast::Expr& e, Scope& scope);
  bool check_arity(ast::Expr& e, const BuiltinInfo& info);
  // min_by / max_by: a list and a lambda giving each element a number.
  void check_best_by(ast::Expr& e, Scope& scope);
  // The argument types of the other builtins (all typed already) and the call's type.
  void check_builtin_args(ast::Expr& e, const BuiltinInfo& info);

  // ---- sized numbers (sema_numbers.cc) ----
  // An int literal above 2^63 - 1 that fits in 64 bits unsigned: typed uint64, its bits in
  // `integer` (docs/language.md#sized-numbers). False for one beyond 2^64 - 1.
  bool uint64_literal(ast::Expr& e);
  // A binary operator with a uint64 operand: only + - * == != < <= > >= against a uint64, an
  // unsigned integer or a constant >= 0; false, reported, otherwise.
  bool check_uint64_binary(ast::Expr& e);
  // A number item of a list literal beside items of type `element`: false, reported, when one
  // is a uint64 and the other may be negative.
  bool check_uint64_list_item(const ast::Expr& item, const TypePtr& element);
  // An operand no uint64 may be (of unary '-', of a builtin): false, reported, when it is one.
  bool check_uint64_operand(const ast::Expr& operand, const std::string& what);
  // `value` goes where `want` is expected (an emit, a test's message): false, reported with
  // `message` and `id`, when its type does not fit (value_fit.h); reported as number-range at the
  // constant when a constant is out of its sized type's range.
  bool check_value_fits(const ast::Expr& value, const TypePtr& want, const std::string& message,
                        DiagId id);

  // ---- constants (sema_const.cc) ----
  // The value of a constant expression (literals, constants and operators on them), folded as
  // the monitor's Lua computes it (const_fold.h); nullopt for anything else.
  std::optional<ConstValue> constant_of(const ast::Expr& e) const;
  // After an operator is typed: folds it if its operands are constants, and reports a
  // constant that overflows 64 bits or a division by a constant zero (its type is then unset).
  void fold_operator(ast::Expr& e);

  // ---- bodies (sema_body.cc) ----
  // The statements of a body in a scope of their own; `ctx` says where the body runs.
  void check_body(ast::Block& body, Scope& scope, BodyContext& ctx);
  // `script` at the top level of a body is the whole body.
  void check_script_alone(const ast::Block& body, const BodyContext& ctx);
  // One statement, by kind (the functions below); may define a name in `scope`.
  void check_stmt(ast::Stmt& s, Scope& scope, BodyContext& ctx);
  void check_local(ast::Stmt& s, Scope& scope, const BodyContext& ctx);
  void check_assign(ast::Stmt& s, Scope& scope);
  void check_set(ast::Stmt& s);
  void check_if(ast::Stmt& s, Scope& scope, BodyContext& ctx);
  void check_emit(ast::Stmt& s, Scope& scope, const BodyContext& ctx);
  void check_throttle(ast::Stmt& s, BodyContext& ctx);
  void check_every(ast::Stmt& s, Scope& scope, BodyContext& ctx);
  static bool definitely_emits(const ast::Block& body);
  void check_script_file(const ast::Stmt& s);

  ast::Spec& spec_;
  std::vector<Diagnostic>& out_;
  std::string script_dir_;  // check_spec's: where script paths are relative to
  std::map<std::string, ast::TypeDecl*> types_;
  std::set<const ast::TypeDecl*> types_active_, types_done_;  // resolve_type_decl's progress
  std::map<std::string, size_t> consts_;
  std::vector<int> const_state_;  // 0 unchecked, 1 checking, 2 done
  // The values of operators whose operands are constants (fold_operator): a constant
  // expression costs one fold per operator, however deep.
  std::unordered_map<const ast::Expr*, ConstValue> folded_;
  std::map<const Type*, std::string> type_names_;
  std::map<std::string, size_t> events_;                   // name -> index in spec_.event_symbols
  std::map<std::string, const ast::ModuleDecl*> modules_;  // the first declaration of each
  std::vector<std::string> event_names_;
  std::map<std::string, const ast::ArbitrateDecl*> arbitrated_;  // "Module.port" -> its block
  std::map<std::string, const ast::ConnectDecl*> fed_;  // ports a connect feeds -> the connect
};

// Whether `e` reads the name `name` (sema_resource.cc).
bool mentions_name(const ast::Expr& e, const std::string& name);

}  // namespace arbc::frontend
