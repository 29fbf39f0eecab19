// The summary `arbc build` prints: where the artifacts went, and every connection, grouped by
// destination port, saying which the user wrote and which the compiler generated.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::cli {

// "1 monitor", "3 monitors".
std::string count_of(size_t n, const std::string& singular, const std::string& plural);

std::string build_summary(const model::App& app, const std::string& spec,
                          const std::string& out_dir, const std::string& verified);

// The same for `--target yarp`: what was written, given the generated files' paths.
std::string yarp_build_summary(const model::App& app, const std::string& spec,
                               const std::string& out_dir, const std::string& verified,
                               const std::vector<std::string>& files);

}  // namespace arbc::cli
