// Two modules for the installed-package test: Counter publishes 1, 2, 3, ... ten times a
// second; Printer logs every value it receives.
#include <string>

#include "runtime/module.h"  // under <prefix>/include/arbc, which the package adds

namespace hello {

class Counter : public arbc::Module {
 public:
  Counter() { out("count", "int"); }
  double tick_period() const override { return 0.1; }
  void tick() override { publish("count", arbc::Value(++n_)); }

 private:
  int64_t n_ = 0;
};

class Printer : public arbc::Module {
 public:
  Printer() { in("value", "int"); }
  void on_message(const std::string& port, const arbc::Value& v) override {
    context().log("Printer got " + std::to_string(v.as_int()));
  }
};

ARBC_REGISTER_MODULE(Counter, "Counter");
ARBC_REGISTER_MODULE(Printer, "Printer");

}  // namespace hello
