#include "compiler/frontend/ast.h"

#include <array>
#include <stdexcept>

namespace arbc::ast {

const PortDecl* ModuleDecl::find_port(const std::string& port) const {
  for (const PortDecl& p : ports)
    if (p.name == port) return &p;
  return nullptr;
}

const ModuleDecl* Spec::find_module(const std::string& name) const {
  for (const ModuleDecl& m : modules)
    if (m.name == name) return &m;
  return nullptr;
}

const EventSymbol* Spec::find_event(const std::string& name) const {
  for (const EventSymbol& e : event_symbols)
    if (e.name == name) return &e;
  return nullptr;
}

const ArbitrateDecl* Spec::find_arbitration(const std::string& qualified_port) const {
  for (const ArbitrateDecl& a : arbitrations)
    if (a.port.qualified() == qualified_port) return &a;
  return nullptr;
}

std::string activity_event_name(const std::string& rule) { return "act_" + rule; }

std::string_view operator_spelling(std::string_view written) {
  static constexpr std::array<std::string_view, 14> kOperators = {
      "+", "-", "*", "/", "%", "<", "<=", ">", ">=", "==", "!=", "and", "or", "not"};
  for (std::string_view op : kOperators)
    if (op == written) return op;
  throw std::logic_error("not an operator of the grammar: '" + std::string(written) + "'");
}

}  // namespace arbc::ast
