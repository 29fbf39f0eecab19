// ObjectDetector (the paper's Table I): the graspable objects on the table, with position and
// distance from the robot, at 10 Hz. It sees the whole table wherever the head looks; held
// objects and objects in the bucket are not listed.
#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class ObjectDetector : public arbc::Module {
 public:
  ObjectDetector() { out("objects", "list<{pos: vec3, dist: float}>"); }
  void start() override { world_ = find_world(*this); }
  double tick_period() const override { return 0.1; }
  void tick() override {
    if (!world_) return;
    arbc::ValueList objects;
    for (const Detection& d : world_->detect_objects(now())) {
      objects.push_back(arbc::Value::record({{"pos", arbc::Value(d.pos)}, {"dist", d.dist}}));
    }
    publish("objects", arbc::Value(std::move(objects)));
  }

 private:
  World* world_ = nullptr;
};

ARBC_REGISTER_MODULE(ObjectDetector, "ObjectDetector");

}  // namespace
}  // namespace arbc::table_clean
