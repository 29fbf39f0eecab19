// The proof `arbc build` made, recorded beside app.json (proof.json) and trusted by `arbc run`
// of that directory when it is about exactly the app.json that runs, proved by this very binary.
//
// Why: `arbc run DIR` proves the app before it runs it, so that what runs is what was proved.
// For the paper's app that proof (about 0.1 s, most of it creating Z3 solvers) took ten times
// as long as the simulated run itself, and it repeated the build's proof of the same bytes. The
// record names the app.json it is about by its SHA-256 (app.json in turn pins every monitor by
// its digest, which the runtime checks before it runs) and the arbc that proved it by its
// build id (verify/executable_id.h). Anything else, and run proves again.
#pragma once

#include <optional>
#include <string>

namespace arbc::verify {

inline constexpr const char* kProofRecordFile = "proof.json";

// proof.json's text for a proof of `app_json` (its bytes) that passed with `summary`; empty
// when this binary has no build id (then nothing can check the record later).
std::string proof_record(const std::string& app_json, const std::string& summary);

// The summary recorded in DIR/proof.json when the record is about exactly `app_json` and was
// written by this binary; nullopt otherwise (no record, another app.json, another arbc, a file
// that is not a record).
std::optional<std::string> recorded_proof(const std::string& dir, const std::string& app_json);

}  // namespace arbc::verify
