#include "core/data_claims.h"

namespace arbc::model {

std::vector<DataClaim> data_claims(const App& app) {
  std::vector<DataClaim> out;
  for (const ArbitratedPort& p : app.arbitrated_ports)
    for (const Assertion& a : p.asserts) {
      if (!a.emitted) continue;
      DataClaim c;
      c.port = p.port;
      c.rule = a.rule;
      c.predicate = &*a.emitted;
      c.loc = a.loc;
      c.text = assertion_text(p.port, a) + " (line " + std::to_string(a.loc.line) + ")";
      out.push_back(std::move(c));
    }
  for (const Resource& r : app.resources) {
    if (!r.uses) continue;
    DataClaim c;
    c.kind = DataClaim::Kind::Uses;
    c.resource = r.name;
    c.predicate = &*r.uses;
    c.loc = r.loc;
    c.text = "resource " + r.name;
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace arbc::model
