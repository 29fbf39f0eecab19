// The in-process transport: one process hosts and mediates every module, so a published
// message goes straight to the connections from its port and a delivery straight to the
// module (docs/design.md#transports).
#include "runtime/transport.h"

namespace arbc {

namespace {

class InprocTransport : public Transport {
 public:
  std::string name() const override { return "inproc"; }

  // Every port must be hosted here (and every input mediated here): nothing leaves the process.
  bool open(const TransportPlan& plan, TransportSink* sink, std::string* error) override {
    for (const TransportPort& p : plan.inputs) {
      if (!p.hosted || !p.mediated) return refuse(p, error);
    }
    for (const TransportPort& p : plan.outputs) {
      if (!p.hosted) return refuse(p, error);
    }
    sink_ = sink;
    return true;
  }
  void publish(int out, const Value& v) override {
    sink_->from_source(out, v, TransportSink::kAnswersAll);
  }
  void deliver(int in, const Delivery& d) override { sink_->to_module(in, d); }
  bool loops_back() const override { return true; }

 private:
  static bool refuse(const TransportPort& p, std::string* error) {
    *error = "module " + p.module +
             " is not run by this process; the in-process transport runs every module (host "
             "and mediate a part of the app with --transport dds)";
    return false;
  }
  TransportSink* sink_ = nullptr;
};

}  // namespace

std::unique_ptr<Transport> make_inproc_transport() { return std::make_unique<InprocTransport>(); }

}  // namespace arbc
