// Every diagnostic id any stage of arbc can report, with the stage and what it means, defined
// once in core/check_ids.def (the model: Clang's DiagnosticKinds.def). Code that reports a
// diagnostic names its id as a typed constant, `diag::UnknownRule`, never as a string: a
// misspelt id does not compile, and `arbc check --list-ids` prints the same table.
#pragma once

#include <span>
#include <string_view>

namespace arbc {

// A diagnostic id: a constant of namespace diag. Built from the table only (no conversion from
// a string), so that every id a diagnostic carries is one of the table's.
class DiagId {
 public:
  constexpr const char* text() const { return text_; }
  constexpr operator std::string_view() const { return text_; }

 private:
  friend struct DiagTable;
  constexpr explicit DiagId(const char* text) : text_(text) {}
  const char* text_;
};

struct DiagTable {
#define ARBC_DIAG(name, id, stage, meaning) static constexpr DiagId name{id};
#include "core/check_ids.def"
#undef ARBC_DIAG
};

// diag::UnknownRule, diag::Exclusive, ...
namespace diag {
#define ARBC_DIAG(name, id, stage, meaning) inline constexpr DiagId name = DiagTable::name;
#include "core/check_ids.def"
#undef ARBC_DIAG
}  // namespace diag

}  // namespace arbc

namespace arbc::frontend {

struct CheckId {
  std::string_view id;
  // "check": the front end, in every command that reads a spec; "verify": `arbc verify` (loading
  // a model, the proof); "yarp": reading a YARP application (`arbc verify APP.xml`, `arbc
  // import yarp`); "import": `arbc import twist_mux`; "internal": a bug in arbc.
  std::string_view stage;
  std::string_view meaning;
};

// All ids, sorted by name.
std::span<const CheckId> all_check_ids();

}  // namespace arbc::frontend
