#include "report/run_report.h"

#include <algorithm>
#include <map>

#include "report/html_text.h"
#include "report/page_assets.h"
#include "report/run_timeline.h"
#include "report/svg_timeline.h"

namespace arbc::report {

namespace {

constexpr size_t kMaxListed = 200;       // log lines, errors: the first ones, then a count
constexpr size_t kDetailsPerReason = 3;  // sample details shown per drop reason

const char* reason_meaning(DropReason r) { return drop_reason_info(r).meaning; }

std::string escaped(std::string_view s) { return html_escape(s); }

std::string number_cell(uint64_t n) {
  return std::string("<td class=\"n") + (n == 0 ? " zero" : "") + "\">" + std::to_string(n) +
         "</td>";
}

std::string swatch(const char* color) {
  return std::string("<span class=\"swatch\" style=\"background:") + color + "\"></span>";
}

uint64_t total_dropped(const ConnectionStats& s) {
  uint64_t n = 0;
  for (uint64_t d : s.dropped) n += d;
  return n;
}

void append_header(std::string& out, const RunHeader& h) {
  out += "<h1>arbc run report: " + escaped(h.app) + "</h1>\n";
  if (!h.description.empty())
    out += "<p class=\"description\">" + escaped(h.description) + "</p>\n";
  out += "<dl class=\"header\">\n";
  out += "<dt>scenario</dt><dd id=\"scenario\">" + escaped(h.scenario) + "</dd>\n";
  out += "<dt>seed</dt><dd id=\"seed\">" + std::to_string(h.seed) + "</dd>\n";
  if (!h.proof.empty()) {
    bool verified = h.proof.rfind("verified", 0) == 0;
    out += std::string("<dt>proof</dt><dd id=\"proof\" class=\"") + (verified ? "ok" : "bad") +
           "\">" + escaped(h.proof) + "</dd>\n";
  }
  // The time run as the timelines write it (a 2 ms run read "0.002 s"); the duration asked for
  // in a unit of its own, which an early stop may make far larger.
  out += std::string("<dt>") + (h.realtime ? "wall-clock" : "simulated") +
         " time</dt><dd id=\"duration\">" + timeline_time_format(h.end).text(h.end) + " of " +
         TimeFormat::for_run(h.requested).text(h.requested) + " requested";
  if (!h.stop_reason.empty()) out += " (stopped early: " + escaped(h.stop_reason) + ")";
  out += "</dd>\n";
  out += std::string("<dt>outcome</dt><dd id=\"outcome\" class=\"") + (h.success ? "ok" : "bad") +
         "\">" + escaped(h.verdict) + "</dd>\n</dl>\n";
  if (!h.environment.empty()) {
    out += "<h2>Environment summary</h2>\n<pre>" + escaped(h.environment) + "</pre>\n";
  }
}

// One row per topic: a topic that never heard a peer is marked, since nothing flowed there.
void append_transport_topic(std::string& out, const TransportTopicStatus& t) {
  bool alone = !t.heard_peer && t.expects_peer;
  std::string heard = t.heard_peer ? "yes" : t.expects_peer ? "never" : "no (none expected)";
  auto count = [](uint64_t n) { return "<td class=\"n\">" + std::to_string(n) + "</td>"; };
  auto blank = std::string("<td class=\"n\"></td>");
  out += std::string("<tr") + (alone ? " class=\"bad\"" : "") + "><td><code>" + escaped(t.topic) +
         "</code></td><td>" + escaped(t.port) + "</td><td><code>" + escaped(t.type) +
         "</code></td><td>" + (t.read ? "read" : "written") + "</td><td>" + heard +
         "</td><td class=\"n\">" + std::to_string(t.peers_now) + "</td>";
  if (t.read) {
    out += count(t.received) + count(t.lost) + count(t.undecodable) + blank + blank + blank;
  } else {
    out += blank + blank + blank + count(t.written) + count(t.to_nobody) + count(t.failed);
  }
  out += "</tr>\n";
}

void append_transport(std::string& out, const TransportSection& t) {
  if (t.placement.empty() && t.status.topics.empty()) return;
  out += "<h2>Transport</h2>\n";
  if (!t.placement.empty()) out += "<p id=\"transport\">" + escaped(t.placement) + "</p>\n";
  if (t.status.topics.empty()) return;
  out += "<p>DDS domain " + std::to_string(t.status.domain) +
         ". Lost: samples DDS reported lost before they reached this process (lost-in-transit), "
         "or that came while its queue for the topic was full (queue-full). To nobody: written "
         "while no subscriber had matched, so no program received them.</p>\n"
         "<div class=\"wide\">\n"
         "<table id=\"transport-topics\">\n<tr><th>topic</th><th>port</th><th>type</th>"
         "<th>here</th><th>heard a peer</th><th class=\"n\">peers at the end</th>"
         "<th class=\"n\">received</th><th class=\"n\">lost</th>"
         "<th class=\"n\">undecodable</th><th class=\"n\">written</th>"
         "<th class=\"n\">to nobody</th><th class=\"n\">failed</th></tr>\n";
  for (const TransportTopicStatus& topic : t.status.topics) append_transport_topic(out, topic);
  out += "</table>\n</div>\n";
  if (t.status.notes.empty()) return;
  out += "<ul id=\"transport-notes\">\n";
  for (const std::string& note : t.status.notes) out += "<li>" + escaped(note) + "</li>\n";
  out += "</ul>\n";
}

// "1 connection", "2 connections": the totals line is read as a sentence.
std::string counted(uint64_t n, const std::string& noun, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? noun : plural);
}

void append_totals(std::string& out, const std::vector<ConnectionRow>& rows) {
  uint64_t arrived = 0, delivered = 0, dropped = 0, pending = 0, errors = 0, quarantined = 0;
  for (const ConnectionRow& r : rows) {
    arrived += r.stats.arrived;
    delivered += r.stats.delivered;
    dropped += total_dropped(r.stats);
    pending += r.stats.pending;
    errors += r.stats.errors;
    quarantined += r.stats.quarantined ? 1 : 0;
  }
  out += "<p id=\"totals\">" + counted(rows.size(), "connection", "connections") + ": " +
         counted(arrived, "message", "messages") + " arrived, " + std::to_string(delivered) +
         " delivered, " + std::to_string(dropped) + " dropped, " + std::to_string(pending) +
         " pending (still queued at the end); " +
         counted(errors, "monitor error", "monitor errors") + ", " +
         counted(quarantined, "connection", "connections") + " quarantined.</p>\n";
}

// What the run checked of the proof, and what it found broken: from a breach on, the proof no
// longer covers the run (docs/runtime.md#runtime-checks).
void append_checks(std::string& out, const RunReportInput& input) {
  out += "<h2>Runtime checks</h2>\n";
  if (!input.checks_watched) {
    out += "<p id=\"runtime-checks\">None watched (<code>--runtime-checks off</code>).</p>\n";
    return;
  }
  if (input.checks.empty()) {
    out +=
        "<p id=\"runtime-checks\">The app states no claim or assumption for this process to "
        "watch (it mediates no port that has one).</p>\n";
    return;
  }
  TimeFormat format = timeline_time_format(input.header.end);
  size_t broken = 0;
  std::string rows;
  for (const CheckRow& c : input.checks) {
    broken += c.broken ? 1 : 0;
    rows += "<tr" + std::string(c.broken ? " class=\"broken\"" : "") + "><td>" + escaped(c.claim) +
            "</td><td>" +
            (c.broken ? "broken at " + escaped(format.text(c.at)) : std::string("kept")) +
            "</td><td>" + escaped(c.what) + "</td></tr>\n";
  }
  out += "<p>" + counted(input.checks.size(), "claim or assumption", "claims and assumptions") +
         " of the proof watched on every decision made here, " + std::to_string(broken) +
         " broken.</p>\n<div class=\"wide\">\n<table id=\"runtime-checks\">\n<tr><th>claim "
         "or assumption</th><th>this run</th><th>what broke it</th></tr>\n" +
         rows + "</table>\n</div>\n";
}

void append_legend(std::string& out) {
  out += "<p class=\"legend\"><span class=\"item\">" + swatch(kDeliveryColor) + "delivered</span>";
  for (int r = 0; r < kDropReasonCount; ++r) {
    DropReason reason = static_cast<DropReason>(r);
    out += "<span class=\"item\">" + swatch(drop_reason_color(reason)) + drop_reason_name(reason) +
           "</span>";
  }
  out += "<span class=\"item\">" + swatch("#ff0000") + "moment of quarantine</span>";
  out += "<span class=\"item\">" + swatch(kBreachColor) +
         "a claim of the proof found broken (runtime checks)</span></p>\n";
}

void append_timelines(std::string& out, const RunReportInput& input) {
  // Rules first, then the generated feeds: the feeds' lanes are mostly `feed` drops.
  std::vector<std::string> names;
  for (const ConnectionRow& r : input.connections) {
    if (!r.feed) names.push_back(r.stats.name);
  }
  size_t first_feed = names.size();
  for (const ConnectionRow& r : input.connections) {
    if (r.feed) names.push_back(r.stats.name);
  }
  static const std::vector<TraceRecord> kNone;
  RunTimeline timeline =
      build_run_timeline(names, input.records ? *input.records : kNone, input.header.end);
  TimelineLayout layout;
  double bin = timeline.end / layout.bins;
  out += "<h2>Deliveries and drops per connection</h2>\n";
  out +=
      "<p class=\"note\">One lane per connection. Bars above a lane's midline count "
      "deliveries, bars below count drops, coloured by the most frequent reason; each bar is "
      "a " +
      span_text(bin) +
      " bin, its height relative to the lane's busiest bin (hover for the exact counts). "
      "Right: delivered / dropped.</p>\n";
  append_legend(out);
  out += connection_timeline_svg(timeline, first_feed, layout);
  out += "<h2>Event presence</h2>\n";
  if (timeline.events.empty()) {
    out += "<p>No event was set during the run.</p>\n";
  } else {
    out +=
        "<p class=\"note\">One lane per event in each arbitrated port's own container: a bar "
        "while the event is present (set and not yet expired or unset by every owner). "
        "Right: the share of the run it was present.</p>\n";
    out += event_timeline_svg(timeline, layout);
  }
}

void append_drops_by_reason(std::string& out, const RunReportInput& input) {
  struct ReasonSummary {
    uint64_t total = 0;
    std::vector<std::pair<std::string, uint64_t>> connections;
    std::map<std::string, uint64_t> details;
  };
  std::vector<ReasonSummary> reasons(kDropReasonCount);
  for (const ConnectionRow& row : input.connections) {
    for (int r = 0; r < kDropReasonCount; ++r) {
      uint64_t n = row.stats.dropped[r];
      if (n == 0) continue;
      reasons[r].total += n;
      reasons[r].connections.push_back({row.stats.name, n});
    }
  }
  if (input.records) {
    for (const TraceRecord& rec : *input.records) {
      if (rec.kind == TraceKind::Drop && !rec.text.empty()) {
        ++reasons[static_cast<int>(rec.reason)].details[rec.text];
      }
    }
  }
  out +=
      "<h2>Drops by reason</h2>\n<div class=\"wide\">\n<table "
      "id=\"drops\">\n<tr><th>reason</th><th>meaning</th>"
      "<th class=\"n\">dropped</th><th>connections</th><th>most frequent details</th></tr>\n";
  for (int r = 0; r < kDropReasonCount; ++r) {
    DropReason reason = static_cast<DropReason>(r);
    ReasonSummary& s = reasons[r];
    out += std::string("<tr data-reason=\"") + drop_reason_name(reason) + "\"><td>" +
           swatch(drop_reason_color(reason)) + drop_reason_name(reason) + "</td><td>" +
           reason_meaning(reason) + "</td>" + number_cell(s.total) + "<td>";
    std::sort(s.connections.begin(), s.connections.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    for (size_t i = 0; i < s.connections.size(); ++i) {
      out += (i ? ", " : "") + escaped(s.connections[i].first) + " " +
             std::to_string(s.connections[i].second);
    }
    out += "</td><td>";
    std::vector<std::pair<std::string, uint64_t>> details(s.details.begin(), s.details.end());
    std::stable_sort(details.begin(), details.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    for (size_t i = 0; i < details.size() && i < kDetailsPerReason; ++i) {
      out += (i ? "<br>" : "") + escaped(details[i].first) + " (" +
             std::to_string(details[i].second) + ")";
    }
    if (details.size() > kDetailsPerReason) {
      out += "<br>and " + std::to_string(details.size() - kDetailsPerReason) + " more";
    }
    out += "</td></tr>\n";
  }
  out += "</table>\n</div>\n";
}

void append_counters(std::string& out, const std::vector<ConnectionRow>& rows) {
  out +=
      "<h2>Counters per connection</h2>\n<p class=\"note\">For every connection: arrived = "
      "delivered + all drops + pending (still queued at the end). The names are those of "
      "<code>arbc run</code>'s table.</p>\n<div class=\"wide\">\n"
      "<table id=\"counters\">\n"
      "<tr><th>connection</th><th>source &#8594; destination</th><th>constraint</th>"
      "<th class=\"n\">arrived</th><th class=\"n\">delivered</th>";
  for (int r = 0; r < kDropReasonCount; ++r) {
    out += std::string("<th class=\"n\">") + drop_reason_name(static_cast<DropReason>(r)) + "</th>";
  }
  out += "<th class=\"n\">pending</th><th class=\"n\">errors</th><th>status</th></tr>\n";
  ConnectionStats total;
  for (const ConnectionRow& row : rows) {
    const ConnectionStats& s = row.stats;
    out += std::string("<tr") + (row.feed ? " class=\"feed\"" : "") + " data-connection=\"" +
           escaped(s.name) + "\"><td>" + escaped(s.name) + (row.feed ? " (feed)" : "") +
           "</td><td>" + escaped(s.source) + " &#8594; " + escaped(s.destination) +
           "</td><td><code>" + escaped(row.constraint) + "</code></td>" + number_cell(s.arrived) +
           number_cell(s.delivered);
    for (int r = 0; r < kDropReasonCount; ++r) {
      out += number_cell(s.dropped[r]);
      total.dropped[r] += s.dropped[r];
    }
    out += number_cell(s.pending) + number_cell(s.errors) + "<td>" +
           (s.quarantined ? "<span class=\"bad\">quarantined</span>" : "") + "</td></tr>\n";
    total.arrived += s.arrived;
    total.delivered += s.delivered;
    total.pending += s.pending;
    total.errors += s.errors;
  }
  out += "<tr class=\"total\" data-connection=\"\"><td>total</td><td></td><td></td>" +
         number_cell(total.arrived) + number_cell(total.delivered);
  for (int r = 0; r < kDropReasonCount; ++r) out += number_cell(total.dropped[r]);
  out +=
      number_cell(total.pending) + number_cell(total.errors) + "<td></td></tr>\n</table>\n</div>\n";
}

// Errors, quarantines, publish and plugin errors, then the log: the first kMaxListed of each,
// each at its time as the timelines write it.
void append_messages(std::string& out, const std::vector<TraceRecord>& records, double end) {
  TimeFormat format = timeline_time_format(end);
  std::string problems, log;
  size_t problem_count = 0, log_count = 0;
  for (const TraceRecord& r : records) {
    std::string line;
    switch (r.kind) {
      case TraceKind::Error:
        line = "error on " + r.connection + ": " + r.text;
        break;
      case TraceKind::Quarantine:
        line = "quarantined " + r.connection + ": " + r.text;
        break;
      case TraceKind::Breach:
        line = "runtime check: " + r.connection + " " + r.text;
        break;
      case TraceKind::PublishError:
        line = "publish error on " + r.port + ": " + r.text;
        break;
      case TraceKind::PluginError:
        line = "plugin error in " + r.connection + " (" + r.callback + "): " + r.text;
        break;
      case TraceKind::Log:
        if (log_count++ < kMaxListed) {
          log += format.text(seconds_of(r.t)) + "  " + escaped(r.connection) + ": " +
                 escaped(r.text) + "\n";
        }
        continue;
      default:
        continue;
    }
    if (problem_count++ < kMaxListed)
      problems += format.text(seconds_of(r.t)) + "  " + escaped(line) + "\n";
  }
  auto more = [](size_t count) {
    return count > kMaxListed ? "… and " + std::to_string(count - kMaxListed) + " more\n"
                              : std::string();
  };
  out += "<h2>Errors and quarantines</h2>\n";
  out += problem_count ? "<pre id=\"problems\">" + problems + more(problem_count) + "</pre>\n"
                       : "<p id=\"problems\">None.</p>\n";
  out += "<h2>Log</h2>\n";
  out += log_count ? "<pre id=\"log\">" + log + more(log_count) + "</pre>\n"
                   : "<p id=\"log\">Nothing was logged.</p>\n";
}

}  // namespace

std::string render_run_report(const RunReportInput& input) {
  std::string out;
  out +=
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>";
  out += "arbc run report: " + escaped(input.header.app) + ", scenario " +
         escaped(input.header.scenario) + ", seed " + std::to_string(input.header.seed);
  out += "</title>\n<style>";
  out += kReportStyle;
  out += "</style>\n</head>\n<body>\n";
  append_header(out, input.header);
  append_transport(out, input.transport);
  append_totals(out, input.connections);
  append_timelines(out, input);
  append_checks(out, input);
  append_drops_by_reason(out, input);
  append_counters(out, input.connections);
  static const std::vector<TraceRecord> kNone;
  append_messages(out, input.records ? *input.records : kNone, input.header.end);
  out +=
      "<p class=\"note\">Written by <code>arbc run --report</code>; self-contained: no "
      "network access, no external files.</p>\n<script>";
  out += kReportScript;
  out += "</script>\n</body>\n</html>\n";
  return out;
}

}  // namespace arbc::report
