// Questions about message data (docs/checks.md#message-data): can these rules accept the same
// message (or independent messages), with what they emit satisfying given predicates? One Z3 query
// over the encoded bodies (verify/body_encoding.h), in the theories of the data (IEEE doubles,
// 64-bit bit-vectors, strings, bounded lists), norms abstract until a model needs them.
#pragma once

#include <z3++.h>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/app_model.h"
#include "core/value.h"
#include "verify/body_encoding.h"
#include "verify/port_solver.h"
#include "verify/solver_timeout.h"
#include "verify/sym_value.h"

namespace arbc::verify {

// Lists in messages have at most this many elements unless --list-bound says otherwise.
inline constexpr int kDefaultListBound = 4;

// One side of a data question: a rule that accepts its message and, if `emitted_holds` is
// set, delivers a value for which that predicate (over the delivered value) holds. Sides with
// the same source read the same message; sides with different sources, independent ones.
struct DataSide {
  const model::Connection* connection = nullptr;
  const model::BodyExpr* emitted_holds = nullptr;
  // Ask instead that the predicate does NOT hold: false, or reading a value that does not
  // exist (an assert over data fails then too).
  bool negate = false;
};

struct DataWitness {
  std::vector<Value> messages;  // one per distinct source, in the order of the sides
  std::vector<std::string> message_sources;
  std::vector<Value> emitted;  // by side
  // Abstracted monitor state the witness assumes ("var n = 3"), by side; empty when none.
  std::vector<std::vector<std::string>> assumed_state;
};

// Why no message satisfies the question: per side, the `accept` lines in an unsat core, and
// whether the side's emitted predicate is in it.
struct DataCore {
  std::vector<std::vector<int>> accept_lines;
  std::vector<bool> predicate_used;
};

// One incremental solver for the whole app: each source's message is one set of constants,
// each rule is encoded once with an indicator literal, and every question is a check under
// assumptions, so a pair costs a solver call, not a new encoding.
class DataQuery {
 public:
  DataQuery(const model::App& app, z3::context& ctx, int list_bound, Clock::time_point deadline);

  // Why the connection's body is opaque for data ("" when it can be encoded).
  std::string opaque_reason(const model::Connection& c);

  // Why `p` over what `c` delivers cannot be encoded ("" when it can, and c can).
  std::string predicate_opaque_reason(const model::Connection& c, const model::BodyExpr& p);

  // A rule that accepts every message on `source` and delivers it unchanged, owned by the
  // query: a side on it with a predicate asks about the message itself, as a feed's derived
  // event reads it (verify/temporal/feed_outcomes.h). Never in bounded_rules(): it is no rule
  // of the app, and its askers check bounded() themselves.
  const model::Connection& pass_through(const std::string& source);

  // Sat: a witness; Unsat: the core. Every side must be encodable (opaque_reason empty).
  Answer ask(const std::vector<DataSide>& sides, DataWitness* witness, DataCore* core);

  // What `p` can be on a value `c` delivers (a message `c` accepts): true, false, or without a
  // value (it reads one that does not exist, and the generated Lua fails). Each is false only
  // when the solver says it cannot happen; unknown answers, an opaque rule or predicate say
  // "can". The temporal model of a delivery event reads it (verify/temporal/own_delivery.h).
  struct PredicateRange {
    bool can_true = true, can_false = true, can_fail = true;
  };
  PredicateRange predicate_range(const model::Connection& c, const model::BodyExpr& p);

  // Whether `predicate` (over a delivered value) holds on the concrete `value` of type `t`;
  // nullopt when it cannot be decided (opaque, solver trouble).
  std::optional<bool> holds(const model::BodyExpr& predicate, const Value& value, const Type& t);

  // Whether the answers about `c` (and `p` over what it delivers) hold only for lists of at most
  // the list bound: its body or the predicate reads elements at an index it does not know
  // (EncodedBody::bounded). Else they hold for lists of any length.
  bool bounded(const model::Connection& c, const model::BodyExpr* p = nullptr, bool negate = false);
  // The rules some unsat answer so far rested on the list bound for (the report's assumption;
  // the runtime drops longer lists into them: model::Connection::list_bound).
  const std::set<const model::Connection*>& bounded_rules() const { return bounded_rules_; }
  bool bound_used() const { return !bounded_rules_.empty(); }
  int list_bound() const { return list_bound_; }

  std::string unknown_reason() const { return unknown_reason_; }
  const model::App& app() const { return app_; }
  int queries() const { return queries_; }

 private:
  struct Encoded;  // a rule's encoding (data_query.cc)
  const Encoded& encoded(const model::Connection& c);
  const SymValue& message(const std::string& source);
  z3::expr predicate_literal(const model::Connection& c, const model::BodyExpr& p, bool negate);
  void spend_tail_reads(const std::string& source, EncodedBody& b);
  Answer check(const z3::expr_vector& assumptions);
  void fill_witness(const std::vector<DataSide>& sides, const z3::expr_vector& assumptions,
                    DataWitness& witness);
  bool lengths_agree(const z3::model& m) const;
  void refine_lengths(const z3::model& m, bool bounds);
  bool repaired(const z3::expr_vector& assumptions, const z3::model& m);
  std::optional<z3::model> settled(const z3::expr_vector& assumptions, const z3::model& m);
  std::vector<std::pair<std::vector<z3::expr>, z3::expr>> bound_points(const z3::model& m,
                                                                       const AbstractLength& l);

  const model::App& app_;
  z3::context& ctx_;
  int list_bound_;
  z3::solver solver_;
  std::map<std::string, SymValue> messages_;
  std::map<std::string, z3::expr> within_bound_;  // by source: its list lengths <= the bound
  std::set<unsigned> bounded_predicates_;         // predicate literals (ids) that assume it
  std::map<std::string, int> tail_budget_;        // by source: scanning reads its lists still allow
  std::set<const model::Connection*> bounded_rules_;
  std::map<const model::Connection*, std::shared_ptr<Encoded>> rules_;
  std::map<std::string, std::unique_ptr<model::Connection>> pass_through_;  // by source
  std::map<std::tuple<const model::Connection*, const model::BodyExpr*, bool>, z3::expr>
      predicates_;
  std::vector<AbstractLength> lengths_;      // norms still abstract (check)
  std::optional<z3::model> repaired_model_;  // the last check's model, when a repair found it
  // `not p` and `p or not p` per predicate p, asked as predicates of their own (their
  // addresses key predicates_, so they live as long as the query).
  struct Derived {
    model::BodyExpr negated, total;
  };
  std::map<const model::BodyExpr*, Derived> derived_;
  // predicate_range's answers: the temporal model asks them again for every property over the
  // port (three queries each; 26% of `verify specs/table_clean.spec` before they were kept).
  std::map<std::pair<const model::Connection*, const model::BodyExpr*>, PredicateRange> ranges_;
  std::string unknown_reason_;
  int queries_ = 0;
  Clock::time_point deadline_;  // of the whole run: holds() asks its own solver within it
  SolverTimeout timeout_;
};

// A value in spec syntax: `[{ dist: 0.3, pos: vec3(0.3, 0, 0) }]`, `"take"`, `0.4`. With its
// type, a uint64 (held as its bits, core/type.h) is written as its unsigned value, which reads
// back as that uint64 in a test (a counterexample kept with --counterexamples).
std::string spec_value_text(const Value& v, const Type* type = nullptr);

// The type of the port `qualified` ("M.p") in `app`; null when there is none.
const Type* port_type_of(const model::App& app, const std::string& qualified);

}  // namespace arbc::verify
