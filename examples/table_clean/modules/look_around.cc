// LookAround (the paper's Table I): random 3-D gaze targets in front of the robot, twice a
// second, from the module's own seeded generator.
#include <cmath>

#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class LookAround : public arbc::Module {
 public:
  static constexpr double kPeriod = 0.5;       // seconds between targets
  static constexpr double kMaxAzimuth = 1.05;  // radians either side of straight ahead
  static constexpr double kMinElevation = -0.35;
  static constexpr double kMaxElevation = 0.5;
  static constexpr double kRange = 1.5;  // metres from the head

  LookAround() { out("gaze", "vec3"); }
  void start() override { world_ = find_world(*this); }
  double tick_period() const override { return kPeriod; }
  void tick() override {
    if (!world_) return;
    const double az = uniform(rng(), -kMaxAzimuth, kMaxAzimuth);
    const double el = uniform(rng(), kMinElevation, kMaxElevation);
    const Vec3 target =
        World::head_position() +
        kRange * Vec3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    world_->referee().published(GazeSource::Search, target, now());
    publish("gaze", arbc::Value(target));
  }

 private:
  World* world_ = nullptr;
};

ARBC_REGISTER_MODULE(LookAround, "LookAround");

}  // namespace
}  // namespace arbc::table_clean
