#include "compiler/codegen/yarp_constraint.h"

#include <algorithm>

namespace arbc::codegen {

namespace {

// `c` over YARP names; compound operands of and/or/not are parenthesised.
std::string text(const Constraint& c, const std::string& port, const YarpNames& names) {
  auto operand = [&](const Constraint& a) {
    std::string t = text(a, port, names);
    bool compound = a.op == Constraint::Op::And || a.op == Constraint::Op::Or ||
                    (a.op == Constraint::Op::Event && t.find(" or ") != std::string::npos);
    return compound ? "( " + t + " )" : t;
  };
  switch (c.op) {
    case Constraint::Op::True:
      return "true";
    case Constraint::Op::False:
      return "false";
    case Constraint::Op::Event: {
      std::vector<std::string> owners = names.owners_of(port, c.event);
      if (owners.empty()) return "false";  // nothing sets it into this port: never present
      std::string out;
      for (const std::string& o : owners) out += (out.empty() ? "" : " or ") + o;
      return out;
    }
    case Constraint::Op::Not:
      return "not " + operand(c.args[0]);
    case Constraint::Op::And:
    case Constraint::Op::Or: {
      std::string out, op = c.op == Constraint::Op::And ? " and " : " or ";
      for (const Constraint& a : c.args) out += (out.empty() ? "" : op) + operand(a);
      return out;
    }
  }
  return "false";
}

// Does a connection into `port` other than `c` set `event`?
bool set_by_another(const model::App& app, const model::Connection& c, const std::string& event) {
  for (const model::Connection* o : app.connections_into(c.destination)) {
    if (o != &c && std::find(o->sets.begin(), o->sets.end(), event) != o->sets.end()) return true;
  }
  return false;
}

}  // namespace

std::string yarp_constraint_text(const Constraint& c, const std::string& port,
                                 const YarpNames& names) {
  return text(c, port, names);
}

std::string yarp_constraint(const model::App& app, const model::Connection& c,
                            const YarpNames& names) {
  std::vector<Constraint> terms{c.constraint};
  if (c.kind != model::ConnectionKind::Feed) {
    for (const std::string& e : c.must_set) terms.push_back(Constraint::event_ref(e));
    for (const std::string& e : c.must_unset)
      if (!set_by_another(app, c, e)) terms.push_back(Constraint::negate(Constraint::event_ref(e)));
  }
  return text(Constraint::conjunction(std::move(terms)), c.destination, names);
}

}  // namespace arbc::codegen
