#include "examples/table_clean/modules/machine_driver.h"

#include <algorithm>

namespace arbc::table_clean {

void MachineDriver::sync() {
  arbc::ModuleContext& ctx = module_.context();
  const std::vector<std::string> flags = machine_.status();
  if (!last_ || *last_ != flags) publish(flags);
  const std::optional<double> due = machine_.next_deadline();
  if (due == wake_due_) return;
  if (wake_due_) ctx.cancel(wake_timer_);
  wake_due_ = due;
  if (due) {
    const double at = *due;
    wake_timer_ = ctx.schedule(std::max(0.0, at - ctx.now()), [this, at] { wake(at); });
  }
}

void MachineDriver::heartbeat() {
  machine_.update(module_.context().now());
  publish(machine_.status());
  sync();
}

void MachineDriver::wake(double due) {
  wake_due_.reset();
  // The timer fires at `due` up to the rounding of now + delay: the step is due now.
  machine_.update(std::max(module_.context().now(), due));
  sync();
}

void MachineDriver::publish(const std::vector<std::string>& flags) {
  arbc::ValueList list;
  for (const std::string& f : flags) list.emplace_back(f);
  module_.context().publish(port_, arbc::Value(std::move(list)));
  last_ = flags;
}

}  // namespace arbc::table_clean
