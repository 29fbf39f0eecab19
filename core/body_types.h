// The static types of a body's nodes (BodyExpr::type): the one typing function over the IR.
// Lowering calls it on the bodies it writes and the app.json reader on the bodies it reads, so a
// body has the same types whichever way it was made (docs/app-json.md#bodies), and app.json
// needs no type annotations. The rules are the checker's (compiler/frontend/sema_expr.cc), over
// a tree whose int-to-float promotions are already explicit (`ToFloat`), so each node's type
// follows from its operands alone; lower_test checks that they agree with sema's on every node
// of every spec in the repository.
#pragma once

#include "core/app_model.h"
#include "core/body.h"

namespace arbc::model {

// Types every expression of `body` for a message of type `message`. False when a node cannot be
// typed (a name not defined, a field the record lacks: an app.json edited by hand); that node
// keeps a null type and the rest is still typed.
bool type_body(Body& body, const TypePtr& message);

// One expression over the message `message`: a derived event's predicate over its source, an
// assert's property over the delivered value, a resource's `when`.
bool type_expr(BodyExpr& e, const TypePtr& message);

// Every body of `app`: a connection's over its source port's type, an assert's and a resource's
// over the delivered value (the port's type).
void type_bodies(App& app);

}  // namespace arbc::model
