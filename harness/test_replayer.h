// The verifier's TestReplayer backed by the embedded runtime (verify/verify.h): a counterexample
// over time runs as a test, in simulated time, on the monitors `arbc test` would load
// (docs/design.md#properties-over-time). The app is written to a scratch directory the first
// time a replay is needed (a spec is compiled; a built directory is copied, so the test
// harness never lands in the user's build), and removed with the replayer.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compiler/lower/lowered_app.h"
#include "core/app_model.h"
#include "verify/verify.h"

namespace arbc::harness {

class RuntimeTestReplayer : public verify::TestReplayer {
 public:
  // `input` is what `arbc verify` was given: a spec, an app.json or a built directory.
  explicit RuntimeTestReplayer(std::string input);
  // A spec compiled in memory (the language server's unsaved text).
  explicit RuntimeTestReplayer(std::shared_ptr<const lower::LoweredApp> lowered);
  ~RuntimeTestReplayer() override;
  RuntimeTestReplayer(const RuntimeTestReplayer&) = delete;
  RuntimeTestReplayer& operator=(const RuntimeTestReplayer&) = delete;

  std::optional<std::vector<verify::ReplayRecord>> replay(const model::TestCase& test,
                                                          const std::string& port,
                                                          std::string* err) const override;
  std::optional<std::string> judge(const model::TestCase& test, std::string* err) const override;

 private:
  bool prepare(std::string* err) const;  // the scratch app directory, once

  std::string input_;
  std::shared_ptr<const lower::LoweredApp> lowered_;  // set: write the app from it
  mutable std::string scratch_, app_dir_;
  mutable std::optional<model::App> app_;
};

}  // namespace arbc::harness
