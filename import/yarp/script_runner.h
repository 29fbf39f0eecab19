// Runs a YARP port monitor script in arbc's Lua sandbox (runtime/lua_sandbox.h), as YARP's
// portmonitor carrier would: the top level, then PortMonitor.create(options), then
// PortMonitor.accept on sample bottles. PortMonitor offers YARP's five functions (setEvent,
// unsetEvent, setConstraint, getConstraint, setTrigInterval), which only record; `yarp` is the
// stand-in of yarp_stand_in.h. This captures the constraint `create` sets, and the events a
// script sets with computed names on the samples (reported, never taken as all it can set).
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace arbc::yarp {

struct RecordedCall {
  std::string function;  // "setEvent", "unsetEvent", "setConstraint", "setTrigInterval"
  std::string text;      // the first argument (a string), if any
  std::optional<double> number;
  int line = 0;  // the script line that called it
};

struct SampleRun {
  std::string bottle;  // the sample, as Bottle text
  bool ok = false;     // accept returned without an error
  bool accepted = false;
  std::string error;
  std::vector<RecordedCall> calls;
};

struct ScriptRun {
  bool loaded = false;   // the top level ran
  bool created = false;  // create ran without error and returned a true value (or is absent)
  // The top level called require("yarp"). YARP hands create, accept and update a YARP object
  // (SWIG), and without the bindings loaded first its receiving process crashes.
  bool requires_yarp = false;
  std::string error;  // why not loaded / not created: "ball.lua:7: attempt to ..."
  std::optional<std::string> constraint;  // the last setConstraint before accept
  int constraint_line = 0;
  std::vector<RecordedCall> create_calls;  // top level and create
  std::vector<SampleRun> samples;
};

struct MonitorContext {
  std::string filename;     // as YARP passes it to create: the script's path
  std::string source;       // the connection's source port
  std::string destination;  // and destination port
  std::string carrier;      // the carrier name YARP reports ("tcp")
};

// `chunk_name` names the script in error messages (its path). `samples` are Bottle texts.
ScriptRun run_script(const std::string& text, const std::string& chunk_name,
                     const MonitorContext& context, const std::vector<std::string>& samples);

// Sample bottles for `accept`: empty, each string literal and number of the script alone
// (at most a few of each), and a list of numbers.
std::vector<std::string> sample_bottles(const std::set<std::string>& strings,
                                        const std::set<double>& numbers);

}  // namespace arbc::yarp
