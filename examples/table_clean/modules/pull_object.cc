// PullObject (the paper's Table I): `pull <pos>` takes the rake from its rack, reaches behind
// the object, pulls it into hand reach and returns the rake; `cancel` aborts a run. Redundant
// pulls while raking are ignored, as in the paper. Its status (e_pull_idle) goes out on every
// change and at 10 Hz (examples/table_clean/rake.h).
#include "examples/table_clean/modules/machine_driver.h"
#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class PullObject : public arbc::Module {
 public:
  PullObject() {
    in("cmd", "{verb: string, pos: vec3}");
    out("status", "list<string>");
  }
  void start() override {
    world_ = find_world(*this);
    if (!world_) return;
    Rake& rake = world_->rake();
    driver_.emplace(
        *this, "status",
        TimedMachine{[&rake](double t) { rake.update(t); },
                     [&rake] { return rake.next_deadline(); }, [&rake] { return rake.status(); }});
    driver_->sync();
  }
  double tick_period() const override { return 0.1; }
  void tick() override {
    if (driver_) driver_->heartbeat();
  }
  void on_message(const std::string& port, const arbc::Value& cmd) override {
    if (!driver_) return;
    const std::string& verb = cmd["verb"].as_string();
    world_->advance_to(now());
    if (verb == "pull") {
      world_->rake().pull(cmd["pos"].as_vec3(), now());
    } else if (verb == "cancel") {
      world_->rake().cancel(now());
    } else {
      context().log("PullObject: unknown command '" + verb + "' ignored (known: pull, cancel)");
    }
    driver_->sync();
  }

 private:
  World* world_ = nullptr;
  std::optional<MachineDriver> driver_;
};

ARBC_REGISTER_MODULE(PullObject, "PullObject");

}  // namespace
}  // namespace arbc::table_clean
