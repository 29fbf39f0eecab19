// The table_clean app's environment: builds the scenario's world, stops the run the instant
// the table is clean, and reports the summary and verdict that `arbc run` prints.
#include "examples/table_clean/modules/world_environment.h"
#include "examples/table_clean/scenario.h"
#include "examples/table_clean/summary.h"

namespace arbc::table_clean {
namespace {

class TableCleanEnvironment : public WorldEnvironment {
 public:
  static constexpr const char* kDefaultScenario = "mixed";

  std::vector<std::string> scenarios() const override { return scenario_names(); }

  void setup(arbc::EnvironmentContext& ctx) override {
    scenario_ = ctx.scenario().empty() ? kDefaultScenario : ctx.scenario();
    seed_ = ctx.seed();
    create_world(ctx);
    error_ = setup_scenario(scenario_, *world_);
    if (!error_.empty()) {
      ctx.log(error_);
      ctx.request_stop(error_);
      return;
    }
    world_->set_on_table_clean([&ctx] { ctx.request_stop("table clean"); });
  }

  void finish() override { end_time_ = ctx_ ? ctx_->now() : 0; }

  std::string summary() const override {
    if (!world_) return "no world was set up\n";
    if (!error_.empty()) return error_ + "\n";
    return summarize(*world_, scenario_, seed_, end_time_);
  }

  bool success() const override { return world_ && error_.empty() && run_succeeded(*world_); }

 private:
  std::string scenario_;
  uint64_t seed_ = 0;
  std::string error_;
};

ARBC_REGISTER_ENVIRONMENT(TableCleanEnvironment, "table_clean");

}  // namespace
}  // namespace arbc::table_clean
