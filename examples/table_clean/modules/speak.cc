// Speak (the paper's Table I): says the text it receives; a person who is present hears it.
#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class Speak : public arbc::Module {
 public:
  Speak() { in("text", "string"); }
  void start() override { world_ = find_world(*this); }
  void on_message(const std::string& port, const arbc::Value& text) override {
    context().log("says \"" + text.as_string() + "\"");
    if (world_) world_->person().hear(text.as_string(), now());
  }

 private:
  World* world_ = nullptr;
};

ARBC_REGISTER_MODULE(Speak, "Speak");

}  // namespace
}  // namespace arbc::table_clean
