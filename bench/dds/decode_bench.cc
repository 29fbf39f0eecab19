// What a big ROS 2 message costs a mediator (issue 41, docs/benchmarks.md "ROS 2 messages"):
// per message, the sample's CDR bytes decoded into its wire type (Fast-DDS dynamic data), read
// into a spec value (dds/wire_values.h), published into the runtime and judged by a rule that
// reads one field, then delivered:
//   decode_laser_scan     sensor_msgs/msg/LaserScan with 1,080 ranges and 1,080 intensities
//                         (what a 270-degree lidar at a quarter degree sends), the rule reading
//                         range_min
//   decode_three_fields   the baseline: a message of three float32s, the rule reading one
//   encode_laser_scan     the write side: the LaserScan value to its sample's bytes by the
//                         mediator's writer, against encode_laser_scan_fastdds, the same by
//                         Fast-DDS's dynamic data (the path before dds/cdr_write.h)
// Under callgrind (bench/figures/decode.sh) each counts a window of its messages alone.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>

#include "bench/instruction_window.h"
#include "dds/cdr_write.h"
#include "dds/topic_type.h"
#include "dds/wire_types.h"
#include "dds/wire_values.h"
#include "runtime/runtime.h"

namespace {

using namespace std::chrono_literals;
using namespace arbc;

constexpr int kRanges = 1080;

const char* kLaserScan =
    "{header: {stamp: {sec: int32, nanosec: uint32}, frame_id: string}, angle_min: float32, "
    "angle_max: float32, angle_increment: float32, time_increment: float32, scan_time: float32, "
    "range_min: float32, range_max: float32, ranges: list<float32>, intensities: list<float32>}";
const char* kThree = "{x: float32, y: float32, z: float32}";

class Source : public Module {};
class Sink : public Module {
 public:
  void on_message(const std::string&, const Value& v) override { benchmark::DoNotOptimize(v); }
};

Value laser_scan() {
  ValueList ranges, intensities;
  for (int i = 0; i < kRanges; ++i) {
    ranges.emplace_back(0.25 + i / 256.0);  // exact in a float32
    intensities.emplace_back(double(i % 100));
  }
  Value stamp =
      Value::record({{"sec", Value(int64_t{1764633600})}, {"nanosec", Value(int64_t{5})}});
  return Value::record({{"header", Value::record({{"stamp", stamp}, {"frame_id", "laser"}})},
                        {"angle_min", -2.375},
                        {"angle_max", 2.375},
                        {"angle_increment", 0.00439453125},
                        {"time_increment", 0.0},
                        {"scan_time", 0.03125},
                        {"range_min", 0.0625},
                        {"range_max", 30.0},
                        {"ranges", Value(std::move(ranges))},
                        {"intensities", Value(std::move(intensities))}});
}

// Sensor.scan -> Planner.scan through rule `near`, whose monitor reads one field; the port's
// type is `type_text`.
model::App decode_app(const char* type_text, const char* field) {
  model::App app;
  app.name = "decode";
  app.types.push_back({"Scan", parse_type(type_text), {}});
  model::Module sensor{"Sensor", "", {}, {}}, planner{"Planner", "", {}, {}};
  sensor.ports.push_back({"scan", model::Direction::Out, parse_type(type_text), {}});
  planner.ports.push_back({"scan", model::Direction::In, parse_type(type_text), {}});
  app.modules = {sensor, planner};
  model::Connection c;
  c.name = "near";
  c.source = "Sensor.scan";
  c.destination = "Planner.scan";
  c.constraint = Constraint::constant(true);
  c.monitor = "monitors/near.lua";
  app.connections.push_back(c);
  std::string dir = std::string(ARBC_BINARY_DIR) + "/bench_decode_app";
  std::filesystem::create_directories(dir + "/monitors");
  std::ofstream(dir + "/monitors/near.lua")
      << "PortMonitor.accept = function(scan)\n  return scan." << field << " >= 0\nend\n";
  return app;
}

// The wire type of Sensor.scan (the port's type is `type_text`).
std::shared_ptr<const dds::WireType> scan_wire(const model::App& app, const char* type_text,
                                               std::string* error) {
  dds::Deployment deployment;
  dds::WireNaming naming(app, deployment);
  return naming.port_type("Sensor", "scan", parse_type(type_text), error);
}

void decode(benchmark::State& state, const char* type_text, const char* field, const Value& v,
            bench::InstructionWindow& window) {
  model::App app = decode_app(type_text, field);
  std::string error;
  auto wire = scan_wire(app, type_text, &error);
  if (!wire) return state.SkipWithError(error.c_str());
  dds::WireTopicType codec(wire);
  auto* out = static_cast<dds::WireSample*>(codec.createData());
  auto* in = static_cast<dds::WireSample*>(codec.createData());
  if (!dds::to_wire(*wire, v, out->data, &error)) return state.SkipWithError(error.c_str());
  eprosima::fastrtps::rtps::SerializedPayload_t payload(codec.getSerializedSizeProvider(out)());
  codec.serialize(out, &payload);
  Registry registry;
  registry.add_module("Sensor", [] { return std::make_unique<Source>(); });
  registry.add_module("Planner", [] { return std::make_unique<Sink>(); });
  auto rt = Runtime::create(app, std::string(ARBC_BINARY_DIR) + "/bench_decode_app", RunOptions{},
                            &error, registry);
  if (!rt) return state.SkipWithError(error.c_str());
  rt->start();
  Nanos t{0};
  uint64_t messages = 0;
  for (auto _ : state) {
    payload.pos = 0;
    codec.deserialize(&payload, in);
    if (in->bad) return state.SkipWithError("a sample did not decode");
    // What the mediator's reader passes on (dds_endpoints.cc, TopicReader::take_one).
    Value decoded = std::move(in->value);
    rt->publish("Sensor", "scan", std::move(decoded));
    t += 1ms;
    rt->advance(t);
    window.after(++messages);
  }
  state.counters["delivered"] = static_cast<double>(rt->stats()[0].delivered);
  state.counters["bytes"] = payload.length;
  codec.deleteData(out);
  codec.deleteData(in);
}

void BM_DecodeLaserScan(benchmark::State& state) {
  // About 10 ms a message natively: 100 after 20 (bench/figures/decode.sh divides by 100).
  static bench::InstructionWindow window("decode_laser_scan", 20, 100);
  static const Value scan = laser_scan();
  decode(state, kLaserScan, "range_min", scan, window);
}
void BM_DecodeThreeFields(benchmark::State& state) {
  static bench::InstructionWindow window("decode_three_fields");
  static const Value three = Value::record({{"x", 0.5}, {"y", -1.25}, {"z", 3.0}});
  decode(state, kThree, "x", three, window);
}
BENCHMARK(BM_DecodeLaserScan)->Iterations(130);  // past the window, whatever --benchmark_min_time
BENCHMARK(BM_DecodeThreeFields);

// The write side: a delivered value to the bytes of its sample, by the mediator's writer
// (dds/cdr_write.h) and, the baseline, by Fast-DDS's dynamic data (to_wire, then its encoder),
// the path the mediator took before.
void encode(benchmark::State& state, const char* type_text, const Value& v, bool fastdds,
            bench::InstructionWindow& window) {
  std::string error;
  auto wire = scan_wire(decode_app(type_text, "x"), type_text, &error);
  if (!wire) return state.SkipWithError(error.c_str());
  dds::WireTopicType codec(wire);
  auto* out = static_cast<dds::WireSample*>(codec.createData());
  eprosima::fastrtps::rtps::SerializedPayload_t payload(64 * 1024);
  uint64_t messages = 0;
  for (auto _ : state) {
    bool written = fastdds ? dds::to_wire(*wire, v, out->data, &error)
                           : dds::cdr_write(*wire->type, v, &out->bytes, &error);
    if (!written || !codec.serialize(out, &payload))
      return state.SkipWithError("a value did not encode");
    window.after(++messages);
  }
  state.counters["bytes"] = payload.length;
  codec.deleteData(out);
}

void BM_EncodeLaserScan(benchmark::State& state) {
  static bench::InstructionWindow window("encode_laser_scan", 20, 100);
  static const Value scan = laser_scan();
  encode(state, kLaserScan, scan, false, window);
}
void BM_EncodeLaserScanFastDds(benchmark::State& state) {
  static bench::InstructionWindow window("encode_laser_scan_fastdds", 20, 100);
  static const Value scan = laser_scan();
  encode(state, kLaserScan, scan, true, window);
}
BENCHMARK(BM_EncodeLaserScan)->Iterations(130);
BENCHMARK(BM_EncodeLaserScanFastDds)->Iterations(130);

}  // namespace

BENCHMARK_MAIN();
