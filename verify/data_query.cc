#include "verify/data_query.h"

#include <algorithm>
#include <map>

#include "core/json_text.h"
#include "verify/body_encoding.h"
#include "verify/lua_number.h"
#include "verify/nice_model.h"
#include "verify/tail_slots.h"

namespace arbc::verify {

namespace {

// The predicate over a delivered value, as a one-statement body `accept P` on that value.
model::Body predicate_body(const model::BodyExpr& p) {
  model::BodyStmt s;
  s.kind = model::BodyStmt::Kind::Accept;
  s.expr = p;
  return {s};
}

std::string state_text(const z3::model& m, const std::pair<std::string, SymValue>& s) {
  std::string name = s.first.rfind("var ", 0) == 0 ? s.first.substr(4) : s.first;
  return name + " = " + spec_value_text(concrete(m, s.second));
}

}  // namespace

struct DataQuery::Encoded {
  EncodedBody body;
  z3::expr accepts;  // indicator: assumed when the question is about this rule
  explicit Encoded(EncodedBody b, z3::expr lit) : body(std::move(b)), accepts(std::move(lit)) {}
};

DataQuery::DataQuery(const model::App& app, z3::context& ctx, int list_bound,
                     Clock::time_point deadline)
    : app_(app),
      ctx_(ctx),
      list_bound_(list_bound),
      solver_(ctx),
      deadline_(deadline),
      timeout_(deadline) {}

std::string DataQuery::opaque_reason(const model::Connection& c) {
  if (c.opaque) return "its monitor is a hand-written script";
  if (!c.body) return "its body is not recorded in the model (rebuild with this arbc)";
  const model::Port* p = app_.find_port(c.source);
  if (!p || !p->type) return "its source port's type is unknown";
  const Encoded& e = encoded(c);
  if (!e.body.opaque.empty()) return "its body uses " + e.body.opaque;
  return "";
}

const model::Connection& DataQuery::pass_through(const std::string& source) {
  std::unique_ptr<model::Connection>& c = pass_through_[source];
  if (!c) {
    c = std::make_unique<model::Connection>();
    c->name = "message";
    c->source = source;
    c->destination = source + "~";  // a name of its own for its constants, no port
    c->body = model::Body{};        // accepts every message and delivers it as it came
  }
  return *c;
}

const SymValue& DataQuery::message(const std::string& source) {
  auto it = messages_.find(source);
  if (it != messages_.end()) return it->second;
  std::vector<z3::expr> domain, within;
  const model::Port* p = app_.find_port(source);
  int slots = tail_slots(app_, source);
  tail_budget_.insert_or_assign(source, slots);
  SymValue m = fresh_value(ctx_, *p->type, source, list_bound_, domain, within, slots);
  for (const z3::expr& d : domain) solver_.add(d);  // list lengths are not negative
  z3::expr all = ctx_.bool_val(true);
  for (const z3::expr& w : within) all = all && w;
  within_bound_.insert_or_assign(source, all);
  return messages_.emplace(source, std::move(m)).first->second;
}

// The connection's body over its source's message, encoded once: `lit implies accepts`, plus
// the definitions of its auxiliary constants (true whatever is assumed).
const DataQuery::Encoded& DataQuery::encoded(const model::Connection& c) {
  auto it = rules_.find(&c);
  if (it != rules_.end()) return *it->second;
  // One clock per source: the rules that read its message judge it at one instant (age()).
  EncodedBody b = encode_body(ctx_, *c.body, message(c.source), c.destination + "/" + c.name,
                              /*abstract_lengths=*/true, "clock@" + c.source);
  z3::expr lit = ctx_.bool_const(("accepts!" + c.destination + "/" + c.name).c_str());
  spend_tail_reads(c.source, b);
  if (b.opaque.empty()) {
    solver_.add(z3::implies(lit, b.accepts));
    // A body exact only for short lists: asking about it assumes the source's lists are short.
    if (b.bounded) solver_.add(z3::implies(lit, within_bound_.at(c.source)));
    for (const z3::expr& x : b.side) solver_.add(x);
    lengths_.insert(lengths_.end(), b.lengths.begin(), b.lengths.end());
  }
  auto e = std::make_shared<Encoded>(std::move(b), lit);
  return *rules_.emplace(&c, e).first->second;
}

// An indicator for "what c delivers satisfies p" (with `negate`: does not); the trackers of
// p's own one `accept` are asserted, so only the indicator is assumed.
z3::expr DataQuery::predicate_literal(const model::Connection& c, const model::BodyExpr& p,
                                      bool negate) {
  auto key = std::make_tuple(&c, &p, negate);
  auto it = predicates_.find(key);
  if (it != predicates_.end()) return it->second;
  const Encoded& e = encoded(c);
  z3::expr lit = ctx_.bool_const(
      ("uses!" + c.destination + "/" + c.name + "#" + std::to_string(predicates_.size())).c_str());
  // Each predicate's own prefix: two predicates on one rule must not share fresh constants.
  EncodedBody pe =
      encode_body(ctx_, predicate_body(p), *e.body.emitted,
                  c.destination + "/" + c.name + ".emitted#" + std::to_string(predicates_.size()),
                  /*abstract_lengths=*/true, "clock@" + c.source);
  spend_tail_reads(c.source, pe);
  // A predicate that cannot be encoded constrains nothing: the literal stays free, so it may
  // hold on any delivery (sound; sema types it on the port, so a checked spec never gets here).
  if (pe.opaque.empty()) {
    solver_.add(z3::implies(lit, negate ? !pe.accepts : pe.accepts));
    if (pe.bounded) {
      solver_.add(z3::implies(lit, within_bound_.at(c.source)));
      bounded_predicates_.insert(lit.id());
    }
    for (const z3::expr& x : pe.side) solver_.add(x);
    for (const AcceptTracker& t : pe.trackers) solver_.add(t.literal);
    lengths_.insert(lengths_.end(), pe.lengths.begin(), pe.lengths.end());
  }
  return predicates_.emplace(key, lit).first->second;
}

// Reads of the stand-ins past the capacity are exact while all encodings over the message
// together make no more than a list has slots (SymValue::tail); an encoding that would make
// more assumes the list bound instead (its answers then say so).
void DataQuery::spend_tail_reads(const std::string& source, EncodedBody& b) {
  if (!b.opaque.empty() || b.bounded || b.tail_reads == 0) return;
  int& left = tail_budget_.at(source);
  if (b.tail_reads <= left)
    left -= b.tail_reads;
  else
    b.bounded = true;
}

bool DataQuery::bounded(const model::Connection& c, const model::BodyExpr* p, bool negate) {
  const Encoded& e = encoded(c);
  if (!e.body.opaque.empty()) return false;  // no data question is asked about it
  if (e.body.bounded) return true;
  if (!p || !e.body.emitted) return false;
  return bounded_predicates_.count(predicate_literal(c, *p, negate).id()) > 0;
}

std::string DataQuery::predicate_opaque_reason(const model::Connection& c,
                                               const model::BodyExpr& p) {
  std::string rule = opaque_reason(c);  // first: a script rule has no body to encode
  if (!rule.empty()) return rule;
  const Encoded& e = encoded(c);
  if (!e.body.emitted) return "it delivers no value";
  std::string pred = encode_body(ctx_, predicate_body(p), *e.body.emitted, "opaque?").opaque;
  return pred.empty() ? "" : "the property uses " + pred;
}

// Norms are abstract (EncodedBody::lengths) until a model needs one: unsat over the abstraction
// is unsat for the machine, and a model in which each norm has the value the monitor computes
// from its components is a model of the machine. A model with a norm that does not is excluded
// by what monotonicity gives from that point (cheap bounds, for every norm) for a few rounds,
// then by the norm's exact circuit, for good. Each later round adds at least one circuit, so
// it ends, at worst with every circuit (the question as precise as it can be).
Answer DataQuery::check(const z3::expr_vector& assumptions) {
  constexpr int kBoundRounds = 32;
  repaired_model_.reset();
  for (int round = 0;; ++round) {
    ++queries_;
    z3::check_result r = verify::check(solver_, timeout_, &unknown_reason_, &assumptions);
    if (r != z3::sat) return r == z3::unsat ? Answer::Unsat : Answer::Unknown;
    z3::model m = solver_.get_model();
    if (lengths_agree(m) || repaired(assumptions, m)) return Answer::Sat;  // repaired_model_
    refine_lengths(m, round < kBoundRounds);
  }
}

// Whether the model's components with each norm as the monitor computes it still answer the
// question; then the solver's model is that one. Cheap: with its components fixed, each circuit
// folds to a constant.
bool DataQuery::repaired(const z3::expr_vector& assumptions, const z3::model& m) {
  bool sat = false;
  try {
    solver_.push();
    for (const AbstractLength& l : lengths_) {
      for (const z3::expr& c : l.components)
        solver_.add(z3::expr(ctx_, Z3_mk_eq(ctx_, c, m.eval(c, true))));
      solver_.add(z3::expr(ctx_, Z3_mk_eq(ctx_, l.result, m.eval(l.exact, true))));
    }
    std::string unknown;
    sat = verify::check(solver_, timeout_, &unknown, &assumptions) == z3::sat &&
          lengths_agree(solver_.get_model());
    if (sat) repaired_model_ = solver_.get_model();
    solver_.pop();
  } catch (const z3::exception&) {
    return false;  // interrupted past the deadline: the next check says unknown
  }
  return sat;
}

std::optional<z3::model> DataQuery::settled(const z3::expr_vector& assumptions,
                                            const z3::model& m) {
  if (lengths_agree(m)) return m;
  if (repaired(assumptions, m)) return repaired_model_;
  return std::nullopt;
}

// Points whose norms bound l's from the model's: the point itself (|components|), each
// component alone (the others 0: a norm is at least that one's) and the largest in all three
// (a norm is at most that one's); each with its norm as the monitor computes it.
std::vector<std::pair<std::vector<z3::expr>, z3::expr>> DataQuery::bound_points(
    const z3::model& m, const AbstractLength& l) {
  std::vector<z3::expr> at;
  for (const z3::expr& c : l.components) at.push_back(m.eval(lua::float_abs(c), true));
  z3::expr zero = lua::float_val(ctx_, 0.0);
  z3::expr largest = at[0];
  for (const z3::expr& a : at)
    if (lua::float_of(a) > lua::float_of(largest)) largest = a;
  std::vector<std::vector<z3::expr>> points = {at, {largest, largest, largest}};
  for (size_t k = 0; k < at.size(); ++k) {
    std::vector<z3::expr> alone(at.size(), zero);
    alone[k] = at[k];
    points.push_back(alone);
  }
  std::vector<std::pair<std::vector<z3::expr>, z3::expr>> out;
  for (const std::vector<z3::expr>& p : points) {
    SymValue n = lua::norm({SymValue::Kind::Float, p[0]}, {SymValue::Kind::Float, p[1]},
                           {SymValue::Kind::Float, p[2]});
    out.emplace_back(p, m.eval(n.scalar, true));
  }
  return out;
}

bool DataQuery::lengths_agree(const z3::model& m) const {
  for (const AbstractLength& l : lengths_)
    if (!lua::same_numeral(m.eval(l.result, true), m.eval(l.exact, true))) return false;
  return true;
}

void DataQuery::refine_lengths(const z3::model& m, bool bounds) {
  for (size_t i = 0; i < lengths_.size();) {
    const AbstractLength& l = lengths_[i];
    z3::expr want = m.eval(l.exact, true);
    if (lua::same_numeral(m.eval(l.result, true), want)) {
      ++i;
      continue;
    }
    if (bounds) {
      for (const auto& [point, norm] : bound_points(m, l))
        for (const AbstractLength& t : lengths_)
          solver_.add(lua::norm_monotone(t.result, t.components, point, norm));
      ++i;
      continue;
    }
    solver_.add(z3::expr(ctx_, Z3_mk_eq(ctx_, l.result, l.exact)));
    lengths_.erase(lengths_.begin() + static_cast<std::ptrdiff_t>(i));  // exact from now on
  }
}

Answer DataQuery::ask(const std::vector<DataSide>& sides, DataWitness* witness, DataCore* core) {
  z3::expr_vector assumptions(ctx_);
  std::map<unsigned, std::pair<size_t, int>> tracker_of;  // literal id -> (side, line)
  std::vector<std::optional<z3::expr>> predicates;
  for (size_t i = 0; i < sides.size(); ++i) {
    const Encoded& e = encoded(*sides[i].connection);
    assumptions.push_back(e.accepts);
    for (const AcceptTracker& t : e.body.trackers) {
      assumptions.push_back(t.literal);
      tracker_of.emplace(t.literal.id(), std::make_pair(i, t.line));
    }
    predicates.emplace_back();
    if (sides[i].emitted_holds && e.body.emitted) {
      predicates.back() =
          predicate_literal(*sides[i].connection, *sides[i].emitted_holds, sides[i].negate);
      assumptions.push_back(*predicates.back());
    }
  }
  Answer a = check(assumptions);
  if (a == Answer::Unsat) {
    for (const DataSide& side : sides)
      if (!pass_through_.count(side.connection->source) ||
          pass_through_.at(side.connection->source).get() != side.connection)
        if (bounded(*side.connection, side.emitted_holds, side.negate))
          bounded_rules_.insert(side.connection);
  }
  if (a == Answer::Unsat && core) {
    core->accept_lines.assign(sides.size(), {});
    core->predicate_used.assign(sides.size(), false);
    z3::expr_vector uc = solver_.unsat_core();
    for (unsigned k = 0; k < uc.size(); ++k) {
      auto it = tracker_of.find(uc[k].id());
      if (it != tracker_of.end()) core->accept_lines[it->second.first].push_back(it->second.second);
      for (size_t i = 0; i < predicates.size(); ++i)
        if (predicates[i] && z3::eq(uc[k], *predicates[i])) core->predicate_used[i] = true;
    }
    for (auto& lines : core->accept_lines) std::sort(lines.begin(), lines.end());
  }
  if (a == Answer::Sat && witness) fill_witness(sides, assumptions, *witness);
  return a;
}

// The messages (and assumed monitor state) of a satisfiable question, each value as simple as
// the question allows (verify/nice_model.h).
void DataQuery::fill_witness(const std::vector<DataSide>& sides, const z3::expr_vector& assumptions,
                             DataWitness& witness) {
  std::vector<const SymValue*> values;
  for (const DataSide& s : sides) {
    const std::string& src = s.connection->source;
    if (std::find(witness.message_sources.begin(), witness.message_sources.end(), src) !=
        witness.message_sources.end())
      continue;
    witness.message_sources.push_back(src);
    values.push_back(&message(src));
  }
  for (const DataSide& s : sides)
    for (const auto& st : encoded(*s.connection).body.state) values.push_back(&st.second);
  // A simpler model must still be one of the machine: its norms as the monitor computes them.
  // (The simplifier's own constraints are in the solver when settled() repairs a model.)
  z3::model found = repaired_model_ ? *repaired_model_ : solver_.get_model();
  z3::model model = nicer_model(solver_, assumptions, values, found, timeout_,
                                [&](const z3::model& m) { return settled(assumptions, m); });
  for (const std::string& src : witness.message_sources)
    witness.messages.push_back(concrete(model, message(src)));
  for (const DataSide& s : sides) {
    const Encoded& e = encoded(*s.connection);
    witness.emitted.push_back(e.body.emitted ? concrete(model, *e.body.emitted) : Value());
    std::vector<std::string> state;
    for (const auto& st : e.body.state) state.push_back(state_text(model, st));
    witness.assumed_state.push_back(std::move(state));
  }
}

DataQuery::PredicateRange DataQuery::predicate_range(const model::Connection& c,
                                                     const model::BodyExpr& p) {
  PredicateRange range;
  if (!predicate_opaque_reason(c, p).empty()) return range;
  auto known = ranges_.find({&c, &p});
  if (known != ranges_.end()) return known->second;
  auto found = derived_.find(&p);
  if (found == derived_.end()) {
    model::BodyExpr negated;
    negated.op = model::BodyExpr::Op::Not;
    negated.type = p.type;
    negated.args = {p};
    model::BodyExpr total;
    total.op = model::BodyExpr::Op::Binary;
    total.text = "or";
    total.type = p.type;
    total.args = {p, negated};
    found = derived_.emplace(&p, Derived{std::move(negated), std::move(total)}).first;
  }
  // `accept p` passes when p has a value and is true; `accept not p`, a value and false; and
  // `p or not p` fails to pass only when p has no value (Lua evaluates p first either way).
  bool unknown = false;
  auto can = [&](const model::BodyExpr& q, bool negate) {
    Answer a = ask({{&c, &q, negate}}, nullptr, nullptr);
    unknown = unknown || a == Answer::Unknown;
    return a != Answer::Unsat;
  };
  range.can_true = can(p, false);
  range.can_false = can(found->second.negated, false);
  range.can_fail = can(found->second.total, true);
  // Kept only when the solver answered each: an answer the deadline cut short says "can",
  // which a later query (with its own time) may sharpen.
  if (!unknown) ranges_.emplace(std::make_pair(&c, &p), range);
  return range;
}

std::optional<bool> DataQuery::holds(const model::BodyExpr& predicate, const Value& value,
                                     const Type& t) {
  SymValue v = constant_value(ctx_, value, t, list_bound_);
  EncodedBody e = encode_body(ctx_, predicate_body(predicate), v, "holds");
  if (!e.opaque.empty()) return std::nullopt;
  z3::expr all = e.accepts;
  for (const z3::expr& x : e.side) all = all && x;
  for (const AcceptTracker& tr : e.trackers) all = all && tr.literal;
  // A constant predicate on a constant value mostly folds to true or false (IEEE operations on
  // numerals included): no solver, so no deadline can leave a replay undecided.
  z3::expr folded = all.simplify();
  if (folded.is_true()) return true;
  if (folded.is_false()) return false;
  z3::solver s(ctx_);
  s.add(all);
  SolverTimeout timeout(deadline_);  // its own solver, within the run's deadline
  std::string unknown;
  z3::check_result r = verify::check(s, timeout, &unknown);
  if (r == z3::unknown) return std::nullopt;
  return r == z3::sat;
}

std::string spec_value_text(const Value& v, const Type* type) {
  std::string out;
  switch (v.kind()) {
    case Value::Kind::None:
      return "none";
    case Value::Kind::Bool:
      return v.as_bool() ? "true" : "false";
    case Value::Kind::Int:
      if (type && is_uint64(*type)) return std::to_string(static_cast<uint64_t>(v.as_int()));
      return std::to_string(v.as_int());
    case Value::Kind::Float:
      out = float_spec_text(v.as_float());
      if (out.size() > 2 && out.compare(out.size() - 2, 2, ".0") == 0 && out != "-0.0")
        out.resize(out.size() - 2);
      return out;
    case Value::Kind::String:
      append_json_string(out, v.as_string());
      return out;
    case Value::Kind::Vec3: {
      const Eigen::Vector3d& p = v.as_vec3();
      return "vec3(" + spec_value_text(Value(p.x())) + ", " + spec_value_text(Value(p.y())) + ", " +
             spec_value_text(Value(p.z())) + ")";
    }
    case Value::Kind::List: {
      const Type* element = type && type->kind == Type::Kind::List ? type->element.get() : nullptr;
      out = "[";
      for (size_t i = 0; i < v.as_list().size(); ++i)
        out += (i ? ", " : "") + spec_value_text(v.as_list()[i], element);
      return out + "]";
    }
    case Value::Kind::Record: {
      out = "{ ";
      bool first = true;
      for (const auto& [name, f] : v.as_record()) {
        const Field* field = type ? type->field(name) : nullptr;
        out += (first ? "" : ", ") + name + ": " +
               spec_value_text(f, field ? field->type.get() : nullptr);
        first = false;
      }
      return out + " }";
    }
  }
  return out;
}

const Type* port_type_of(const model::App& app, const std::string& qualified) {
  const model::Port* p = app.find_port(qualified);
  return p && p->type ? p->type.get() : nullptr;
}

}  // namespace arbc::verify
