#include "cli/counterexample_files.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "verify/claim_test.h"
#include "verify/temporal/counterexample.h"

namespace arbc::cli {

namespace fs = std::filesystem;

namespace {

// Writes `text` to `path`; false (after saying why on stderr) when it cannot.
bool write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) std::fprintf(stderr, "arbc verify: cannot write %s\n", path.string().c_str());
  return static_cast<bool>(out);
}

// "M.p" as a file name part: "M_p".
std::string file_part(std::string name) {
  for (char& c : name) c = c == '.' ? '_' : c;
  return name;
}

std::string unique(const std::string& stem, std::set<std::string>& used) {
  std::string name = stem;
  for (int n = 2; !used.insert(name).second; ++n) name = stem + std::to_string(n);
  return name;
}

// The spec as the test's `tests for` names it: relative to the folder the test is written to.
std::string spec_from(const model::SourceLocation& loc, const fs::path& dir) {
  std::error_code ec;
  return fs::proximate(fs::absolute(loc.file.str()), fs::absolute(dir), ec).generic_string();
}

bool write_temporal(const verify::InputReport& r, const fs::path& dir,
                    std::set<std::string>& used) {
  for (const verify::TemporalResult& t : r.report.temporal) {
    if (!t.replayed) continue;
    std::string text = verify::temporal::test_file_text(*t.replay_test, t.property,
                                                        spec_from(t.property.loc, dir));
    if (!write_file(dir / (temporal_stem(r.report.app, t.property, used) + ".test.spec"), text))
      return false;
  }
  return true;
}

// A finding that cannot be replayed as a test is written as a .txt file that says why and what
// the counterexample is, so that nothing is left out silently.
bool write_finding(const verify::InputReport& r, const verify::Finding& f, const std::string& where,
                   const fs::path& dir, std::set<std::string>& used) {
  if (!f.replay_test && f.not_replayable.empty()) return true;
  std::string stem = finding_stem(r.report.app, where, f, used);
  if (!f.replay_test) {
    std::string text = "Not written as a test: " + f.not_replayable + ".\n\n" + f.message + "\n";
    for (const verify::Note& n : f.notes) text += "note: " + n.message + "\n";
    return write_file(dir / (stem + ".txt"), text);
  }
  return write_file(
      dir / (stem + ".test.spec"),
      verify::counterexample_file_text(*f.replay_test, f.replay_test->expectations.at(0).text,
                                       spec_from(f.loc, dir), verify::kDecisionTestHeader));
}

}  // namespace

std::string temporal_stem(const std::string& app, const model::TemporalProperty& p,
                          std::set<std::string>& used) {
  std::string kind = std::string(".") + model::temporal_kind_name(p.kind);
  if (p.kind == model::TemporalProperty::Kind::Spacing)
    kind = p.other.empty() ? "" : ".after_" + p.other;
  std::string who = p.rule.empty() ? file_part(p.port) : p.rule;
  return unique(app + "." + who + kind, used);
}

std::string finding_stem(const std::string& app, const std::string& where, const verify::Finding& f,
                         std::set<std::string>& used) {
  std::string stem = app + "." + file_part(where);
  for (const std::string& rule : f.rules) stem += "." + rule;
  return unique(stem + "." + f.check, used);
}

bool write_counterexamples(const std::vector<verify::InputReport>& reports,
                           const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  std::set<std::string> used;  // stems written, so that none is overwritten
  for (const verify::InputReport& r : reports) {
    if (!write_temporal(r, dir, used)) return false;
    for (const verify::PortResult& p : r.report.ports)
      for (const verify::Finding& f : p.findings)
        if (!write_finding(r, f, p.port, dir, used)) return false;
    for (const verify::ResourceResult& res : r.report.resources)
      for (const verify::Finding& f : res.findings)
        if (!write_finding(r, f, res.name, dir, used)) return false;
  }
  return true;
}

}  // namespace arbc::cli
