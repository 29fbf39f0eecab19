// The monitors that run are the ones `arbc build` wrote: app.json records the SHA-256 of each
// monitor file (`monitor_sha256`, docs/app-json.md), and every reader of an app directory that
// trusts the proof (`arbc run DIR`, `arbc verify DIR`, the runtime itself) compares it with the
// bytes on disk. A monitor is changed only by changing the spec and rebuilding.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/app_model.h"

namespace arbc::model {

// Whether `bytes`, read from the monitor file `path` of connection `c`, are what app.json
// records. On a mismatch sets *err (the file, the connection, what to do). A connection whose
// digest is not recorded (a model built in code, not read from app.json) always matches.
bool monitor_matches_digest(const Connection& c, const std::string& path, std::string_view bytes,
                            std::string* err);

// Reads the claims script `app` names (App::claims_script) from the app directory `dir` into
// *text and checks its digest; false (and *err) when it is missing, unreadable or changed. An
// app without one gives an empty *text.
bool read_claims_script(const App& app, const std::string& dir, std::string* text,
                        std::string* err);

// Reads every monitor file `app` names, relative to the app directory `dir`, and checks each
// against its digest. Returns one message per missing, unreadable or changed file.
std::vector<std::string> check_monitor_files(const App& app, const std::string& dir);

}  // namespace arbc::model
