// The verifier's MonitorRunner backed by the runtime's Lua monitors (verify/verify.h): every
// message counterexample is replayed through the monitor that `arbc run` would load
// (docs/checks.md#message-data). A built directory's monitors are read from disk (their digests
// were checked); a spec's are generated in memory, only when a replay is needed.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "compiler/lower/lowered_app.h"
#include "core/app_model.h"
#include "verify/verify.h"

namespace arbc::harness {

class LuaMonitorRunner : public verify::MonitorRunner {
 public:
  // `input` is what `arbc verify` was given (a spec, an app.json or a directory); `app` its
  // model, which must outlive the runner.
  LuaMonitorRunner(std::string input, const model::App& app);
  // A spec compiled in memory (the language server's unsaved text): its monitors are generated
  // from it, not from a file.
  explicit LuaMonitorRunner(std::shared_ptr<const lower::LoweredApp> lowered);

  bool run(const model::Connection& c, const Value& message, verify::MonitorRun* out,
           std::string* err) const override;

 private:
  std::optional<std::string> monitor_text(const model::Connection& c, std::string* err) const;

  std::string input_;
  std::shared_ptr<const lower::LoweredApp> lowered_;  // set: generate from it
  const model::App& app_;
  mutable std::optional<std::map<std::string, std::string>> generated_;  // spec: path -> text
};

}  // namespace arbc::harness
