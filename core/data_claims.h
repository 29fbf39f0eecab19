// The proof's claims over delivered values (issue 39), in one order shared by the generated
// claims script (compiler/codegen/claims_writer.h, which writes each predicate as Lua from the
// IR the proof encodes) and the runtime that checks them on each delivery
// (runtime/data_claims.h): the asserts over `emitted` of each arbitrated port, then the
// `when` of each resource that has one.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::model {

struct DataClaim {
  enum class Kind { Assert, Uses };
  Kind kind = Kind::Assert;
  std::string port;                     // Assert: the arbitrated port
  std::string rule;                     // Assert: the rule whose deliveries it is about
  std::string resource;                 // Uses: the resource whose `when` it is
  const BodyExpr* predicate = nullptr;  // over the delivered value (BodyExpr::Op::Message)
  SourceLocation loc;
  // As a violation names it: "assert PickAndPlace.cmd: take -> (over `emitted`, line 79)".
  std::string text;
};

std::vector<DataClaim> data_claims(const App& app);

}  // namespace arbc::model
