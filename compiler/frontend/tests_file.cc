#include "compiler/frontend/tests_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <tuple>

#include "compiler/frontend/frontend.h"
#include "compiler/frontend/parse.h"
#include "core/check_ids.h"
#include "core/suggest.h"

namespace arbc::frontend {

namespace {

namespace fs = std::filesystem;

Diagnostic error_at(const ast::Loc& loc, std::string message, DiagId id) {
  Diagnostic d;
  d.loc = loc;
  d.message = std::move(message);
  d.id = id.text();
  return d;
}

// The first declaration of a tests file that is not a test: (its location, what it is).
std::optional<std::pair<ast::Loc, std::string>> first_non_test(const ast::Spec& s) {
  std::vector<std::pair<ast::Loc, std::string>> found;
  if (s.app) found.push_back({s.app->loc, "an app"});
  if (!s.uses.empty()) found.push_back({s.uses[0].loc, "a `use`"});
  if (!s.types.empty()) found.push_back({s.types[0].loc, "a type"});
  if (!s.consts.empty()) found.push_back({s.consts[0].loc, "a constant"});
  if (!s.modules.empty()) found.push_back({s.modules[0].loc, "a module"});
  if (!s.events.empty()) found.push_back({s.events[0].loc, "an event"});
  if (!s.status_events.empty()) found.push_back({s.status_events[0].loc, "status events"});
  if (!s.derived_events.empty()) found.push_back({s.derived_events[0].loc, "an event"});
  if (!s.exclusives.empty()) found.push_back({s.exclusives[0].loc, "an `exclusive`"});
  if (!s.invariants.empty()) found.push_back({s.invariants[0].loc, "an invariant"});
  if (!s.arbitrations.empty()) found.push_back({s.arbitrations[0].loc, "an `arbitrate` block"});
  if (!s.connects.empty()) found.push_back({s.connects[0].loc, "a `connect`"});
  if (!s.asserts.empty()) found.push_back({s.asserts[0].loc, "an assertion"});
  if (!s.temporal.empty()) found.push_back({s.temporal[0].loc, "a property over time"});
  if (!s.assumptions.empty()) found.push_back({s.assumptions[0].loc, "an environment assumption"});
  if (found.empty()) return std::nullopt;
  return *std::min_element(found.begin(), found.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.line, a.first.column) < std::tie(b.first.line, b.first.column);
  });
}

// The name of a .spec file beside `missing` (a path that does not exist) close enough to its
// name to be a typo; nothing when there is none, or the folder cannot be read.
std::optional<std::string> close_spec_file(const fs::path& missing) {
  std::error_code ec;
  fs::path folder = missing.parent_path().empty() ? fs::path(".") : missing.parent_path();
  std::vector<std::string> names;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() == ".spec") names.push_back(it->path().filename().string());
  }
  std::sort(names.begin(), names.end());  // the first of equally close names, whatever the disk
  return closest_name(missing.filename().string(), names);
}

}  // namespace

bool read_spec_file(const std::string& path, std::string* text, Diagnostic* problem) {
  auto fail = [&](std::string message) {
    problem->loc.file = path;
    problem->message = std::move(message);
    problem->id = diag::Io.text();
    return false;
  };
  std::error_code ec;
  fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return fail("no such file: check the path");
  if (fs::is_directory(status))
    return fail("is a directory, not a spec file: name a .spec file inside it");
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(std::string("cannot open the file: ") + std::strerror(errno));
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text->append(buffer, static_cast<size_t>(in.gcount()));
    if (text->size() > kMaxSpecBytes)
      return fail("the file is larger than " + std::to_string(kMaxSpecBytes >> 20) +
                  " MiB; a spec this large is surely not hand-written text");
  }
  if (in.bad()) return fail("error while reading the file");
  return true;
}

std::unique_ptr<ast::Spec> merge_with_app(std::unique_ptr<ast::Spec> tests, const std::string& file,
                                          std::vector<Diagnostic>& out, std::string* app_file,
                                          std::string* app_text) {
  const ast::TestsFor& named = *tests->tests_for;
  if (auto other = first_non_test(*tests)) {
    out.push_back(error_at(other->first,
                           "a tests file holds only `test` declarations, and this is " +
                               other->second + ": declare it in the app's spec, \"" + named.path +
                               "\"",
                           diag::TestsFile));
    return nullptr;
  }
  fs::path app = fs::path(named.path);
  if (app.is_relative()) app = fs::path(file).parent_path() / app;
  *app_file = app.lexically_normal().string();
  Diagnostic problem;
  if (!read_spec_file(*app_file, app_text, &problem)) {
    Diagnostic d = error_at(named.loc,
                            "cannot read the app's spec " + *app_file + ": " + problem.message +
                                " (the path is relative to this file's folder)",
                            diag::TestsFile);
    if (auto meant = close_spec_file(app)) {  // `bse.spec` for `base.spec`
      Diagnostic note;
      note.severity = Severity::Note;
      note.message =
          "did you mean \"" + (fs::path(named.path).parent_path() / *meant).string() + "\"?";
      d.notes.push_back(std::move(note));
    }
    out.push_back(std::move(d));
    return nullptr;
  }
  ParseResult parsed = parse_spec(*app_text, *app_file);
  for (Diagnostic& d : parsed.diagnostics) out.push_back(std::move(d));
  if (!parsed.spec) return nullptr;
  if (parsed.spec->tests_for) {
    out.push_back(error_at(
        named.loc,
        "\"" + named.path + "\" is itself a tests file: name the spec that declares the app",
        diag::TestsFile));
    return nullptr;
  }
  // The app's own tests belong to the app's spec (`arbc test APP.spec` runs them): a tests
  // file runs only its own, so naming both files runs each test once.
  parsed.spec->tests = std::move(tests->tests);
  return std::move(parsed.spec);
}

}  // namespace arbc::frontend
