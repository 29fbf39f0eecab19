// The name a body or a derived event's predicate reads the incoming message by: its source
// port's (docs/language.md#monitor-bodies).
#include "compiler/frontend/sema_context.h"
#include "core/suggest.h"

namespace arbc::frontend {

using namespace ast;

void Sema::bind_message(Scope& scope, const PortRef& source, bool resolved) {
  Binding message;
  message.kind = NameKind::Message;
  message.type = resolved && source.port_decl ? source.port_decl->type.resolved : nullptr;
  scope.define(source.port, message);
  if (resolved || !source.module_decl) return;
  // `from Camera.objcts` was reported at the misspelt port, with "did you mean 'objects'";
  // the body was written against the port meant, so it reads `objects`. Reporting each such
  // read as an unknown name (suggesting 'objcts') would flag the right spelling, so the name
  // suggested is bound too, untyped like the one written: what the body reads of the message
  // is checked once the source is fixed.
  std::vector<std::string> ports;
  for (const PortDecl& p : source.module_decl->ports) ports.push_back(p.name);
  if (auto meant = closest_name(source.port, ports)) scope.define(*meant, message);
}

}  // namespace arbc::frontend
