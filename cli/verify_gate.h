// "Verify first": `arbc build` (and `arbc run SPEC`) run the proof before anything else and
// stop when it does not pass (docs/cli.md#arbc-build).
#pragma once

#include <string>

#include "core/diagnostic.h"
#include "core/app_model.h"

namespace arbc::cli {

struct VerifyGate {
  bool pass = false;
  int exit_code = 0;    // when !pass: kExitRefuted, or kExitBadInput for a malformed model
  std::string summary;  // when pass: one line, e.g. "verified: 4 arbitrated ports proved"
};

// Verifies `app`, printing the findings to stderr (with spec lines quoted from `sources`).
// Warnings alone pass unless `strict`.
VerifyGate verify_before_writing(const model::App& app, const std::string& input,
                                 SourceCache* sources, bool strict);

}  // namespace arbc::cli
