// The spec language's abstract syntax tree (docs/language.md), with source locations.
//
// The parse-tree builder (ast_builder.*) fills the syntax; semantic analysis (sema.*) then
// fills the fields marked "sema:" so that lowering never resolves a name or infers a type
// again: every expression knows its type, every name knows what it refers to, every port
// reference knows its module and port, every constraint is already a runtime Constraint tree,
// and every duration is already a whole number of nanoseconds.
//
// Ownership: a Spec owns everything. Declarations live in per-kind vectors; sema links them with
// plain pointers, so a Spec is movable (vector buffers move with it) but not copyable.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/app_model.h"
#include "core/builtins.h"
#include "core/constraint.h"
#include "core/type.h"

namespace arbc::ast {

using Loc = model::SourceLocation;

struct ModuleDecl;
struct PortDecl;
struct ConstDecl;
struct Stmt;
struct Expr;
struct Rule;
struct ArbitrateDecl;

using ExprPtr = std::unique_ptr<Expr>;
using Block = std::vector<std::unique_ptr<Stmt>>;

// ---------------------------------------------------------------------------------------------
// Types as written: `float`, `list<Object>`, `{ pos: vec3, dist: float }`, `Object`.
struct TypeExpr {
  enum class Kind { Bool, Int, Float, String, Vec3, List, Record, Named };
  Kind kind = Kind::Bool;
  std::string name;                                                       // Kind::Named
  std::unique_ptr<TypeExpr> element;                                      // Kind::List
  std::vector<std::pair<std::string, std::unique_ptr<TypeExpr>>> fields;  // Kind::Record
  std::vector<Loc> field_locs;  // Kind::Record, parallel to fields
  int size = 0;                 // Kind::List, Kind::String: N of list<T, N>, T[N], string<N>
  bool fixed = false;           // Kind::List: T[N], exactly N elements
  Loc loc;
  TypePtr resolved;  // sema: the structural type (named types expanded); null on error
};

// `Module.port`, wherever a port is named.
struct PortRef {
  std::string module;
  std::string port;
  Loc loc;                                  // the whole `Module.port`
  Loc module_loc, port_loc;                 // each name alone: what a misspelling points at
  const ModuleDecl* module_decl = nullptr;  // sema
  const PortDecl* port_decl = nullptr;      // sema
  std::string qualified() const { return module + "." + port; }
};

// A duration-valued position (`lifetime D`, `hold D`, `for D`, `throttle D`, `every D`):
// a duration literal (`500ms`, `0.5s`, `2min`) or a constant holding one.
struct Duration {
  ExprPtr expr;
  Nanos nanos{0};  // sema: the value, a whole number of nanoseconds (core/instant.h)
};

// ---------------------------------------------------------------------------------------------
// Expressions.

// The builtin a call names: core/builtins.h lists them once for every stage.
using Builtin = arbc::Builtin;

// What an identifier in an expression names (sema).
enum class NameKind {
  Unresolved,
  Message,  // the incoming message, bound to the source port's name (`objects`, `face`)
  Let,      // `let x = E;` in the enclosing body
  Var,      // `var x = E;`: monitor state kept across messages
  Param,    // a lambda's parameter
  Const,    // `const N = E;`
  Event,    // an event, only inside constraints (`when`, `assert`, `invariant`)
};

struct Expr {
  enum class Kind {
    Number,     // number; is_int says whether it was written without a fraction or exponent
    Duration,   // `500ms`: number holds seconds, text the literal as written
    String,     // text holds the decoded string
    Bool,       // boolean
    Name,       // text holds the identifier
    Field,      // args[0].text
    Index,      // args[0][args[1]]
    Unary,      // op is "-" or "not"; args[0]
    Binary,     // op is one of + - * / % < <= > >= == != and or; args[0], args[1]
    Record,     // { names[i].name: args[i] }
    List,       // [ args... ]
    Lambda,     // text => args[0]  (only as an argument of min_by / max_by)
    Call,       // text(args...), text names a builtin
    Otherwise,  // `otherwise`, only as a whole constraint
  };
  // A name written inside an expression, with where it was written.
  struct NameAt {
    std::string name;
    Loc loc;
  };

  // The fields are ordered to pack: a 10,000-rule spec has about 180,000 expressions, and on
  // these machines the fresh memory they fill costs more than building them
  // (docs/benchmarks.md).
  Kind kind = Kind::Number;
  NameKind name_kind = NameKind::Unresolved;  // sema, Kind::Name
  Builtin builtin = Builtin::None;            // sema, Kind::Call
  bool is_int = false;
  bool boolean = false;
  bool is_duration = false;  // sema: a float that came from a duration literal or constant
  bool int_too_big = false;  // Number, is_int: the digits do not fit in 64 bits (sema says so)
  Loc loc;
  std::string_view op;  // one of the grammar's operator spellings (static storage)
  std::string text;
  double number = 0;
  int64_t integer = 0;  // Number, is_int: the exact value (number holds it rounded to a double)
  std::vector<NameAt> names;  // Record: each field; Call: [0] the callee; Lambda: [0] the parameter
  std::vector<ExprPtr> args;

  // sema:
  TypePtr type;                  // value type; null for lambdas, events, otherwise, and on error.
                                 // An empty list literal `[]` has a List type with a null element.
  const Stmt* local = nullptr;   // NameKind::Let / Var: the declaring statement
  const Expr* lambda = nullptr;  // NameKind::Param: the Lambda expression
  const ConstDecl* constant = nullptr;  // NameKind::Const
};

// ---------------------------------------------------------------------------------------------
// Monitor body statements.

struct Stmt {
  enum class Kind {
    Let,       // let name = expr;
    Var,       // var name = expr;   (initialised once, kept across messages)
    Assign,    // name = expr;       (name is a var)
    Accept,    // accept expr;
    Set,       // set name [for duration];
    Unset,     // unset name;
    If,        // if expr { body } else { else_body }   (else if: one If in else_body)
    Emit,      // emit expr;
    Throttle,  // throttle duration;
    Every,     // every duration { body }
    Script,    // script "text";
  };
  Kind kind = Kind::Accept;
  Loc loc;
  std::string name;  // Let, Var, Assign (the variable), Set, Unset (the event)
  Loc name_loc;
  std::string text;                  // Script: the file name as written
  ExprPtr expr;                      // Let, Var, Assign, Accept, If (condition), Emit
  std::optional<Duration> duration;  // Set (for D), Throttle, Every
  Block body;                        // If (then), Every
  Block else_body;                   // If; empty when there is no else
  bool has_else = false;
  // sema:
  const Stmt* var_decl = nullptr;  // Assign: the Var statement it writes
};

// ---------------------------------------------------------------------------------------------
// Declarations.

struct AppDecl {
  std::string name;
  std::string doc;
  Loc loc;
};

struct TypeDecl {
  std::string name;
  TypeExpr type;
  Loc loc;  // the name; for a type `use` declared, the message's name in the `use`
  // Declared by `use ros2` (ros2_uses.h): the message it is ("geometry_msgs/msg/Twist") and the
  // .msg file it was read from ("" for a built-in definition). Empty for a `type` declaration.
  std::string ros2;
  std::string msg_file;
};

// `use ros2 geometry_msgs/msg/Twist;`: the message's type, read from its .msg file.
struct UseDecl {
  std::string system;   // the word after `use`: `ros2` is the only one
  Loc system_loc;       //
  std::string written;  // the name as written: "geometry_msgs/msg/Twist" or "pkg/Name"
  std::string package, name;
  Loc loc;       // the whole name
  Loc name_loc;  // its last part: the type it declares
};

struct ConstDecl {
  std::string name;
  ExprPtr value;
  Loc loc;  // the name
  // sema: value->type / value->is_duration give the constant's type; the folded value:
  double number = 0;    // floats (durations in seconds)
  int64_t integer = 0;  // ints
  std::string text;     // strings
  bool boolean = false;
};

struct PortDecl {
  std::string name;
  model::Direction direction = model::Direction::In;
  TypeExpr type;
  Loc loc;  // the name
};

struct ModuleDecl {
  std::string name;
  std::string doc;
  std::vector<PortDecl> ports;
  Loc loc;  // the name
  const PortDecl* find_port(const std::string& port) const;
};

// One name declared by `event e, f [lifetime D];`.
struct EventName {
  std::string name;
  Loc loc;
};

// `event e, f [lifetime D];`: events set and unset by monitor code.
struct EventDecl {
  std::vector<EventName> names;
  std::optional<Duration> lifetime;
  Loc loc;
};

// `events from M.p { e, f = "flag" } lifetime D;`
// `otherwise absent after D` on a feed's declaration.
struct FailOpen {
  std::string word;  // `absent`, the only one sema accepts
  Loc word_loc;
  Duration after;
};

struct StatusEventDecl {
  struct Entry {
    std::string event;  // the event's name
    std::string flag;   // the module's flag name; the event's name unless `= "flag"`
    Loc loc;
  };
  PortRef source;
  std::vector<Entry> entries;
  std::optional<Duration> lifetime;
  std::optional<FailOpen> fail_open;
  Loc loc;
};

// `event e = M.p : PRED [for D];`
struct DerivedEventDecl {
  std::string name;
  PortRef source;
  ExprPtr predicate;                 // over the message, bound to the source port's name
  std::optional<Duration> lifetime;  // `for D`
  std::optional<FailOpen> fail_open;
  Loc loc;  // the name
};

// `event e = lock M.p [: PRED] [timeout D | otherwise open after D];` (docs/language.md#locks):
// engaged while its last message says so, and while its publisher has not spoken since the
// start or (with `timeout`) has been silent that long. desugar_locks.h writes it as two derived
// events before sema, and the name, where a constraint reads it, as their disjunction.
struct LockDecl {
  std::string name;
  Loc loc;  // the name
  PortRef source;
  ExprPtr predicate;  // null: the message itself (a bool port), or its `data` (std_msgs/Bool)
  std::optional<Duration> timeout;
  std::optional<FailOpen> open_after;  // `otherwise open after D`: silence opens it
};

// `exclusive { a, b, c };`
struct ExclusiveDecl {
  std::vector<EventName> events;
  Loc loc;
};

// `invariant EXPR;`
struct InvariantDecl {
  ExprPtr formula;
  Loc loc;
  Constraint constraint;  // sema
};

// `then set e` / `then unset e` of a rule: done by the runtime as the rule delivers.
struct DeliveryEffect {
  bool set = true;  // false: unset
  std::string event;
  Loc loc;  // the event's name
};

// `name: from M.q [when C] [hold D] [then set e, ...] [{ body }]` or ending in `;`.
struct Rule {
  std::string name;
  PortRef source;
  ExprPtr when;  // null: no `when` (constraint true)
  std::optional<Duration> hold;
  std::vector<DeliveryEffect> on_delivery;  // `then ...`, in the order written
  bool has_body = false;
  Block body;
  Loc loc;  // the name
  // sema:
  const ArbitrateDecl* port = nullptr;
  bool otherwise = false;    // the constraint is `otherwise`
  Constraint constraint;     // the `when` as a tree (true when absent; unused if otherwise)
  std::string message_name;  // the name the message is bound to in the body: source.port
};

// `arbitrate M.p [by priority] [complete] { rules }`
struct ArbitrateDecl {
  PortRef port;
  bool by_priority = false;
  bool complete = false;
  std::vector<Rule> rules;  // in spec order (highest priority first under `by priority`)
  Loc loc;                  // the `arbitrate` keyword
};

// `connect M.q -> N.p [{ body }]`
struct ConnectDecl {
  PortRef source;
  PortRef destination;
  bool has_body = false;
  Block body;
  Loc loc;                   // the `connect` keyword
  std::string message_name;  // sema: source.port
};

// `assert M.p: rule -> EXPR;`
struct AssertDecl {
  PortRef port;
  std::string rule;
  Loc rule_loc;
  ExprPtr property;
  Loc loc;  // the `assert` keyword
  // sema:
  const Rule* rule_decl = nullptr;
  // A property that reads `emitted` is over what the rule delivers (a bool over the port's
  // value, docs/checks.md#assert-over-data); any other is a constraint over events.
  bool over_data = false;
  Constraint constraint;
};

// A property over time (docs/language.md#properties-over-time), decided by verify/temporal/:
//   Spacing    `never two RULE within D;`   RULE never delivers twice less than D apart;
//              `never RULE within D after OTHER;`  nor less than D after a delivery of OTHER;
//   Absence    `never RULE while EVENT;`    RULE delivers nothing while EVENT is present;
//   Precedence `only RULE after OTHER;`     each delivery of RULE follows one of OTHER with no
//                                           delivery of RULE in between.
//   Response   `after OTHER [stops], RULE within D [while C];`  RULE delivers within D of each
//                                           delivery of OTHER (its last one, with `stops`) whenever
//                                           C holds at RULE's decisions in that window. OTHER may
//                                           be an event (each time it becomes present in the
//                                           port) and RULE a port `M.p` (any of its rules).
//   Stability  `stable M.p for D;`          the rule delivering into M.p changes at most once
//                                           in any D (two switches are at least D apart).
struct TemporalDecl {
  enum class Kind { Spacing, Absence, Precedence, Response, Stability };
  Kind kind = Kind::Spacing;
  std::string rule;
  Loc rule_loc;
  Duration window;                           // Spacing, Response
  bool stops = false;                        // Response: the trigger is OTHER's last delivery
  ExprPtr condition;                         // Response: `while C`; null: none
  Constraint condition_sema;                 // sema: C as a constraint (true without `while`)
  PortRef port;                              // Stability, a Response answered by a port
                                             // (their rule is empty)
  const ArbitrateDecl* port_decl = nullptr;  // sema: that arbitrated port
  std::string event;  // Absence; Response: the trigger, when OTHER names an event (sema moves it)
  Loc event_loc;
  std::string other;  // Precedence, Response, Spacing with `after` (empty without)
  Loc other_loc;
  Loc loc;  // the `never` or `only` keyword
  // sema:
  const Rule* rule_decl = nullptr;
  const Rule* other_decl = nullptr;  // Precedence, Response, Spacing with `after`
};

// An environment assumption (docs/language.md#environment-assumptions),
// `assume EVENT only after AFTER [until UNTIL];`: at every decision of a message into the port
// both rules go into, EVENT (set only by feeds) is present only if AFTER has delivered and,
// with `until`, UNTIL has not delivered since.
struct AssumeDecl {
  std::string event;
  Loc event_loc;
  std::string after;
  Loc after_loc;
  std::string until;  // empty: no `until`
  Loc until_loc;
  // `assume not EVENT for D after RULE;` (the timed form): D; its expr is null for the other.
  Duration absent_for;
  Loc loc;  // the `assume` keyword
  // sema:
  const Rule* after_decl = nullptr;  // null: reported, lowering skips it
  const Rule* until_decl = nullptr;
};

// `given M.p every D;`: source M.p publishes at least every D from the start
// (docs/language.md#properties-over-time).
struct RateDecl {
  PortRef port;
  Duration period;
  Loc loc;  // the `given` keyword
};

// `resource NAME { M.p, N.q } [when PRED];`: the ports share a resource; PRED, over the
// delivered value bound to `emitted`, says which commands use it (all, without `when`).
struct ResourceDecl {
  std::string name;
  std::vector<PortRef> ports;
  ExprPtr uses;  // null: every delivered command uses the resource
  Loc loc;       // the name
};

// What an event name refers to (sema builds one per declared event).
struct EventSymbol {
  enum class Kind { Manual, Status, Derived };
  Kind kind = Kind::Manual;
  std::string name;
  std::optional<Nanos> lifetime;
  std::string source;                    // "Module.port" for Status and Derived
  std::string flag;                      // Status: the module's flag name
  std::optional<Nanos> fail_open_after;  // Status, Derived: `otherwise absent after D`
  Loc loc;
};

// ---------------------------------------------------------------------------------------------
// Tests (`arbc test`, docs/testing.md). They describe runs of the app, not the app: lowering to
// app.json ignores them; compiler/lower/test_cases.h turns them into model::TestCase values.

// `at D` or `within D1..D2` after an expectation; absent: the whole test.
struct TestWindow {
  bool present = false;
  Duration from, to;  // `at D`: both are D (to.expr is null)
  Loc loc;
};

// `at D M.p <- VALUE;` (Input) or `at D set e;` / `at D unset e;`.
struct TestStep {
  enum class Kind { Input, Set, Unset };
  Kind kind = Kind::Input;
  Duration at;
  PortRef port;       // Input
  ExprPtr value;      // Input
  std::string event;  // Set, Unset
  Loc event_loc;
  Loc loc;
};

struct TestExpect {
  enum class Kind {
    Receives,         // `expect M.p receives [VALUE] [window];`
    Nothing,          // `expect M.p receives nothing [window];`
    Drops,            // `expect RULE drops ["reason"] [window];`
    Delivers,         // `expect RULE delivers [window];`
    DeliversNothing,  // `expect RULE delivers nothing [window];`
    Property,         // `expect never two take within 1s;` (any property over time): the whole run
    State,            // `expect CONSTRAINT [in M.p] at D;`
    Exclusive,        // `expect exclusive M.p;`: no two rules of the port selected at once
    Assert,           // `expect assert M.p: RULE -> EXPR;`: EXPR holds at each delivery of RULE
    Resource,         // `expect resource R;`: no two of R's ports receive a command using it
  };
  Kind kind = Kind::Receives;
  PortRef port;      // Receives, Nothing, Exclusive; State: `in M.p` (empty module: none)
  ExprPtr value;     // Receives: null means any value; State: the constraint
  std::string rule;  // Drops, Delivers, DeliversNothing; Resource: the resource
  Loc rule_loc;
  std::string reason;  // Drops: empty means any reason
  Loc reason_loc;
  TestWindow window;
  std::string text;  // as written (without `expect` and `;`), for failure messages
  Loc loc;
  // sema:
  const Rule* rule_decl = nullptr;         // Drops, Delivers, DeliversNothing
  Constraint constraint;                   // State
  std::shared_ptr<TemporalDecl> property;  // Property
  std::shared_ptr<AssertDecl> assertion;   // Assert (checked by sema as a declared one)
};

// `test "name" [on RULE] { steps and expectations }`
struct TestDecl {
  std::string name;
  std::string on;  // a rule to test alone; empty: the whole app
  Loc on_loc;
  std::vector<TestStep> steps;  // in the order written
  std::vector<TestExpect> expects;
  Loc loc;                        // the name
  const Rule* on_rule = nullptr;  // sema
};

// `tests for "app.spec";`: this file holds tests of the app in that spec (docs/testing.md).
struct TestsFor {
  std::string path;  // as written: relative to the tests file's folder
  Loc loc;           // the string
};

// One spec file.
struct Spec {
  std::string file;
  std::optional<AppDecl> app;
  std::vector<UseDecl> uses;
  // The names of types a `use` could not declare (reported there): a port or field of such a
  // type is not reported again as an unknown type (ros2_uses.h).
  std::set<std::string> failed_uses;
  std::vector<TypeDecl> types;  // after the `type` declarations, those `uses` declare
  std::vector<ConstDecl> consts;
  std::vector<ModuleDecl> modules;
  std::vector<EventDecl> events;
  std::vector<StatusEventDecl> status_events;
  std::vector<DerivedEventDecl> derived_events;
  std::vector<LockDecl> locks;  // gone after desugar_locks (into derived_events)
  std::vector<ExclusiveDecl> exclusives;
  std::vector<InvariantDecl> invariants;
  std::vector<ArbitrateDecl> arbitrations;
  std::vector<ConnectDecl> connects;
  std::vector<AssertDecl> asserts;
  std::vector<TemporalDecl> temporal;
  std::vector<AssumeDecl> assumptions;
  std::vector<RateDecl> rates;
  std::vector<ResourceDecl> resources;
  std::vector<TestDecl> tests;
  std::optional<TestsFor> tests_for;  // a tests file (frontend.cc merges it into its app)

  // sema: every event by name, in declaration order.
  std::vector<EventSymbol> event_symbols;

  Spec() = default;
  Spec(Spec&&) = default;
  Spec& operator=(Spec&&) = default;
  Spec(const Spec&) = delete;
  Spec& operator=(const Spec&) = delete;

  const ModuleDecl* find_module(const std::string& name) const;
  const EventSymbol* find_event(const std::string& name) const;
  const ArbitrateDecl* find_arbitration(const std::string& qualified_port) const;
};

// The activity event `by priority` generates for a rule above the lowest: "act_" + rule
// (docs/lowering.md). The name is reserved: sema rejects a declared event that takes it.
std::string activity_event_name(const std::string& rule);

// The operator `written` as a string with static storage, for Expr::op; `written` must be one of
// the grammar's operators (+ - * / % < <= > >= == != and or not), else std::logic_error.
std::string_view operator_spelling(std::string_view written);

}  // namespace arbc::ast
