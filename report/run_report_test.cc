#include "report/run_report.h"

#include <gtest/gtest.h>

#include <set>

#include "runtime/runtime_test_util.h"

namespace arbc::report {

using namespace std::chrono_literals;
namespace {

using arbc::testing::TestApp;

constexpr const char* kNastyName = "odd<&>\"'name";

// A run of a small app with a feed, a rule with drops of several reasons, and a connection
// whose name needs escaping; returns the report.
struct ReportedRun {
  std::vector<ConnectionStats> stats;
  std::vector<TraceRecord> records;
  std::string html;
};

ReportedRun run_and_report(double duration) {
  TestApp t;
  add_noisy_app(t);
  t.connect("rule", "Noisy.x", "Sink.x", "e",
            "PortMonitor.accept = function(m)\n"
            "  if m % 5 == 0 then return false, 'multiple of <5>' end\n"
            "  return true\n"
            "end\n"
            "PortMonitor.update = function(m) if m % 7 == 0 then PortMonitor.novalue() end "
            "return m end\n");
  t.connect(kNastyName, "Noisy.x", "Sink.x", "not e");
  ReportedRun run;
  RunOptions o;
  o.duration = duration;
  o.seed = 3;
  o.trace_records = &run.records;
  auto rt = t.start(o);
  rt->advance(nanos_from_seconds(duration));
  rt->shutdown();
  run.stats = rt->stats();

  RunReportInput input;
  input.header.app = "noisy";
  input.header.description = "<script>alert('pwned')</script> & more";
  input.header.scenario = "s<1>";
  input.header.seed = 3;
  input.header.requested = duration;
  input.header.end = seconds_of(rt->now());
  input.header.success = true;
  input.header.verdict = "success";
  input.header.proof = "not verified (--no-verify)";
  for (size_t i = 0; i < run.stats.size(); ++i) {
    const model::Connection& c = t.app.connections[i];
    input.connections.push_back(
        {run.stats[i], c.kind == model::ConnectionKind::Feed, c.constraint.to_string()});
  }
  input.records = &run.records;
  run.html = render_run_report(input);
  return run;
}

// The part of html from the element with this id to the end of that element's tag name.
std::string section(const std::string& html, const std::string& tag, const std::string& id) {
  size_t begin = html.find("<" + tag + " class=\"timeline\" id=\"" + id + "\"");
  if (begin == std::string::npos) begin = html.find("<" + tag + " id=\"" + id + "\"");
  if (begin == std::string::npos) return {};
  size_t end = html.find("</" + tag + ">", begin);
  return html.substr(begin, end - begin);
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The numbers in a counters row: arrived, delivered, the drop reasons, pending, errors.
std::vector<uint64_t> row_numbers(const std::string& html, const std::string& escaped_name) {
  std::string table = section(html, "table", "counters");
  size_t begin = table.find("data-connection=\"" + escaped_name + "\"");
  if (begin == std::string::npos) return {};
  std::string row = table.substr(begin, table.find("</tr>", begin) - begin);
  // Each number cell is `<td class="n">N</td>` or `<td class="n zero">0</td>`.
  std::vector<uint64_t> out;
  for (size_t at = row.find("<td class=\"n"); at != std::string::npos;
       at = row.find("<td class=\"n", at + 1)) {
    size_t digits = row.find("\">", at) + 2;
    out.push_back(std::stoull(row.substr(digits, row.find("</td>", digits) - digits)));
  }
  return out;
}

std::vector<uint64_t> expected_numbers(const ConnectionStats& s) {
  std::vector<uint64_t> out = {s.arrived, s.delivered};
  for (uint64_t d : s.dropped) out.push_back(d);
  out.push_back(s.pending);
  out.push_back(s.errors);
  return out;
}

// One 30 s run shared by the tests (made in the first test's SetUp: TestApp needs a test).
class RunReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!run_) run_ = new ReportedRun(run_and_report(30));
  }
  static void TearDownTestSuite() {
    delete run_;
    run_ = nullptr;
  }
  static ReportedRun* run_;
};
ReportedRun* RunReportTest::run_ = nullptr;

TEST_F(RunReportTest, OneDeliveryLanePerConnectionAndOneEventLane) {
  std::string deliveries = section(run_->html, "svg", "deliveries");
  ASSERT_FALSE(deliveries.empty());
  EXPECT_EQ(count(deliveries, "<g class=\"lane\">"), 3u);
  // Rules first, then the feed under its own heading.
  size_t rule = deliveries.find(">rule<"), nasty = deliveries.find(">odd&lt;&amp;&gt;");
  size_t feeds = deliveries.find("event feeds"), feed = deliveries.find(">feed<");
  EXPECT_LT(rule, nasty);
  EXPECT_LT(nasty, feeds);
  EXPECT_LT(feeds, feed);
  ASSERT_NE(feed, std::string::npos);
  std::string events = section(run_->html, "svg", "events");
  EXPECT_EQ(count(events, "<g class=\"lane\">"), 1u);
  EXPECT_NE(events.find(">e<"), std::string::npos);
  EXPECT_GT(count(events, "present "), 5u);
}

// A run over a transport has a table with a row per topic, drawn from the transport's status
// (not from its text): whether a peer was ever heard, what was received, lost and written; a
// topic that never heard a peer is marked; what discovery found amiss is listed; names are
// escaped. An in-process run has no such section.
TEST_F(RunReportTest, ATransportHasATableOfItsTopicsAndInProcessHasNone) {
  EXPECT_EQ(run_->html.find("<h2>Transport</h2>"), std::string::npos);
  RunReportInput input;
  input.header.app = "split";
  input.transport.placement = "dds (domain 7, hosting M, mediating <all>)";
  input.transport.status.domain = 7;
  TransportTopicStatus heard;
  heard.topic = "M/x", heard.port = "M.x", heard.type = "int", heard.heard_peer = true;
  heard.peers_now = 1, heard.received = 40, heard.lost = 3, heard.undecodable = 2;
  TransportTopicStatus alone;
  alone.topic = "W/y<1>", alone.port = "W.y", alone.type = "int", alone.read = false;
  alone.written = 5, alone.to_nobody = 4, alone.failed = 1;
  input.transport.status.topics = {heard, alone};
  input.transport.status.notes = {"DDS: topic M/x: a remote writer's type is <other>"};
  std::string html = render_run_report(input);
  ASSERT_NE(html.find("<h2>Transport</h2>"), std::string::npos);
  EXPECT_NE(html.find("<p id=\"transport\">dds (domain 7, hosting M, mediating &lt;all&gt;)</p>"),
            std::string::npos);
  std::string table = section(html, "table", "transport-topics");
  EXPECT_NE(table.find("<tr><td><code>M/x</code></td><td>M.x</td><td><code>int</code></td>"
                       "<td>read</td><td>yes</td><td class=\"n\">1</td><td class=\"n\">40</td>"
                       "<td class=\"n\">3</td><td class=\"n\">2</td>"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("<tr class=\"bad\"><td><code>W/y&lt;1&gt;</code></td><td>W.y</td>"
                       "<td><code>int</code></td><td>written</td><td>never</td>"),
            std::string::npos)
      << table;
  // Written to nobody (no subscriber had matched) apart from written (issue 39).
  EXPECT_NE(table.find("<th class=\"n\">to nobody</th>"), std::string::npos) << table;
  EXPECT_NE(table.find("<td class=\"n\">5</td><td class=\"n\">4</td><td class=\"n\">1</td></tr>"),
            std::string::npos)
      << table;
  std::string notes = section(html, "ul", "transport-notes");
  EXPECT_NE(notes.find("<li>DDS: topic M/x: a remote writer&#39;s type is &lt;other&gt;</li>"),
            std::string::npos)
      << notes;
  // No text to parse: the summary's lines are not on the page.
  EXPECT_EQ(html.find("transport-summary"), std::string::npos);
  // Before the counters: it explains a page of empty timelines.
  EXPECT_LT(html.find("<h2>Transport</h2>"), html.find("<h2>Counters per connection</h2>"));
}

// The header says whether the app that ran was proved (issue 13).
TEST_F(RunReportTest, TheHeaderSaysWhetherTheAppWasProved) {
  EXPECT_NE(run_->html.find("<dt>proof</dt><dd id=\"proof\" class=\"bad\">not verified "
                            "(--no-verify)</dd>"),
            std::string::npos);
}

TEST_F(RunReportTest, CountersEqualTheRuntimeCounters) {
  ConnectionStats total;
  for (const ConnectionStats& s : run_->stats) {
    std::string name = s.name == kNastyName ? "odd&lt;&amp;&gt;&quot;&#39;name" : s.name;
    EXPECT_EQ(row_numbers(run_->html, name), expected_numbers(s)) << s.name;
    total.arrived += s.arrived;
    total.delivered += s.delivered;
    for (int r = 0; r < kDropReasonCount; ++r) total.dropped[r] += s.dropped[r];
    total.pending += s.pending;
    total.errors += s.errors;
  }
  EXPECT_EQ(row_numbers(run_->html, ""), expected_numbers(total));
  // The run exercised several reasons, so the columns are really compared.
  EXPECT_GT(total.delivered, 0u);
  EXPECT_GT(total.drops(DropReason::Rejected), 0u);
  EXPECT_GT(total.drops(DropReason::NoValue), 0u);
  EXPECT_GT(total.drops(DropReason::NotSelected), 0u);
  EXPECT_GT(total.drops(DropReason::Feed), 0u);
}

// The timeline is drawn from the trace records; its per-lane totals must match the counters,
// so no record was lost on the way.
TEST_F(RunReportTest, TimelineTotalsMatchTheCounters) {
  std::string deliveries = section(run_->html, "svg", "deliveries");
  for (const ConnectionStats& s : run_->stats) {
    uint64_t dropped = 0;
    for (uint64_t d : s.dropped) dropped += d;
    std::string text = ">" + std::to_string(s.delivered) + " / " + std::to_string(dropped) +
                       "<title>delivered / dropped";
    EXPECT_NE(deliveries.find(text), std::string::npos) << s.name << ": " << text;
  }
}

TEST_F(RunReportTest, DropsByReasonListsReasonsConnectionsAndDetails) {
  std::string drops = section(run_->html, "table", "drops");
  for (int r = 0; r < kDropReasonCount; ++r) {
    EXPECT_NE(drops.find(std::string("data-reason=\"") + drop_reason_name(DropReason(r)) + "\""),
              std::string::npos);
  }
  // The rejection's detail, escaped.
  EXPECT_NE(drops.find("multiple of &lt;5&gt; ("), std::string::npos);
}

TEST_F(RunReportTest, EveryNameIsEscaped) {
  const std::string& html = run_->html;
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(&#39;pwned&#39;)&lt;/script&gt; &amp; more"),
            std::string::npos);
  EXPECT_EQ(html.find(kNastyName), std::string::npos);
  EXPECT_NE(html.find("odd&lt;&amp;&gt;&quot;&#39;name"), std::string::npos);
  EXPECT_NE(html.find("<dd id=\"scenario\">s&lt;1&gt;</dd>"), std::string::npos);
  EXPECT_EQ(count(html, "<script"), 1u);  // only the report's own inline script
}

TEST_F(RunReportTest, SelfContained) {
  const std::string& html = run_->html;
  for (const char* reference : {"http://", "https://", "<script src", "<link", "@import", "url(",
                                "<img", "<iframe", "src="}) {
    EXPECT_EQ(html.find(reference), std::string::npos) << reference;
  }
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<meta charset=\"utf-8\">"), std::string::npos);
}

// Bins keep the page small: ten times the run, hardly a bigger page.
TEST_F(RunReportTest, SizeIsBoundedByBinsNotByTheRunsLength) {
  ReportedRun longer = run_and_report(300);
  uint64_t delivered = 0;
  for (const ConnectionStats& s : longer.stats) delivered += s.delivered;
  EXPECT_GT(delivered, 5 * 300u / 10);
  EXPECT_LT(longer.html.size(), 400u * 1024) << longer.html.size();
  EXPECT_LT(longer.html.size(), 3 * run_->html.size());
}

}  // namespace
}  // namespace arbc::report

namespace arbc::report {
namespace {

// A run of 2 ms with a message every 0.1 ms: the hovers and the cursor write its times in ms
// with the decimals that tell the deliveries apart (they all read 0.000 to 0.002 s before).
TEST(RunReportShortRunTest, TimesFitTheRunsLength) {
  arbc::testing::TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("fast", "Src.x", "Sink.x", "true");
  std::vector<TraceRecord> records;
  RunOptions o;
  o.trace_records = &records;
  auto rt = t.start(o);
  for (int k = 0; k < 20; ++k)
    arbc::testing::TestApp::publish_at(*rt, 1e-4 * k, "Src", "x", Value(k));
  rt->advance(2ms);
  rt->shutdown();
  std::vector<ConnectionStats> stats = rt->stats();
  ASSERT_EQ(stats[0].delivered, 20u);

  RunReportInput input;
  input.header.app = "fast";
  input.header.end = seconds_of(rt->now());
  input.header.requested = 0.002;
  input.connections.push_back({stats[0], false, "true"});
  input.records = &records;
  std::string svg = section(render_run_report(input), "svg", "deliveries");
  std::set<std::string> titles;
  for (size_t at = svg.find("<title>fast: 1 delivery, "); at != std::string::npos;
       at = svg.find("<title>fast: 1 delivery, ", at + 1))
    titles.insert(svg.substr(at, svg.find("</title>", at) - at));
  EXPECT_EQ(titles.size(), 20u);
  EXPECT_NE(svg.find("<title>fast: 1 delivery, 0.100\u20130.107 ms</title>"), std::string::npos)
      << svg;
  EXPECT_NE(svg.find("data-unit=\"ms\""), std::string::npos);
  EXPECT_NE(svg.find(">1.0 ms</text>"), std::string::npos);  // an axis tick
  EXPECT_NE(svg.find("<title>end of run: 2.000 ms</title>"), std::string::npos);
}

// The header and the lists at the end write times as the timelines do: a 2 ms run is not
// "0.002 s of 0.002 s requested", and its log lines are not all "0.000" to "0.002".
TEST(RunReportShortRunTest, TheHeaderAndTheLogFitTheRunsLengthToo) {
  std::vector<TraceRecord> records(2);
  records[0].t = 1250us;
  records[0].kind = TraceKind::Log;
  records[0].connection = "environment";
  records[0].text = "half way";
  records[1].t = 1500us;
  records[1].kind = TraceKind::Error;
  records[1].connection = "fast";
  records[1].text = "boom";
  RunReportInput input;
  input.header.app = "fast";
  input.header.end = 0.002;
  input.header.requested = 60;
  input.records = &records;
  std::string html = render_run_report(input);
  EXPECT_NE(html.find("<dd id=\"duration\">2.000 ms of 60.000 s requested"), std::string::npos)
      << html.substr(0, 3000);
  EXPECT_NE(html.find("1.250 ms  environment: half way\n"), std::string::npos) << html;
  EXPECT_NE(html.find("1.500 ms  error on fast: boom\n"), std::string::npos) << html;
}

// A monitor that always fails: its errors are listed, its quarantine is marked on its lane
// and in its counters row, and the outcome shows as a failure.
TEST(RunReportFailureTest, ErrorsAndQuarantineAreShown) {
  arbc::testing::TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("broken", "Src.x", "Sink.x", "true",
            "PortMonitor.accept = function(m) error('boom ' .. m) end\n");
  std::vector<TraceRecord> records;
  RunOptions o;
  o.trace_records = &records;
  auto rt = t.start(o);
  for (int k = 0; k < 8; ++k) {
    arbc::testing::TestApp::publish_at(*rt, 1 + k * 0.5, "Src", "x", Value(k));
  }
  rt->advance(6s);
  rt->shutdown();
  std::vector<ConnectionStats> stats = rt->stats();
  ASSERT_TRUE(stats[0].quarantined);

  RunReportInput input;
  input.header.app = "failing";
  input.header.end = seconds_of(rt->now());
  input.header.requested = 6;
  input.header.verdict =
      "failure (no environment; judged by quarantined connections and messages of the wrong type)";
  input.connections.push_back({stats[0], false, "true"});
  input.records = &records;
  std::string html = render_run_report(input);

  EXPECT_NE(html.find("<dd id=\"outcome\" class=\"bad\">failure (no environment"),
            std::string::npos);
  EXPECT_NE(html.find("<title>broken: quarantined at 3.000 s</title>"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"bad\">quarantined</span>"), std::string::npos);
  std::string problems = html.substr(html.find("<pre id=\"problems\">"));
  problems = problems.substr(0, problems.find("</pre>"));
  EXPECT_NE(problems.find("1.000 s  error on broken: "), std::string::npos) << problems;
  EXPECT_NE(problems.find("boom 0"), std::string::npos);
  EXPECT_NE(problems.find("3.000 s  quarantined broken: 5 failures in a row"), std::string::npos)
      << problems;
  EXPECT_EQ(count(html, "error on broken"), 5u);
  // The totals line reads as a sentence for one connection too.
  EXPECT_NE(html.find("<p id=\"totals\">1 connection: 8 messages arrived, 0 delivered, 8 "
                      "dropped, 0 pending (still queued at the end); 5 monitor errors, 1 "
                      "connection quarantined.</p>"),
            std::string::npos);
  // The counters' columns carry the names of `arbc run`'s table (arrived, pending).
  EXPECT_NE(html.find("<th class=\"n\">arrived</th>"), std::string::npos);
  EXPECT_NE(html.find("<th class=\"n\">pending</th>"), std::string::npos);
  // The three later messages are dropped as quarantined, the five before as monitor errors
  // (one column per drop reason, lost-in-transit and bad-value last).
  EXPECT_EQ(row_numbers(html, "broken"),
            (std::vector<uint64_t>{8, 0, 0, 0, 0, 0, 0, 5, 3, 0, 0, 0, 0, 0, 5}));
}

// A plugin whose tick throws: the run goes on and the report lists the plugin error.
class Jammed : public Module {
 public:
  double tick_period() const override { return 1.0; }
  void tick() override { throw std::runtime_error("arm <jammed>"); }
};

TEST(RunReportFailureTest, PluginErrorsAreListed) {
  arbc::testing::TestApp t;
  t.registry.add_module("Jammed", [] { return std::make_unique<Jammed>(); });
  t.module("Jammed", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Jammed.x", "Sink.x", "true");
  std::vector<TraceRecord> records;
  RunOptions o;
  o.trace_records = &records;
  auto rt = t.start(o);
  rt->advance(3500ms);
  rt->shutdown();

  RunReportInput input;
  input.header.app = "jammed";
  input.header.end = seconds_of(rt->now());
  input.header.requested = 3.5;
  input.connections.push_back({rt->stats()[0], false, "true"});
  input.records = &records;
  std::string html = render_run_report(input);
  std::string problems = html.substr(html.find("<pre id=\"problems\">"));
  problems = problems.substr(0, problems.find("</pre>"));
  EXPECT_NE(problems.find("plugin error in Jammed (tick): "), std::string::npos) << problems;
  EXPECT_NE(problems.find("arm &lt;jammed&gt;"), std::string::npos) << problems;
  EXPECT_EQ(count(problems, "plugin error in Jammed"), 3u);  // ticks at 1, 2 and 3 s
}

}  // namespace
}  // namespace arbc::report
