#include "harness/model_loader.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/lower/compile_spec.h"
#include "core/app_json.h"

namespace arbc::harness {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

bool is_spec_path(const std::string& path) { return ends_with(path, ".spec"); }

Diagnostic file_error(const std::string& file, std::string message, DiagId id) {
  Diagnostic d;
  d.loc.file = file;
  d.message = std::move(message);
  d.id = id.text();
  return d;
}

std::optional<model::App> load_spec_model(const std::string& path, LoadNotes* notes,
                                          std::string* err) {
  lower::CompiledSpec compiled = lower::compile_spec(path);
  for (const Diagnostic& d : compiled.diagnostics) notes->rendered += render(d, &compiled.sources);
  if (!compiled.ok || !compiled.lowered) {
    *err = path + ": not verified: the spec has errors (fix them; `arbc check` lists them)";
    notes->errors = compiled.diagnostics;
    return std::nullopt;
  }
  for (const Diagnostic& d : compiled.diagnostics)
    if (d.severity == Severity::Warning) notes->warnings.push_back(d);
  return compiled.lowered->app;
}

std::optional<model::App> load_model(const std::string& path, LoadNotes* notes, std::string* err) {
  std::error_code ec;
  if (is_spec_path(path)) return load_spec_model(path, notes, err);
  std::string file = path;
  if (std::filesystem::is_directory(path, ec))
    file = (std::filesystem::path(path) / "app.json").string();
  std::ifstream in(file, std::ios::binary);
  if (!in && std::filesystem::exists(std::filesystem::path(path) / "ports.json", ec)) {
    // A build for YARP has no app.json: it runs on YARP, and `arbc verify` takes it.
    *err = path +
           ": a build for YARP (arbc build --target yarp), which runs on YARP "
           "(docs/yarp.md#deploying-a-spec-on-yarp-step-by-step) and has no app.json; for "
           "arbc's runtime, build the spec without --target yarp";
    notes->errors.push_back(file_error(path, err->substr(path.size() + 2), diag::Io));
    return std::nullopt;
  }
  if (!in) {
    *err = file +
           ": cannot read the file; give a spec (*.spec), an app.json, or a directory "
           "written by `arbc build`";
    notes->errors.push_back(file_error(file, err->substr(file.size() + 2), diag::Io));
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  Diagnostic error;
  std::optional<model::App> app = model::from_app_json(text.str(), file, &error);
  if (!app) {
    // As a spec's errors: at the place in the file, the line quoted, then one line that says
    // the input was not taken.
    SourceCache sources;
    sources.add(file, text.str());
    notes->rendered += render(error, &sources);
    *err = file + ": not a valid app.json (the error above)";
    notes->errors.push_back(std::move(error));
  }
  return app;
}

}  // namespace arbc::harness
