// Semantic checks of environment rates, `given M.p every D;`
// (docs/language.md#properties-over-time): the port is an `out` port the app reads, the period a
// positive duration, one rate per source.
#include <map>
#include <string>

#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

namespace {

// Whether some rule, stream event or connect reads `port`: a rate of a source nothing reads
// constrains nothing, so it is most likely a misspelt port.
bool read_by_app(const Spec& spec, const std::string& port) {
  for (const ArbitrateDecl& a : spec.arbitrations)
    for (const Rule& r : a.rules)
      if (r.source.qualified() == port) return true;
  for (const DerivedEventDecl& d : spec.derived_events)
    if (d.source.qualified() == port) return true;
  for (const StatusEventDecl& s : spec.status_events)
    if (s.source.qualified() == port) return true;
  for (const ConnectDecl& c : spec.connects)
    if (c.source.qualified() == port) return true;
  return false;
}

}  // namespace

void Sema::check_rates() {
  std::map<std::string, int> seen;  // port -> line of its first rate
  for (RateDecl& r : spec_.rates) {
    check_duration(r.period, "the `every` period");
    if (!resolve_port(r.port, "source", "a rate (`given`)")) continue;
    if (r.port.port_decl->direction != model::Direction::Out) continue;  // reported
    std::string port = r.port.qualified();
    auto [first, inserted] = seen.emplace(port, r.loc.line);
    if (!inserted) {
      error(r.port.loc,
            "a rate for " + port + " is already given at line " + std::to_string(first->second) +
                ": state one period per source",
            diag::Duplicate);
    } else if (!read_by_app(spec_, port)) {
      error(r.port.loc,
            "no rule, stream event or connect reads " + port +
                ", so its rate constrains nothing: name a source the app reads",
            diag::RateSource);
    }
  }
}

}  // namespace arbc::frontend
