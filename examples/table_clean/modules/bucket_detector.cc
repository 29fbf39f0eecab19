// BucketDetector (the paper's Table I): where the bucket is, at 10 Hz, wherever the head looks.
#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class BucketDetector : public arbc::Module {
 public:
  BucketDetector() { out("bucket", "vec3"); }
  void start() override { world_ = find_world(*this); }
  double tick_period() const override { return 0.1; }
  void tick() override {
    if (world_) publish("bucket", arbc::Value(world_->detect_bucket(now())));
  }

 private:
  World* world_ = nullptr;
};

ARBC_REGISTER_MODULE(BucketDetector, "BucketDetector");

}  // namespace
}  // namespace arbc::table_clean
