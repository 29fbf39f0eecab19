// Every diagnostic id the front end can report, with what it means. Ids are stable: tests,
// editors and CI scripts match on them. tests/check/ has at least one golden case per id, and
// its runner fails when an id here has none (`arbc check --list-ids` prints this table).
#pragma once

#include <span>
#include <string_view>

namespace arbc::frontend {

struct CheckId {
  std::string_view id;
  std::string_view meaning;
};

// All ids, sorted by name.
std::span<const CheckId> all_check_ids();

}  // namespace arbc::frontend
