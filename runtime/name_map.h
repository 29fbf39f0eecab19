// Hash maps keyed by names (connections, ports) that the runtime checks look up with a trace
// line's string_views (trace_format.h, TraceLine) on every record: heterogeneous look-up, so no
// std::string is made to find one.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>

namespace arbc {

struct NameHash {
  using is_transparent = void;
  size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
};

template <class V>
using NameMap = std::unordered_map<std::string, V, NameHash, std::equal_to<>>;

}  // namespace arbc
