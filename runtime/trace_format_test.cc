// The trace format is defined once (runtime/trace_format.h): every kind has a name, and every
// line the writer makes reads back as the record it came from, so `arbc run --diff` and
// `--inputs TRACE` read exactly what `arbc run --trace` writes.
#include "runtime/trace_format.h"

#include <gtest/gtest.h>

#include <set>

namespace arbc {
namespace {

using namespace std::chrono_literals;

constexpr TraceKind kAll[] = {TraceKind::Deliver,      TraceKind::Drop,        TraceKind::Event,
                              TraceKind::Error,        TraceKind::Quarantine,  TraceKind::Log,
                              TraceKind::PublishError, TraceKind::PluginError, TraceKind::Pending,
                              TraceKind::Publish,      TraceKind::Breach};

TEST(TraceFormatTest, EveryKindHasItsOwnNameAndIsFoundByIt) {
  std::set<std::string> names;
  for (TraceKind k : kAll) {
    std::string name = trace_kind_name(k);
    EXPECT_TRUE(names.insert(name).second) << name;
    EXPECT_EQ(trace_kind_named(name), k) << name;
  }
  EXPECT_FALSE(trace_kind_named("delivered"));
}

// A line with every field its kind has, filled with distinct text.
TraceLine full_line(TraceKind kind, const Value& value) {
  TraceLine l(2500ms, kind);
  l.connection = "take";
  l.port = "PickAndPlace.cmd";
  l.op = "set";
  l.event = "e_taken";
  l.owner = "feed_status";
  l.text = "monitors/take.lua:3: boom";
  l.callback = "tick";
  l.reason = DropReason::NotSelected;
  l.expiry = 3250ms;
  l.count = 7;
  l.value = &value;
  return l;
}

TEST(TraceFormatTest, EveryLineReadsBackAsTheRecordItWasWrittenFrom) {
  Value value = Value::record({{"verb", "take"}});
  for (TraceKind k : kAll) {
    TraceLine line = full_line(k, value);
    std::string text;
    append_trace_line(text, line);
    ASSERT_EQ(text.back(), '\n');
    TraceRecord read;
    nlohmann::json read_value;
    ASSERT_TRUE(read_trace_line(nlohmann::json::parse(text), &read, &read_value)) << text;
    // What the kind does not carry is not in the line, so compare with the written record's
    // fields the line does carry: writing the read record gives the same text.
    std::string again;
    TraceLine back(read.t, read.kind);
    back.connection = read.connection;
    back.port = read.port;
    back.op = read.op;
    back.event = read.event;
    back.owner = read.owner;
    back.text = read.text;
    back.callback = read.callback;
    back.reason = read.reason;
    back.expiry = read.expiry;
    back.count = read.count;
    Value parsed = read_value.is_null() ? Value() : value;
    back.value = read_value.is_null() ? nullptr : &parsed;
    append_trace_line(again, back);
    EXPECT_EQ(again, text);
    EXPECT_EQ(read.kind, k);
    EXPECT_EQ(read.t, 2500ms);
    bool has_value = k == TraceKind::Deliver || k == TraceKind::Publish;
    EXPECT_EQ(!read_value.is_null(), has_value) << text;
    if (has_value) {
      EXPECT_EQ(read_value.dump(), value.to_json());
    }
  }
}

TEST(TraceFormatTest, OptionalKeysAreLeftOutAndLinesMissingKeysAreRefused) {
  TraceLine drop(1s, TraceKind::Drop);
  drop.connection = "put";
  drop.reason = DropReason::Feed;
  std::string text;
  append_trace_line(text, drop);
  EXPECT_EQ(text, "{\"t\":1.0,\"type\":\"drop\",\"connection\":\"put\",\"reason\":\"feed\"}\n");
  TraceRecord r;
  EXPECT_TRUE(read_trace_line(nlohmann::json::parse(text), &r, nullptr));
  EXPECT_EQ(r.reason, DropReason::Feed);
  EXPECT_FALSE(read_trace_line(nlohmann::json::parse(R"({"t":1,"type":"drop","connection":"x"})"),
                               &r, nullptr));  // no reason
  EXPECT_FALSE(read_trace_line(
      nlohmann::json::parse(R"({"t":1,"type":"drop","connection":"x","reason":"bored"})"), &r,
      nullptr));
  EXPECT_FALSE(read_trace_line(nlohmann::json::parse(R"({"type":"log","from":"a","message":"m"})"),
                               &r, nullptr));  // no time
}

}  // namespace
}  // namespace arbc
