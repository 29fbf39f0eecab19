// `then set e` / `then unset e` on a rule (docs/language.md#events-set-on-delivery): the runtime
// sets the event in the rule's port's container each time the rule delivers, after the
// decision, as it sets a `by priority` rule's hold; `unset` removes what deliveries set. The
// proof models exactly that (verify/temporal/unrolling.cc), which holds only while nothing
// else touches the event: so it must be a plain `event e [lifetime D];` (no feed sets it), no
// monitor body may set or unset it (a second owner the delivery's `unset` cannot remove), and
// only rules of that one port may read it (the other ports' containers never hold it).
#include <functional>
#include <map>
#include <set>

#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

// Where an event is set or unset on delivery: the port, the first rule, the first unset.
struct DeliveryOwner {
  const ArbitrateDecl* port = nullptr;
  const Rule* rule = nullptr;
  bool set_somewhere = false;
  const DeliveryEffect* first_unset = nullptr;
  const Rule* unset_rule = nullptr;
};

namespace {

void each_event_stmt(const Block& block, const std::function<void(const Stmt&)>& fn) {
  for (const auto& s : block) {
    if (s->kind == Stmt::Kind::Set || s->kind == Stmt::Kind::Unset) fn(*s);
    each_event_stmt(s->body, fn);
    each_event_stmt(s->else_body, fn);
  }
}

const char* kind_text(EventSymbol::Kind k) {
  return k == EventSymbol::Kind::Status ? "a status event" : "a derived event";
}

}  // namespace

void Sema::check_delivery_effects() {
  std::map<std::string, DeliveryOwner> owners;
  for (const ArbitrateDecl& a : spec_.arbitrations) {
    for (const Rule& r : a.rules) {
      std::set<std::string> seen;
      for (const DeliveryEffect& x : r.on_delivery) {
        const EventSymbol* e = spec_.find_event(x.event);
        if (!e) {
          unknown_event(x.loc, x.event, true);
          continue;
        }
        if (e->kind != EventSymbol::Kind::Manual) {
          Diagnostic& d = error(x.loc,
                                "'" + x.event + "' is " + kind_text(e->kind) + " fed from " +
                                    e->source + ": its feed sets it, a delivery cannot",
                                diag::OnDelivery);
          add_note(d, "declare an event of its own for the delivery to set: `event " + x.event +
                          "_taken lifetime D;`");
          continue;
        }
        if (!seen.insert(x.event).second) {
          error(x.loc, "rule '" + r.name + "' names '" + x.event + "' twice after `then`: keep one",
                diag::OnDelivery);
          continue;
        }
        DeliveryOwner& o = owners[x.event];
        if (o.port && o.port != &a) {
          Diagnostic& d = error(x.loc,
                                "'" + x.event + "' is set or unset on delivery into " +
                                    o.port->port.qualified() + " (rule '" + o.rule->name +
                                    "'), and here into " + a.port.qualified() +
                                    ": each arbitrated port has its own events",
                                diag::OnDelivery);
          add_note(d, "declare one event per port");
          continue;
        }
        if (!o.port) o = {&a, &r, false, nullptr, nullptr};
        if (x.set) {
          o.set_somewhere = true;
        } else if (!o.first_unset) {
          o.first_unset = &x;
          o.unset_rule = &r;
        }
      }
    }
  }
  check_delivery_owners(owners);
}

// What the effects need of the rest of the spec: a set for every unset, no monitor touching
// the event, no rule of another port reading it.
void Sema::check_delivery_owners(const std::map<std::string, DeliveryOwner>& owners) {
  for (const auto& [event, o] : owners) {
    if (!o.set_somewhere && o.first_unset) {
      Diagnostic& d = error(o.first_unset->loc,
                            "rule '" + o.unset_rule->name + "' unsets '" + event +
                                "' on delivery, but no rule of " + o.port->port.qualified() +
                                " sets it on delivery: `then unset` removes what deliveries set",
                            diag::OnDelivery);
      add_note(d, "add `then set " + event + "` to the rule that takes it");
    }
  }
  auto body_touch = [&](const Block& body, const std::string& who) {
    each_event_stmt(body, [&](const Stmt& s) {
      auto it = owners.find(s.name);
      if (it == owners.end()) return;
      Diagnostic& d = error(s.name_loc,
                            who + (s.kind == Stmt::Kind::Set ? " sets '" : " unsets '") + s.name +
                                "' in its body, which rule '" + it->second.rule->name +
                                "' sets or unsets on delivery: an event is changed one way",
                            diag::OnDelivery);
      add_note(d,
               "a body's `set` and `unset` run when the message is accepted, before the "
               "decision; change the event only with `then set` / `then unset` on the rules");
    });
  };
  for (const ArbitrateDecl& a : spec_.arbitrations) {
    for (const Rule& r : a.rules) {
      body_touch(r.body, "rule '" + r.name + "'");
      if (r.otherwise) continue;
      std::set<std::string> read;
      r.constraint.collect_events(read);
      for (const std::string& e : read) {
        auto it = owners.find(e);
        if (it == owners.end() || it->second.port == &a) continue;
        Diagnostic& d =
            error(r.loc,
                  "rule '" + r.name + "' of " + a.port.qualified() + " reads '" + e +
                      "', which deliveries set only into " + it->second.port->port.qualified() +
                      "'s container: here it would never be present",
                  diag::OnDelivery);
        add_note(d, "to read another port's deliveries, use a delivery event: `event " + e +
                        "_seen = " + it->second.port->port.qualified() + " : true for D;`");
      }
    }
  }
  for (const ConnectDecl& c : spec_.connects)
    body_touch(c.body, "the connect into " + c.destination.qualified());
}

}  // namespace arbc::frontend
