// The name a body or a derived event's predicate reads the incoming message by: its source
// port's (docs/language.md#monitor-bodies).
#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

void Sema::bind_message(Scope& scope, const PortRef& source, bool resolved) {
  Binding message;
  message.kind = NameKind::Message;
  message.type = resolved && source.port_decl ? source.port_decl->type.resolved : nullptr;
  scope.define(source.port, message);
  if (resolved || !source.module_decl) return;
  // `from Camera.objcts` was reported at the misspelt port (with "did you mean 'objects'"
  // when a port is close); the body was written against the port meant, so it reads
  // `objects`. Reporting each such read as an unknown name would flag the right spelling
  // rather than the wrong one, so the module's ports are bound too, untyped like the name
  // written: what the body reads of the message is checked once the source is fixed.
  Binding other = message;
  other.other_port = true;
  for (const PortDecl& p : source.module_decl->ports)
    if (p.name != source.port) scope.define(p.name, other);
}

}  // namespace arbc::frontend
