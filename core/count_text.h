// "1 monitor", "3 monitors": a count with its noun, for summaries and reports.
#pragma once

#include <cstddef>
#include <string>

namespace arbc {

std::string count_of(size_t n, const std::string& singular, const std::string& plural);

}  // namespace arbc
