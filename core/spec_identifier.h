// Spec names made from other tools' names (`arbc import yarp`, `arbc import twist_mux`): a YARP
// port, a twist_mux input, become module, rule and event names that the front end accepts.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace arbc {

// Every keyword of the spec language, sorted: the grammar's alphabetic literals. Core cannot
// read the grammar, so a front-end test (grammar_info_test.cc) checks that the two agree.
std::span<const std::string_view> spec_keywords();
bool is_spec_keyword(std::string_view word);

// A spec name for any text: letters, digits and '_' (other characters become '_', those at
// either end are dropped), not starting with a digit (`p_` is put before), no keyword (`_` is
// put after).
std::string spec_identifier(std::string_view text);

}  // namespace arbc
