#include "compiler/frontend/frontend.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "compiler/frontend/parse.h"
#include "compiler/frontend/sema.h"

namespace arbc::frontend {

bool CheckResult::ok() const {
  return std::none_of(diagnostics.begin(), diagnostics.end(),
                      [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

namespace {

Diagnostic io_error(const std::string& path, std::string message) {
  Diagnostic d;
  d.loc.file = path;
  d.message = std::move(message);
  d.id = "io";
  return d;
}

void sort_by_position(std::vector<Diagnostic>& diagnostics) {
  std::stable_sort(diagnostics.begin(), diagnostics.end(),
                   [](const Diagnostic& a, const Diagnostic& b) {
                     return std::tie(a.loc.line, a.loc.column) < std::tie(b.loc.line, b.loc.column);
                   });
}

// Editors on Windows may start a UTF-8 file with a byte-order mark: it is not part of the text
// (and, kept, would be an invisible "unexpected character" at 1:1).
std::string_view without_bom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.substr(0, kBom.size()) == kBom) text.remove_prefix(kBom.size());
  return text;
}

}  // namespace

CheckResult check_text(std::string_view text, const std::string& file,
                       const std::string& script_dir) {
  text = without_bom(text);
  CheckResult result;
  result.source = std::string(text);
  ParseResult parsed = parse_spec(text, file);
  result.diagnostics = std::move(parsed.diagnostics);
  if (parsed.spec) {
    check_spec(*parsed.spec, result.diagnostics, script_dir);
    result.spec = std::move(parsed.spec);
  }
  sort_by_position(result.diagnostics);
  return result;
}

CheckResult check_file(const std::string& path) {
  namespace fs = std::filesystem;
  CheckResult result;
  std::error_code ec;
  fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    result.diagnostics.push_back(io_error(path, "no such file: check the path"));
    return result;
  }
  if (fs::is_directory(status)) {
    result.diagnostics.push_back(
        io_error(path, "is a directory, not a spec file: name a .spec file inside it"));
    return result;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    result.diagnostics.push_back(
        io_error(path, std::string("cannot open the file: ") + std::strerror(errno)));
    return result;
  }
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxSpecBytes) {
      result.diagnostics.push_back(
          io_error(path, "the file is larger than " + std::to_string(kMaxSpecBytes >> 20) +
                             " MiB; a spec this large is surely not hand-written text"));
      return result;
    }
  }
  if (in.bad()) {
    result.diagnostics.push_back(io_error(path, "error while reading the file"));
    return result;
  }
  return check_text(text, path);
}

std::string render_diagnostics(const std::vector<Diagnostic>& diagnostics, SourceCache* sources,
                               size_t cap) {
  std::string out;
  size_t errors = 0, hidden = 0;
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Error && ++errors > cap) {
      ++hidden;
      continue;
    }
    out += render(d, sources);
  }
  if (hidden > 0)
    out += "... and " + std::to_string(hidden) + " more error" + (hidden == 1 ? "" : "s") +
           " (only the first " + std::to_string(cap) + " are shown)\n";
  return out;
}

}  // namespace arbc::frontend
