// The core model: what an application is after lowering (docs/design.md#pipeline).
//
// The compiler produces it, app.json serialises it (round trip), the verifier and the code
// generators read it, and the runtime runs it. It lives in runtime/ because the runtime loads
// app.json without the compiler; nothing here knows about the spec language's syntax.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/body.h"
#include "core/constraint.h"
#include "core/file_name.h"
#include "core/instant.h"
#include "core/type.h"

namespace arbc::model {

inline constexpr int kSchemaVersion = 2;

// A place in the spec, for diagnostics and the source map. Lines and columns count from 1;
// 0 means unknown (e.g. a model loaded from a hand-written app.json).
struct SourceLocation {
  FileName file;  // shared, not copied (core/file_name.h)
  int line = 0;
  int column = 0;
  int end_line = 0;
  int end_column = 0;
};

enum class Direction { In, Out };

struct Port {
  std::string name;
  Direction direction = Direction::In;
  TypePtr type;
  SourceLocation loc;
};

// `type Name = T;`: a named type of the spec, for the transports that name types on the wire
// (DDS, docs/distributed.md). Port and field types are structural (named types expanded).
struct NamedType {
  std::string name;
  TypePtr type;
  SourceLocation loc;
  // The ROS 2 message a `use ros2` declared it from ("geometry_msgs/msg/Twist"): its name on the
  // wire (dds/wire_types.cc) when the deployment file does not map it. Empty for a `type`.
  std::string ros2 = {};
};

struct Module {
  std::string name;
  std::string doc;
  std::vector<Port> ports;
  SourceLocation loc;
};

// An event any container may hold. `source` is "Module.port" for events fed from a stream
// (`events from`, derived events) and empty for events set by hand-written monitor code.
struct Event {
  std::string name;
  std::optional<Nanos> lifetime;  // none: until unset
  std::string source;
  SourceLocation loc;
  // A derived event's predicate over its source's message (BodyExpr::Op::Message); for a
  // delivery event (`source` an arbitrated in-port, docs/language.md#delivery-events), over
  // what that port delivers. nullopt: not derived, or not recorded. The resource check reads
  // it (verify/resource_checks.h): which deliveries set the event.
  std::optional<BodyExpr> predicate = std::nullopt;
  // A status event (`events from M.p { e, f = "flag" }`): the flag of `source`'s list that
  // sets it ("flag" for f, "e" for e). Empty for every other event. Stand-in sources publish
  // these, so a `--stub` run reaches the feeds (docs/cli.md, `--stub`).
  std::string flag = "";
  // `otherwise absent after D` (docs/language.md#a-feed-that-may-fail-open): after a start, the
  // event counts as absent once its feed has been silent for D, instead of staying unknown
  // until the feed speaks (runtime/unknown_events.cc). nullopt: unknown until then.
  std::optional<Nanos> fail_open_after = std::nullopt;
};

// One line of a generated monitor and the spec line it comes from, so a script error at
// `monitors/x.lua:42` can be reported at the spec line that wrote it.
struct SourceMapEntry {
  int monitor_line = 0;
  int spec_line = 0;
  bool operator==(const SourceMapEntry&) const = default;
};

enum class ConnectionKind {
  Rule,     // a user's rule into an arbitrated port
  Feed,     // generated: carries events into an arbitrated port's container, never delivers
  Connect,  // a monitored connection into a port that is not arbitrated
};

struct Connection {
  std::string name;         // rule name ("take"), or a generated name for feeds
  std::string source;       // "Module.port"
  std::string destination;  // "Module.port"
  ConnectionKind kind = ConnectionKind::Rule;
  bool generated = false;  // written by the compiler rather than by the user
  Constraint constraint;   // selection constraint; false for feeds, true for plain connects
  // Events the monitor can set / unset on some path, and on every accepting path
  // (docs/design.md#effective-guards uses must_set and must_unset).
  std::vector<std::string> sets, unsets;
  std::vector<std::string> must_set, must_unset;
  // `by priority` (every rule but the lowest): the event the runtime sets, with its lifetime
  // from `events` (the rule's hold), each time this connection delivers; after the decision,
  // so it is not in must_set, but the effective guard includes it (core/effective_guard.h).
  // Also listed in `sets`: the connection owns its entries. Empty: none.
  std::string activity_event;
  // `then set e` / `then unset e` (docs/language.md#events-set-on-delivery): each time this
  // rule delivers, the runtime sets its own entry of each event of `delivery_sets` (for the
  // event's lifetime in `events`) and removes every entry that deliveries set of each event of
  // `delivery_unsets`, in the task of the delivery, as for `activity_event`. `delivery_sets`
  // are also in `sets` (the connection owns those entries); neither is in must_set.
  std::vector<std::string> delivery_sets, delivery_unsets;
  // Whether the runtime sets `e` as this connection delivers (its activity event or a
  // `then set`), rather than its monitor as it accepts.
  bool set_on_delivery(std::string_view e) const {
    if (e == activity_event) return true;
    for (const std::string& s : delivery_sets)
      if (s == e) return true;
    return false;
  }
  bool opaque = false;  // a `script` rule: its code is not analysed
  // The generated monitor's body, for proofs over message data (core/body.h). nullopt: not
  // recorded (a script, a feed, an app.json written before bodies were): opaque for data.
  std::optional<Body> body;
  std::optional<Nanos> trig_interval;  // from `every`
  std::optional<Nanos> throttle;       // from `throttle`
  // The proof of what this rule accepts and delivers covers messages whose lists have at most
  // this many elements (verify's --list-bound, where an answer about the rule rested on it:
  // docs/checks.md#message-data); the runtime drops a message with a longer list before the
  // monitor, counted `bad-value`. 0: any length (the proof needed no bound).
  int list_bound = 0;
  std::string monitor;  // Lua file relative to the app directory; empty: none
  // SHA-256 of the monitor file as `arbc build` wrote it (64 hex digits); readers of an app
  // directory refuse a monitor whose bytes differ (core/monitor_digests.h). Empty in models
  // built in code, which are not read from a directory.
  std::string monitor_sha256;
  std::vector<SourceMapEntry> source_map;  // monitor lines -> spec lines (of loc.file)
  SourceLocation loc;
};

// `assert PORT: rule -> property;`
struct Assertion {
  std::string rule;
  Constraint property;  // over events; unused (true) when `emitted` is set
  SourceLocation loc;
  // Over the delivered value (BodyExpr::Op::Message): the assert is about data
  // (docs/checks.md#assert-over-data). Last, so `{rule, property, loc}` still initialises one.
  std::optional<BodyExpr> emitted;
};

struct ArbitratedPort {
  std::string port;  // "Module.port"
  bool by_priority = false;
  bool complete = false;
  std::vector<std::string> rules;  // names of the Rule connections into it, in spec order
  std::vector<Assertion> asserts;
  SourceLocation loc;
};

// `exclusive { a, b, c };`: at most one of the events is present.
struct ExclusiveGroup {
  std::vector<std::string> events;
  SourceLocation loc;
};

// `invariant EXPR;`: EXPR over events always holds.
struct Invariant {
  Constraint formula;
  SourceLocation loc;
};

// A property over time (docs/design.md#properties-over-time) about `rule`, a rule into `port`:
//   Spacing    `never two RULE within W;`  never delivers twice less than `window` seconds apart;
//              `never RULE within W after OTHER;`  with `other` (a rule into the same port):
//                                          never delivers less than `window` after OTHER did;
//   Absence    `never RULE while EVENT;`   never delivers while `event` is present in the
//                                          port's container at the decision;
//   Precedence `only RULE after OTHER;`    each delivery follows a delivery of `other` (a rule
//                                          into the same port) with no delivery of RULE between.
//   Response   `after OTHER [stops], RULE within D [while C];`  RULE delivers within D of
//                                          each delivery of OTHER (of its last one: `stops`)
//                                          unless C is false at one of RULE's decisions then.
//   Stability  `stable M.p for D;`         the rule delivering into `port` changes at most once
//                                          in any D (`rule` is empty).
struct TemporalProperty {
  enum class Kind { Spacing, Absence, Precedence, Response, Stability };
  Kind kind = Kind::Spacing;
  std::string port;  // "Module.port"
  std::string rule;  // empty: Stability; a Response answered by any rule of the port
  Nanos window{0};   // Spacing, Response, Stability
  SourceLocation loc;
  std::string event;     // Absence; Response: the trigger is EVENT becoming present (other empty)
  std::string other;     // Precedence, Response (the trigger), Spacing (empty: RULE itself)
  bool stops = false;    // Response: the trigger is OTHER's last delivery
  Constraint condition;  // Response: `while C` (true without one)
};

// `given M.p every D;`: the environment publishes on source M.p at least every `period`
// seconds from the start; response properties rely on it (docs/design.md#properties-over-time).
struct SourceRate {
  std::string port;  // "Module.port", an out port
  Nanos period{0};
  SourceLocation loc;
};

// "spacing", "absence", "precedence", "response", "stability": the `kind` in app.json and verify's
// JSON.
const char* temporal_kind_name(TemporalProperty::Kind k);

// The property as a spec writes it, without `;` ("never two take within 1s"), for verify's
// verdicts, the tests it writes and the runtime's checks.
std::string temporal_property_text(const TemporalProperty& p);

// An assert as a spec writes it, without `;` ("assert Arm.cmd: take -> e_idle", "assert Arm.cmd:
// take -> emitted.speed <= 0.5"), for the runtime's checks, the verifier's messages and the tests
// `arbc verify --counterexamples` writes.
std::string assertion_text(const std::string& port, const Assertion& a);

// An environment assumption (docs/language.md#environment-assumptions) about EVENT, an event
// only feeds set, at every decision of a message into `port`:
//   `assume EVENT only after AFTER [until UNTIL];`  the port's container holds EVENT only if
//       rule `after` has delivered and, when `until` is not empty, rule `until` has not
//       delivered since. Both rules go into `port`.
//   `assume not EVENT for D after AFTER;`  (`absent_for` = D) the container does not hold
//       EVENT less than D after a delivery of rule `after`: the environment answers a
//       delivery (an arm busy with a `take`) before the next message, for D.
struct Assumption {
  std::string event;
  std::string port;  // "Module.port"
  std::string after;
  std::string until;  // empty: EVENT may stay once `after` has delivered
  SourceLocation loc;
  std::optional<Nanos> absent_for;  // the timed form (then `until` is empty)
};

// An environment assumption as a spec writes it, without `;`, for verify's verdicts and the
// runtime's checks.
std::string assumption_text(const Assumption& a);

// `resource NAME { M.p, ... } [when PRED];`: at most one of the ports receives a command that
// uses the resource, for one message or two (docs/checks.md#resource).
struct Resource {
  std::string name;
  std::vector<std::string> ports;  // "Module.port", arbitrated, in spec order
  // Over the delivered value (BodyExpr::Op::Message); nullopt: every command uses it.
  std::optional<BodyExpr> uses;
  SourceLocation loc;
};

struct App {
  int schema_version = kSchemaVersion;
  std::string name;
  std::string description;
  std::string spec_file;
  std::vector<NamedType> types;  // in declaration order
  std::vector<Module> modules;
  std::vector<Event> events;
  std::vector<Connection> connections;
  std::vector<ArbitratedPort> arbitrated_ports;
  std::vector<ExclusiveGroup> exclusive_groups;
  std::vector<Invariant> invariants;
  std::vector<TemporalProperty> temporal;
  std::vector<Assumption> assumptions;
  std::vector<SourceRate> rates;  // at most one per source port
  std::vector<Resource> resources;
  // The script of the proof's claims over delivered values (core/data_claims.h), relative to
  // the app directory, and the SHA-256 of its bytes; empty: the app has none.
  std::string claims_script, claims_script_sha256;

  const Module* find_module(std::string_view name) const;
  const Port* find_port(std::string_view qualified) const;  // "Module.port"
  const Event* find_event(std::string_view name) const;
  // The rate given for source `port`; null when none is.
  const SourceRate* find_rate(std::string_view port) const;
  const ArbitratedPort* find_arbitrated(std::string_view port) const;
  // All connections whose destination is `port`, in model order.
  std::vector<const Connection*> connections_into(std::string_view port) const;
};

}  // namespace arbc::model
