// FaceDetector (the paper's Table I): the position of a face and how certain the detection is,
// at 10 Hz, only while the camera (the head's gaze) sees one.
#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class FaceDetector : public arbc::Module {
 public:
  FaceDetector() { out("face", "{pos: vec3, certainty: float}"); }
  void start() override { world_ = find_world(*this); }
  double tick_period() const override { return 0.1; }
  void tick() override {
    if (!world_) return;
    const std::optional<FaceSighting> face = world_->detect_face(now());
    if (!face) return;
    world_->referee().published(GazeSource::Face, face->pos, now());
    publish("face",
            arbc::Value::record({{"pos", arbc::Value(face->pos)}, {"certainty", face->certainty}}));
  }

 private:
  World* world_ = nullptr;
};

ARBC_REGISTER_MODULE(FaceDetector, "FaceDetector");

}  // namespace
}  // namespace arbc::table_clean
