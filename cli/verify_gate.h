// "Verify first": `arbc build` and `arbc run` run the proof before anything else and stop when
// it does not pass (docs/cli.md).
#pragma once

#include <string>

#include "core/app_model.h"
#include "core/diagnostic.h"

namespace arbc::cli {

struct VerifyGate {
  bool pass = false;
  int exit_code = 0;    // when !pass: kExitRefuted, or kExitBadInput for a malformed model
  std::string summary;  // when pass: one line, e.g. "verified: 4 arbitrated ports proved"
};

// Verifies `app`, printing the findings to stderr (with spec lines quoted from `sources`).
// Warnings alone pass unless `strict`. When it does not pass, `refusal` follows the verdict on
// stderr: "arbc build: verification refuted; " + refusal.
VerifyGate verify_before_writing(
    const model::App& app, const std::string& input, SourceCache* sources, bool strict,
    const std::string& refusal =
        "nothing was written (fix the spec, or build anyway with --no-verify)",
    const char* command = "arbc build");

// "verified: 4 arbitrated ports proved exclusive": the summary of a passed gate for an app with
// `ports` arbitrated ports.
std::string verified_summary(size_t ports);

}  // namespace arbc::cli
