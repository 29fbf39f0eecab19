// Puts generated files on disk as one unit: everything is written into a staging directory
// beside the destination first, and only then swapped in, so a failed build never leaves a
// half-written application, and monitors of rules that no longer exist do not linger. Files
// whose bytes did not change since the previous build are hard-linked into the new one.
#pragma once

#include <string>
#include <vector>

#include "compiler/codegen/target.h"

namespace arbc::codegen {

// Writes `files` (paths relative to the app directory) into `out_dir`/`app_name`, replacing an
// earlier build there. Refuses to replace a non-empty directory that has no app.json (it is not
// an arbc build). False (and `err`) when nothing was replaced.
bool write_artifacts(const std::string& out_dir, const std::string& app_name,
                     const std::vector<OutputFile>& files, std::string* err);

}  // namespace arbc::codegen
