#include "harness/monitor_runner.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/codegen/embedded_target.h"
#include "compiler/lower/compile_spec.h"
#include "harness/model_loader.h"
#include "runtime/lua_monitor.h"

namespace arbc::harness {

namespace {

// A monitor alone: no container (events are the effective guard's business), clock at 0.
class ReplayHost : public MonitorHost {
 public:
  explicit ReplayHost(std::string constraint) : constraint_(std::move(constraint)) {}
  Nanos now() override { return Nanos(0); }
  void set_event(std::string_view, std::optional<Nanos>) override {}
  void unset_event(std::string_view) override {}
  bool has_event(std::string_view) override { return false; }
  bool set_constraint(std::string_view, std::string*) override { return true; }
  std::string get_constraint() override { return constraint_; }
  void set_trig_interval(Nanos) override {}
  void print(const std::string&) override {}

 private:
  std::string constraint_;
};

}  // namespace

LuaMonitorRunner::LuaMonitorRunner(std::string input, const model::App& app)
    : input_(std::move(input)), app_(app) {}

LuaMonitorRunner::LuaMonitorRunner(std::shared_ptr<const lower::LoweredApp> lowered)
    : lowered_(std::move(lowered)), app_(lowered_->app) {}

std::optional<std::string> LuaMonitorRunner::monitor_text(const model::Connection& c,
                                                          std::string* err) const {
  if (lowered_ || is_spec_path(input_)) {
    if (!generated_) {
      std::shared_ptr<const lower::LoweredApp> lowered = lowered_;
      if (!lowered) {
        lower::CompiledSpec compiled = lower::compile_spec(input_);
        if (!compiled.ok || !compiled.lowered) {
          *err = "the spec no longer compiles";
          return std::nullopt;
        }
        lowered = compiled.lowered;
      }
      codegen::CodegenResult r = codegen::EmbeddedTarget().generate(*lowered);
      generated_.emplace();
      for (const codegen::OutputFile& f : r.files) (*generated_)[f.path] = f.content;
    }
    auto it = generated_->find(c.monitor);
    if (it == generated_->end()) {
      *err = "no monitor " + c.monitor + " was generated";
      return std::nullopt;
    }
    return it->second;
  }
  std::error_code ec;
  std::filesystem::path dir = std::filesystem::is_directory(input_, ec)
                                  ? std::filesystem::path(input_)
                                  : std::filesystem::path(input_).parent_path();
  std::ifstream in(dir / c.monitor, std::ios::binary);
  if (!in) {
    *err = "cannot read " + (dir / c.monitor).string();
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool LuaMonitorRunner::run(const model::Connection& c, const Value& message,
                           verify::MonitorRun* out, std::string* err) const {
  std::optional<std::string> text = monitor_text(c, err);
  if (!text) return false;
  const model::Port* dest = app_.find_port(c.destination);
  if (!dest || !dest->type) {
    *err = "the destination port " + c.destination + " has no type";
    return false;
  }
  ReplayHost host(c.constraint.to_string());
  std::unique_ptr<LuaMonitor> m = LuaMonitor::load(*text, c.monitor, SandboxLimits{}, &host, err);
  if (!m) return false;
  bool created = false;
  LuaCall call = m->create({c.source, c.destination, c.name}, &created);
  if (!call.ok() || !created) {
    *err = "create failed: " + call.error;
    return false;
  }
  call = m->accept(message, &out->accepted, &out->reason);
  if (call.status == LuaCall::Status::NoValue) {
    out->accepted = false;
    out->reason = "no-value";
    return true;
  }
  if (!call.ok()) {
    out->accepted = false;
    out->reason = "monitor-error: " + call.error;
    return true;
  }
  if (!out->accepted) return true;
  call = m->update(*dest->type, &out->delivered);
  if (call.status == LuaCall::Status::NoValue) {
    out->accepted = false;
    out->reason = "no-value";
  } else if (!call.ok()) {
    out->accepted = false;
    out->reason = "monitor-error: " + call.error;
  }
  return true;
}

}  // namespace arbc::harness
