// "Verify first": `arbc build` and `arbc run` run the proof before anything else and stop when
// it does not pass (docs/cli.md).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/app_model.h"
#include "core/diagnostic.h"

namespace arbc::cli {

struct VerifyGate {
  bool pass = false;
  int exit_code = 0;    // when !pass: kExitRefuted, or kExitBadInput for a malformed model
  std::string summary;  // when pass: one line, e.g. "verified: 4 arbitrated ports proved"
  // Rules (destination, name) proved only for lists of at most list_bound elements
  // (verify::VerifyReport::bounded_rules): apply_list_bounds writes them into the model.
  std::vector<std::pair<std::string, std::string>> bounded_rules;
  int list_bound = 0;
};

// Sets Connection::list_bound on the rules the gate's proof holds for only up to the list
// bound, so that app.json carries it and the runtime drops longer lists (bad-value).
void apply_list_bounds(const VerifyGate& gate, model::App& app);

// Verifies `app`, printing the findings to stderr (with spec lines quoted from `sources`).
// Warnings alone pass unless `strict`. When it does not pass, `refusal` follows the verdict on
// stderr: "arbc build: verification refuted; " + refusal.
VerifyGate verify_before_writing(
    const model::App& app, const std::string& input, SourceCache* sources, bool strict,
    const std::string& refusal =
        "nothing was written (fix the spec, or build anyway with --no-verify)",
    const char* command = "arbc build");

// "verified: 3 arbitrated ports proved exclusive; 1 by priority: ...": the summary of a passed
// gate. A `by priority` port is counted apart because exclusivity is not what holds there: two
// messages at one instant can both be delivered from one event state (the higher rule has not
// delivered yet), so its line states the property proved for it
// (docs/design.md#priorities-and-holds).
std::string verified_summary(size_t exclusive, size_t by_priority);
std::string verified_summary(const std::vector<model::ArbitratedPort>& ports);

}  // namespace arbc::cli
