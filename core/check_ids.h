// Every diagnostic id any stage of arbc can report, with the stage and what it means. Ids are
// stable: tests, editors and CI scripts match on them (`arbc check --list-ids` prints this
// table). Each id of stage "check" has a golden case in tests/check/, each of stage "verify"
// one in tests/verify/golden/, each of stage "yarp" one in tests/yarp_verify/
// (tests/check/check_ids_covered.py fails otherwise); ids of stage "internal" report a bug in
// arbc, which no input should reach.
#pragma once

#include <span>
#include <string_view>

namespace arbc::frontend {

struct CheckId {
  std::string_view id;
  // "check": the front end, in every command that reads a spec; "verify": `arbc verify` (loading
  // a model, the proof); "yarp": reading a YARP application (`arbc verify APP.xml`, `arbc
  // import yarp`); "internal": a bug in arbc.
  std::string_view stage;
  std::string_view meaning;
};

// All ids, sorted by name.
std::span<const CheckId> all_check_ids();

}  // namespace arbc::frontend
