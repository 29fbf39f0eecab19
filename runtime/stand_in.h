// Stand-in modules: what runs in place of a module no plugin provides, so that a spec can be
// tried and tested without C++ (docs/testing.md). A stand-in declares the app's ports of its
// module, publishes the timed values it is given (an `arbc run --inputs` file, the inputs of an
// `arbc test`) and, with `--stub`, samples at a rate per port (runtime/stand_in_sample.h); it
// records every message delivered to it. It uses only the module API (runtime/module.h): the
// runtime cannot tell it from a plugin's module. Its times are the runtime's whole nanoseconds
// (core/instant.h), through the module API's seconds, which carry them exactly for runs under 2^21
// s (24 days).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "runtime/module.h"

namespace arbc {

// A value to publish on an out-port of a stand-in at time t.
struct TimedValue {
  Nanos t{0};
  std::string port;  // "Module.port"
  Value value;
};

// A message delivered to a stand-in.
struct Received {
  Nanos t{0};
  std::string port;  // "Module.port"
  std::string connection;
  Value value;
};

// What stand-ins publish, beyond their scripted values: with `--stub`, a sample value every
// `period` seconds on each out-port that has no scripted value.
struct StubPlan {
  bool enabled = false;
  double default_period = 0.1;                   // 10 Hz
  std::map<std::string, double> period_of_port;  // "Module.port" -> seconds; 0: silent
};

// What a stand-in sink received on one port, in constant space: what `arbc run` prints.
struct ReceivedTally {
  uint64_t count = 0;
  Nanos first{0};
  Received last;
};

// What every stand-in of one run shares: its inputs, and what it received. The runtime runs all
// callbacks on one thread, so no lock is needed.
struct StandInLog {
  // The values the stand-ins publish besides --stub's samples: the lines of an `arbc run
  // --inputs` file, the steps of an `arbc test`. In the one order every way of running an app
  // uses (docs/runtime.md#messages-of-one-instant): by time, and at one instant in the order
  // listed, each published once the deliveries of the one before it have run. add_input keeps
  // that order (a value goes after every value of its instant already listed).
  void add_input(TimedValue v);
  const std::vector<TimedValue>& inputs() const { return inputs_; }
  // How many inputs are for `port` ("Module.port").
  uint64_t inputs_on(const std::string& port) const;

  StubPlan stub;
  // While a stand-in runs: how it publishes a value on one of its ports (by module name). The
  // inputs are played through them, whichever stand-in's port each is on.
  std::map<std::string, std::function<void(const TimedValue&)>> publishers;
  bool inputs_scheduled = false;  // by the first stand-in that started
  // Every message, for `arbc test`'s expectations. A run sets it false: a sink that kept every
  // value of a long run with --stub grew without bound, the tallies are what it prints.
  bool keep_received = true;
  std::vector<Received> received;              // in delivery order (keep_received)
  std::map<std::string, ReceivedTally> tally;  // "Module.port" -> what reached it
  std::map<std::string, uint64_t> published;   // "Module.port" -> messages published

 private:
  std::vector<TimedValue> inputs_;
};

// `base` plus a stand-in for every module of `app` that `base` does not register; the
// stand-ins' names are appended to *stand_ins. The stand-ins share `log`.
Registry registry_with_stand_ins(const model::App& app, const Registry& base,
                                 std::shared_ptr<StandInLog> log,
                                 std::vector<std::string>* stand_ins);

// One line per in-port of a stand-in: how many messages it received, when, and the last value;
// then per out-port how many it published. For `arbc run`'s output and report.
std::string stand_in_summary(const model::App& app, const std::vector<std::string>& stand_ins,
                             const StandInLog& log);

}  // namespace arbc
