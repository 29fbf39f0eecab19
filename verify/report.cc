#include "verify/report.h"

namespace arbc::verify {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::Proved:
      return "proved";
    case Verdict::Refuted:
      return "refuted";
    case Verdict::Unknown:
      return "unknown";
  }
  return "?";
}

int VerifyReport::count(Severity s) const {
  int n = 0;
  for (const PortResult& p : ports) {
    for (const Finding& f : p.findings) n += f.severity == s;
  }
  for (const Finding& f : app_findings) n += f.severity == s;
  for (const ResourceResult& r : resources)
    for (const Finding& f : r.findings) n += f.severity == s;
  return n;
}

Diagnostic to_diagnostic(const Finding& f) {
  Diagnostic d;
  d.severity = f.severity;
  d.loc = f.loc;
  d.message = f.message;
  d.id = f.check;
  for (const Note& n : f.notes) {
    Diagnostic note;
    note.severity = Severity::Note;
    note.loc = n.loc;
    note.message = n.message;
    d.notes.push_back(std::move(note));
  }
  return d;
}

}  // namespace arbc::verify
