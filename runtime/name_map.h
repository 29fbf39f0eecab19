// Hash maps keyed by names (connections, ports) that the runtime checks look up with a trace
// line's string_views (trace_format.h, TraceLine) on every record: heterogeneous look-up, so no
// std::string is made to find one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "runtime/same_name.h"

namespace arbc {

struct NameHash {
  using is_transparent = void;
  size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
};

template <class V>
using NameMap = std::unordered_map<std::string, V, NameHash, std::equal_to<>>;

// Names (rules, ports) numbered once, at construction, so that each record finds its name's
// number with one search and the checks then index arrays. A table holds few names (an app's
// rules, its arbitrated ports): up to kLinear they are compared in place (same_name.h), which
// costs less than hashing the record's name; past that they are hashed.
class NameIndex {
 public:
  static constexpr size_t npos = SIZE_MAX;
  // The name's number, given the next one if it is new.
  size_t add(std::string_view name) {
    if (size_t i = find(name); i != npos) return i;
    names_.emplace_back(name);
    if (names_.size() > kLinear)
      for (size_t i = hashed_.size(); i < names_.size(); ++i) hashed_.emplace(names_[i], i);
    return names_.size() - 1;
  }
  // npos: not a name of the table. Inlined: called on every record, its call cost as much as
  // its search.
  [[gnu::always_inline]] size_t find(std::string_view name) const {
    if (names_.size() > kLinear) return find_hashed(name);
    for (size_t i = 0; i < names_.size(); ++i)
      if (same_name(names_[i], name)) return i;
    return npos;
  }
  const std::string& name(size_t i) const { return names_[i]; }
  size_t size() const { return names_.size(); }

 private:
  static constexpr size_t kLinear = 8;
  [[gnu::noinline]] size_t find_hashed(std::string_view name) const {
    auto it = hashed_.find(name);
    return it == hashed_.end() ? npos : it->second;
  }
  std::vector<std::string> names_;
  NameMap<size_t> hashed_;
};

}  // namespace arbc
