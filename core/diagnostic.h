// Diagnostics as values (docs/design.md#reporting-errors): severity, location, message, check id,
// notes. Rendered like a compiler's:
//   specs/x.spec:12:3: error: unknown event 'e_tken' [unknown-name]
//     take: from ObjectDetector.objects when not e_tken
//                                                ^~~~~~
//   note: did you mean 'e_taken'?
// Used by the front end (`arbc check`) and by `arbc verify`.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/app_model.h"

namespace arbc {

enum class Severity { Error, Warning, Note };

const char* severity_name(Severity s);

struct Diagnostic {
  Severity severity = Severity::Error;
  model::SourceLocation loc;
  std::string message;
  std::string id;                 // stable check id, e.g. "unknown-name", "exclusive"
  std::vector<Diagnostic> notes;  // extra lines: "did you mean", "why each side holds"
};

// A diagnostic in one expression, without notes.
inline Diagnostic make_diagnostic(Severity s, model::SourceLocation loc, std::string message,
                                  std::string id) {
  return {s, std::move(loc), std::move(message), std::move(id), {}};
}
// Adds a note line under `d` (quoting `loc`'s line when it has one).
inline void add_note(Diagnostic& d, std::string message, model::SourceLocation loc = {}) {
  d.notes.push_back({Severity::Note, std::move(loc), std::move(message), "", {}});
}

// Source text by file name, to quote lines under diagnostics. Files are read on demand;
// a file that cannot be read is quoted as nothing.
class SourceCache {
 public:
  void add(std::string file, std::string text);  // text already in memory (e.g. the spec)
  // The 1-based line, without its newline; empty when unknown.
  std::string_view line(const std::string& file, int line);

 private:
  struct Text {
    std::string content;
    std::vector<size_t> line_starts;
  };
  Text& load(const std::string& file);
  std::map<std::string, Text> texts_;
};

// Renders one diagnostic (and its notes) as text ending in a newline. `sources` may be null:
// then no source line is quoted.
std::string render(const Diagnostic& d, SourceCache* sources);

}  // namespace arbc
