// A tiny plugin for the runtime's end-to-end tests: a ticker, an arm that is busy every
// other second, and an environment that counts commands reaching the arm while it is busy.
// Scenario "stuck": the arm never returns from its first command (plugin code stuck where no
// interrupt reaches it, for tests/interrupt/).
// testdata/pingpong/ is the app that wires them (as `arbc build` would).
#include <chrono>
#include <sstream>
#include <thread>

#include "runtime/module.h"

namespace pingpong {

class World : public arbc::Environment {
 public:
  std::vector<std::string> scenarios() const override { return {"normal", "impossible", "stuck"}; }
  void setup(arbc::EnvironmentContext& ctx) override {
    ctx_ = &ctx;
    wanted_ = ctx.scenario() == "normal" ? 8 : 1000;
    stuck_ = ctx.scenario() == "stuck";
  }
  bool stuck() const { return stuck_; }
  void command(bool busy) {
    ++commands_;
    if (busy) ++conflicts_;
    if (commands_ == wanted_) ctx_->request_stop("enough commands");
  }
  std::string summary() const override {
    std::ostringstream out;
    out << "commands: " << commands_ << " (wanted " << wanted_ << "), conflicts: " << conflicts_;
    return out.str();
  }
  bool success() const override { return commands_ >= wanted_ && conflicts_ == 0; }

 private:
  arbc::EnvironmentContext* ctx_ = nullptr;
  int commands_ = 0, conflicts_ = 0, wanted_ = 0;
  bool stuck_ = false;
};

class Ticker : public arbc::Module {
 public:
  Ticker() { out("count", "int"); }
  double tick_period() const override { return 0.1; }
  void tick() override { publish("count", arbc::Value(++n_)); }

 private:
  int64_t n_ = 0;
};

class Arm : public arbc::Module {
 public:
  Arm() {
    in("cmd", "{verb: string, n: int}");
    out("status", "list<string>");
  }
  void start() override {
    schedule(1.05, [this] { toggle(); });
  }
  double tick_period() const override { return 0.1; }
  void tick() override { report(); }
  void on_message(const std::string& port, const arbc::Value& v) override {
    auto* world = environment<World>();
    while (world && world->stuck()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (world) world->command(busy_);
  }

 private:
  void toggle() {
    busy_ = !busy_;
    report();
    schedule(1.0, [this] { toggle(); });
  }
  void report() { publish("status", arbc::Value::list({busy_ ? "busy" : "idle"})); }
  bool busy_ = false;
};

ARBC_REGISTER_ENVIRONMENT(World, "pingpong");
ARBC_REGISTER_MODULE(Ticker, "Ticker");
ARBC_REGISTER_MODULE(Arm, "Arm");

}  // namespace pingpong
