// PickAndPlace (the paper's Table I): `take <pos>` grasps an object, `put <pos>` releases it
// there; both take time. Its status (e_taken, e_arm_idle) goes out on every change and at
// 10 Hz. Misuse is refused and counted as a conflict by the world (examples/table_clean/arm.h).
#include "examples/table_clean/modules/machine_driver.h"
#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class PickAndPlace : public arbc::Module {
 public:
  PickAndPlace() {
    in("cmd", "{verb: string, pos: vec3}");
    out("status", "list<string>");
  }
  void start() override {
    world_ = find_world(*this);
    if (!world_) return;
    Arm& arm = world_->arm();
    driver_.emplace(
        *this, "status",
        TimedMachine{[&arm](double t) { arm.update(t); }, [&arm] { return arm.next_deadline(); },
                     [&arm] { return arm.status(); }});
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
    if (verb == "take") {
      world_->arm().take(cmd["pos"].as_vec3(), now());
    } else if (verb == "put") {
      world_->arm().put(cmd["pos"].as_vec3(), now());
    } else {
      context().log("PickAndPlace: unknown command '" + verb + "' ignored (known: take, put)");
    }
    driver_->sync();
  }

 private:
  World* world_ = nullptr;
  std::optional<MachineDriver> driver_;
};

ARBC_REGISTER_MODULE(PickAndPlace, "PickAndPlace");

}  // namespace
}  // namespace arbc::table_clean
