// The `yarp` target (docs/yarp.md#deploying-a-spec-on-yarp-step-by-step): a yarpmanager
// application for YARP's portmonitor carrier.
//   <app>.xml                       the application: module placeholders, one connection per
//                                   (source, destination) pair with its carrier
//   contexts/<app>/<monitor>.lua    one monitor per connection that needs one, for YARP's Lua API
//   ports.json                      spec port -> YARP port, YARP connections, YARP event names
#pragma once

#include "compiler/codegen/target.h"

namespace arbc::codegen {

class YarpTarget : public Target {
 public:
  std::string_view name() const override { return "yarp"; }
  std::string_view description() const override {
    return "a yarpmanager application and Lua monitors for YARP's portmonitor carrier";
  }
  bool configure(const TargetOptions& options, std::string* err) override;
  CodegenResult generate(const lower::LoweredApp& app) const override;

 private:
  TargetOptions options_;
};

}  // namespace arbc::codegen
