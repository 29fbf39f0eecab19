// Times on the command line as CLI11 options (core/duration_parse.h is the parser).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "core/duration_parse.h"

namespace arbc::cli {

// For an option stored as a number of seconds (`->transform(seconds_option(false))`): turns
// its text into that number before CLI11 converts it ("2min" -> "120"), or fails with
// parse_duration's reason.
CLI::Validator seconds_option(bool zero_allowed);

}  // namespace arbc::cli
