#include "harness/test_replayer.h"

#include <stdlib.h>

#include <filesystem>
#include <set>

#include "compiler/codegen/target.h"
#include "compiler/codegen/write_artifacts.h"
#include "compiler/lower/compile_spec.h"
#include "harness/model_loader.h"
#include "harness/test_expect.h"
#include "harness/test_runner.h"
#include "runtime/app_loader.h"

namespace arbc::harness {

namespace fs = std::filesystem;

RuntimeTestReplayer::RuntimeTestReplayer(std::string input) : input_(std::move(input)) {}

RuntimeTestReplayer::RuntimeTestReplayer(std::shared_ptr<const lower::LoweredApp> lowered)
    : lowered_(std::move(lowered)) {}

RuntimeTestReplayer::~RuntimeTestReplayer() {
  std::error_code ignored;
  if (!scratch_.empty()) fs::remove_all(scratch_, ignored);
}

bool RuntimeTestReplayer::prepare(std::string* err) const {
  if (app_) return true;
  std::string pattern = (fs::temp_directory_path() / "arbc-replay-XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    *err = "cannot make a scratch directory";
    return false;
  }
  scratch_ = pattern;
  if (lowered_ || is_spec_path(input_)) {
    std::shared_ptr<const lower::LoweredApp> lowered = lowered_;
    if (!lowered) {
      lower::CompiledSpec compiled = lower::compile_spec(input_);
      if (!compiled.ok || !compiled.lowered) {
        *err = "the spec no longer compiles";
        return false;
      }
      lowered = compiled.lowered;
    }
    std::unique_ptr<codegen::Target> target = codegen::make_target(codegen::kDefaultTarget);
    codegen::CodegenResult generated = target->generate(*lowered);
    const std::string& name = lowered->app.name;
    if (!generated.ok || !codegen::write_artifacts(scratch_, name, generated.files, err)) {
      if (err->empty()) *err = "cannot generate the monitors";
      return false;
    }
    app_dir_ = (fs::path(scratch_) / name).string();
  } else {
    std::error_code ec;
    fs::path dir = fs::is_directory(input_, ec) ? fs::path(input_) : fs::path(input_).parent_path();
    app_dir_ = (fs::path(scratch_) / "app").string();
    fs::copy(dir.empty() ? fs::path(".") : dir, app_dir_, fs::copy_options::recursive, ec);
    if (ec) {
      *err = "cannot copy " + dir.string() + ": " + ec.message();
      return false;
    }
  }
  std::optional<model::App> app = load_app_dir(app_dir_, err);
  if (!app || !write_test_harness(app_dir_, err)) return false;
  app_ = std::move(*app);
  return true;
}

std::optional<std::vector<verify::ReplayRecord>> RuntimeTestReplayer::replay(
    const model::TestCase& test, const std::string& port, std::string* err) const {
  if (!prepare(err)) return std::nullopt;
  TestTrace trace;
  if (!run_test_trace(*app_, app_dir_, test, &trace, err)) return std::nullopt;
  std::vector<verify::ReplayRecord> out;
  using K = verify::ReplayRecord::Kind;
  // A drop's record names its connection only: the port's rules are these.
  std::set<std::string> rules;
  for (const model::Connection* c : app_->connections_into(port))
    if (c->kind == model::ConnectionKind::Rule) rules.insert(c->name);
  for (const TraceRecord& r : trace.records) {
    if (r.kind == TraceKind::Drop && rules.count(r.connection)) {
      out.push_back({K::Drop, r.t, r.connection, "", kNever});
      continue;
    }
    if (r.port != port) continue;
    if (r.kind == TraceKind::Deliver) {
      out.push_back({K::Deliver, r.t, r.connection, "", kNever});
    } else if (r.kind == TraceKind::Event) {
      // "set", "unset" or "expire" (the entry lapsed at r.t, its expiry)
      out.push_back({r.op == "set" ? K::Set : K::Remove, r.t, r.owner, r.event, r.expiry});
    }
  }
  return out;
}

std::optional<std::string> RuntimeTestReplayer::judge(const model::TestCase& test,
                                                      std::string* err) const {
  if (!prepare(err)) return std::nullopt;
  TestTrace trace;
  if (!run_test_trace(*app_, app_dir_, test, &trace, err, false)) return std::nullopt;
  TestRun run{trace.received, trace.records, trace.end, &*app_};
  for (const model::Expectation& e : test.expectations) {
    std::string why = check_expectation(e, run);
    if (!why.empty()) return "expected " + e.text + " " + why;
  }
  return "";
}

}  // namespace arbc::harness
