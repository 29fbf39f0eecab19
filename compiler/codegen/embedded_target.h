// The `embedded` target: the bundled runtime's artifact directory
// (docs/design.md#code-generation-targets):
//   app.json                      the core model, with each monitor's source map
//   monitors/<port>__<rule>.lua   one monitor per connection, generated feeds included
#pragma once

#include "compiler/codegen/target.h"

namespace arbc::codegen {

class EmbeddedTarget : public Target {
 public:
  std::string_view name() const override { return "embedded"; }
  std::string_view description() const override {
    return "app.json and Lua monitors for the bundled embedded runtime";
  }
  CodegenResult generate(const lower::LoweredApp& app) const override;
};

}  // namespace arbc::codegen
