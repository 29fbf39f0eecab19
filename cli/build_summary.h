// The summary `arbc build` prints: where the artifacts went, and every connection, grouped by
// destination port, saying which the user wrote and which the compiler generated.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/count_text.h"

namespace arbc::cli {

std::string build_summary(const model::App& app, const std::string& spec,
                          const std::string& out_dir, const std::string& verified);

// The same for `--target yarp`: what was written, given the generated files' paths.
std::string yarp_build_summary(const model::App& app, const std::string& spec,
                               const std::string& out_dir, const std::string& verified,
                               const std::vector<std::string>& files);

}  // namespace arbc::cli
