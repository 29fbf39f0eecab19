// What `arbc verify` found: per-port verdicts and findings (docs/checks.md).
//
// The report is a plain value: the checks fill it in, the text / JSON / SARIF writers read it.
// Nothing in it depends on Z3, so tools that only print reports need not link the solver.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/check_ids.h"
#include "core/diagnostic.h"
#include "core/test_case.h"

namespace arbc::verify {

enum class Verdict { Proved, Refuted, Unknown };

const char* verdict_name(Verdict v);  // "proved", "refuted", "unknown"

// Stable check ids, used in diagnostics, JSON, SARIF and docs/checks.md anchors.
inline constexpr const char* kCheckExclusive = diag::Exclusive.text();
inline constexpr const char* kCheckDead = diag::Dead.text();
inline constexpr const char* kCheckUnfed = diag::Unfed.text();
inline constexpr const char* kCheckUnused = diag::Unused.text();
inline constexpr const char* kCheckOwnership = diag::Ownership.text();
inline constexpr const char* kCheckComplete = diag::Complete.text();
inline constexpr const char* kCheckAssert = diag::Assert.text();
inline constexpr const char* kCheckUnknown = diag::Unknown.text();    // the solver gave no answer
inline constexpr const char* kCheckInternal = diag::Internal.text();  // Z3 and the runtime disagree
inline constexpr const char* kCheckResource = diag::Resource.text();
inline constexpr const char* kCheckTemporal =
    diag::Temporal.text();  // a property over time is violated
// A response whose window cannot close within --temporal-bound messages at the given rates.
inline constexpr const char* kCheckTemporalBound = diag::TemporalBound.text();
// A property over time about an event nothing can put into its port's container: it says nothing.
inline constexpr const char* kCheckVacuous = diag::Vacuous.text();
// A rule that accepts no message whose lists have at most --list-bound elements.
inline constexpr const char* kCheckListBound = diag::ListBound.text();

// A decision state: which of the port's events are present. Both lists are sorted.
struct EventState {
  std::vector<std::string> present;
  std::vector<std::string> absent;
};

struct Note {
  std::string message;
  model::SourceLocation loc;
};

// A concrete message that shows a data finding (docs/checks.md#message-data), in spec syntax, and
// what the runtime's Lua monitors did with it when it was replayed.
struct MessageExample {
  std::string source;               // "ObjectDetector.objects"
  std::string value;                // `[{ dist: 0.3, pos: vec3(0, 0, 0) }]`
  std::vector<std::string> replay;  // one line per rule: "'take' accepts and delivers ..."
};

struct Finding {
  std::string check;  // one of the kCheck* ids
  Severity severity = Severity::Error;
  std::string port;                // "Module.port"; empty for findings about the whole app
  std::vector<std::string> rules;  // rules or connections involved, in spec order
  // The arbitrated port of each rule, parallel to `rules`, when they go into different ports
  // (a resource's pair); empty: every rule goes into `port`. A rule's name is unique only
  // within its port, so a rule is found by both (rule_port).
  std::vector<std::string> rule_ports;
  // Where each of those rules is in the spec, parallel to `rule_ports` (SARIF places a
  // resource finding at both rules); empty with it.
  std::vector<model::SourceLocation> rule_locs;
  std::string event;  // the event concerned (unfed, unused, ownership)
  std::string message;
  model::SourceLocation loc;
  std::optional<EventState> counterexample;
  std::vector<MessageExample> messages;  // data findings: the message(s) that show it
  std::vector<Note> notes;               // why each side holds, what to do
  bool strict = false;                   // a warning (dead, unused) that --strict made an error
  // A counterexample to a claim about single decisions (`exclusive`, `assert`) as a test that
  // states the claim in its expectation (verify/claim_test.h), for --counterexamples; nullopt
  // when it cannot be written, with `not_replayable` saying why (empty: not such a finding).
  std::optional<model::TestCase> replay_test;
  std::string not_replayable;

  // The port of rules[i]; empty when the finding does not say.
  const std::string& rule_port(size_t i) const {
    return i < rule_ports.size() ? rule_ports[i] : port;
  }
};

// The outcome for one arbitrated port.
struct PortResult {
  std::string port;
  bool by_priority = false;
  bool complete = false;
  model::SourceLocation loc;
  Verdict verdict = Verdict::Proved;
  // The candidates: rules that can deliver, in spec order. A feed (a rule written `when false`
  // whose body or script sets or unsets events, as `arbc import yarp` writes a YARP monitor
  // that only sets events) is never one, so the proof's claim does not name it.
  std::vector<std::string> rules;
  std::vector<std::string> feeds;       // the port's feeds, in spec order
  std::vector<std::string> events;      // the port's scope, sorted
  std::vector<std::string> invariants;  // texts of the invariants used
  int exclusive_groups = 0;             // exclusive groups used
  int asserts = 0;
  int overlapping_pairs = 0;   // all overlapping pairs found (reported or only counted)
  int reported_pairs = 0;      // pairs reported with a counterexample (at most the cap)
  std::string unknown_reason;  // when verdict is Unknown: "timeout", "resource limit", ...
  std::vector<Finding> findings;
  // Pairs that overlap in some event state but never accept the same message, each with why
  // ("'take' and 'put': ...").
  std::vector<std::string> exclusive_by_data;
  // Pairs that overlap in some event state but whose deliveries keep each other out
  // (verify/delivery_order.h), each with why.
  std::vector<std::string> exclusive_by_delivery;
  // A proved verdict that rests on message data with lists, encoded with at most this many
  // elements (--list-bound): the verdict's first line says "for lists of at most N elements".
  // 0: no such claim.
  int list_bound = 0;
  double seconds = 0;  // wall time, printed only with --stats
  int solver_queries = 0;
};

// One step of a timed counterexample (docs/design.md#properties-over-time): one message that
// one connection into the port handled.
struct TraceStep {
  Nanos time{0};                        // since the start of the run
  std::string connection;               // the rule or feed that ran
  std::string source;                   // "Module.port" that published the message
  bool feed = false;                    // a generated feed: it sets events, never delivers
  bool accepted = false;                // its `accept` accepted (message data is abstract)
  std::vector<std::string> set, unset;  // entries it set / removed in the port's container
  bool delivered = false;
};

// The outcome for one property over time, decided by bounded model checking.
struct TemporalResult {
  // Proved: for every run, whatever its length (`proof` says by what argument); the search
  // also found no violation up to `bound` messages.
  // Vacuous: about an event nothing can put into the port's container, so true of any run and
  // saying nothing (a `vacuous` warning, never "proved"); `proof` says why.
  enum class Outcome { HoldsToBound, Violated, Unknown, Proved, Vacuous };
  model::TemporalProperty property;
  Outcome outcome = Outcome::Unknown;
  // HoldsToBound and Proved: the largest number of messages into the port explored;
  // Violated: the length of the (shortest) trace.
  int bound = 0;
  std::string proof;    // Proved only: why, in spec terms
  int induction_k = 0;  // Proved by k-induction (verify/temporal/induction.h): its k
  // The environment assumptions the verdict is under (those about the port), printed with it.
  std::vector<model::Assumption> assumptions;
  // Decided among the runs a replay makes (verify/temporal/unrolling.h PortShape::faithful),
  // after the free model's violation did not replay: each message of a source reaches every
  // connection from it into the port together. Printed with the verdict, which is then at best
  // "holds up to the bound".
  bool faithful = false;
  std::vector<TraceStep> trace;  // Violated only
  // The trace as a test of the app that `arbc test` runs (verify/temporal/counterexample.h);
  // nullopt when some step has no message to replay it with (`not_replayable` says why).
  std::optional<model::TestCase> replay_test;
  std::string not_replayable;
  // The runtime ran replay_test in simulated time and showed the violation: only then is the
  // outcome Violated (docs/design.md#properties-over-time).
  bool replayed = false;
  std::string unknown_reason;
  int solver_queries = 0;
  // The environment rates (`given M.p every D`) the verdict relies on: those of the sources of
  // the port's connections, which the search assumed (verify/temporal/rates.h).
  std::vector<model::SourceRate> rates;
  // HoldsToBound with rates: the shortest run they fill with more than `bound` messages
  // (Rates::span), so the search saw only shorter runs; 0 otherwise.
  Nanos rated_span{0};
  // A response with rates: the fewest messages into the port of a run in which a window
  // closes (the rated sources' messages due by its length, and the trigger when its source
  // has no rate). A bound below it cannot show a violation; 0 otherwise.
  int window_bound = 0;
  // A violated response: when its window closed unanswered, and why silence counts
  // ("no rate is given for ..."); empty otherwise.
  std::string explanation;
};

// The outcome for one `resource` (docs/checks.md#resource).
struct ResourceResult {
  std::string name;
  std::vector<std::string> ports;
  model::SourceLocation loc;
  Verdict verdict = Verdict::Proved;
  int pairs = 0;  // pairs of rules (into different ports) checked
  // Per proved pair, why: neither can be selected in the state the other's delivery leaves
  // ("exclusive by events"), or one of them never delivers a command that uses it ("exclusive
  // by data").
  std::vector<std::string> exclusive_by_events;
  std::vector<std::string> exclusive_by_data;
  int list_bound = 0;  // as PortResult::list_bound
  std::vector<Finding> findings;
  std::string unknown_reason;
};

struct VerifyReport {
  std::string app;
  std::string spec_file;
  std::vector<PortResult> ports;
  std::vector<Finding> app_findings;  // findings not about one arbitrated port
  std::vector<ResourceResult> resources;
  // What a verdict that used message data assumes (docs/checks.md#message-data); empty when
  // no data question was asked.
  std::vector<std::string> assumptions;
  std::vector<TemporalResult> temporal;  // properties over time, in spec order
  // The rules (destination, name) whose proofs hold for lists of at most `list_bound` elements
  // (DataQuery::bounded_rules): `arbc build` records it in app.json (Connection::list_bound),
  // and the runtime drops longer lists into them.
  std::vector<std::pair<std::string, std::string>> bounded_rules;
  int list_bound = 0;
  Verdict verdict = Verdict::Proved;  // refuted if any error, else unknown if any unknown
  double seconds = 0;
  int solver_queries = 0;

  int count(Severity s) const;  // findings of that severity, ports and app together
};

// A finding as a compiler-style diagnostic (message, location, notes, counterexample).
Diagnostic to_diagnostic(const Finding& f);

}  // namespace arbc::verify
