// HeadControl (the paper's Table I): turns the head towards each 3-D point it receives.
#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class HeadControl : public arbc::Module {
 public:
  HeadControl() { in("gaze", "vec3"); }
  void start() override { world_ = find_world(*this); }
  void on_message(const std::string& port, const arbc::Value& gaze) override {
    if (!world_ || !gaze.is_vec3()) return;
    world_->advance_to(now());
    world_->head().look_at(gaze.as_vec3(), now());
    world_->referee().delivered(gaze.as_vec3(), now());
  }

 private:
  World* world_ = nullptr;
};

ARBC_REGISTER_MODULE(HeadControl, "HeadControl");

}  // namespace
}  // namespace arbc::table_clean
