// Words a newcomer brings from the paper's Lua monitors, from YARP and ROS, or from other
// languages, where the spec language has a construct of its own. No keyword is near them in
// spelling, so "did you mean" cannot help; the error names the construct instead.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace arbc::frontend {

// How to write what `word` means where a declaration was expected ("feed" -> the derived event
// declaration), else nothing.
std::optional<std::string> declaration_for_word(std::string_view word);

// How to write what `word` means where a monitor statement was expected ("setEvent" -> `set`),
// else nothing.
std::optional<std::string> statement_for_word(std::string_view word);

}  // namespace arbc::frontend
