// The proof's claims over delivered values, evaluated on the runtime's deliveries (issue 39):
// asserts over `emitted` and the `when` of resources (core/data_claims.h gives their order).
// Their predicates are the claims script `arbc build` writes from the IR the proof encodes
// (compiler/codegen/claims_writer.h), run in a sandbox of their own with a monitor's limits, so
// a check never changes what a monitor sees and a stuck predicate is stopped as a monitor is.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/data_claims.h"
#include "core/value.h"
#include "runtime/lua_sandbox.h"

namespace arbc {

class DataClaims {
 public:
  enum class Outcome { Holds, Fails, NoValue, Error };

  // Loads the script `text` (named `file` in errors) for `app`; null and *err when it does not
  // load or defines another number of claims than the app states.
  static std::unique_ptr<DataClaims> load(const model::App& app, const std::string& text,
                                          const std::string& file, std::string* err);

  const std::vector<model::DataClaim>& claims() const { return claims_; }
  // Claim i's predicate on the delivered value; *why says what failed (NoValue, Error).
  Outcome evaluate(size_t i, const Value& emitted, std::string* why);

 private:
  DataClaims() = default;
  std::vector<model::DataClaim> claims_;
  std::unique_ptr<LuaSandbox> sandbox_;
};

}  // namespace arbc
