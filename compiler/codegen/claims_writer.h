// Writes claims.lua: the predicates of the proof's claims over delivered values (asserts over
// `emitted`, each resource's `when`; core/data_claims.h gives their order), as Lua generated
// from the same IR the proof encodes (lua_expr.h), so the runtime checks on each delivery
// exactly what was proved (runtime/data_claims.h, docs/runtime.md#runtime-checks).
//
// The file defines the global `Claims`, a sequence of functions `function(emitted) ... end`
// returning whether the predicate holds. Builtins come from the prelude (lua_prelude.h): a
// value that does not exist calls PortMonitor.novalue(), which the runtime provides.
#pragma once

#include <optional>
#include <string>

#include "compiler/lower/lowered_app.h"

namespace arbc::codegen {

// The script's name in the app directory.
inline constexpr const char* kClaimsScript = "claims.lua";

// The text of claims.lua; nullopt when the app has no claim over delivered values.
std::optional<std::string> write_claims(const lower::LoweredApp& app);

}  // namespace arbc::codegen
