#include "report/svg_timeline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "report/html_text.h"

namespace arbc::report {

const char* drop_reason_color(DropReason reason) { return drop_reason_info(reason).color; }

namespace {

constexpr double kAxisHeight = 26;  // tick labels above the first lane
constexpr double kLaneHeight = 30;  // a connection lane: deliveries up, drops down
constexpr double kEventLaneHeight = 16;
constexpr double kHeadingHeight = 22;  // "event feeds", a port's name

// Maps times to x positions in the plot, and writes them as precisely as a pixel tells apart.
class TimeScale {
 public:
  TimeScale(const TimelineLayout& layout, double end)
      : x0_(layout.label_width),
        width_(layout.plot_width()),
        end_(end > 0 ? end : 1),
        format_(timeline_time_format(end, layout)) {}
  double x(double t) const { return x0_ + width_ * std::clamp(t / end_, 0.0, 1.0); }
  double end() const { return end_; }
  double seconds_per_pixel() const { return end_ / width_; }
  const TimeFormat& format() const { return format_; }

 private:
  double x0_, width_, end_;
  TimeFormat format_;
};

// 1, 2 or 5 times a power of ten, so that about 10 ticks cover the run.
double tick_step(double end) {
  double raw = end / 10;
  double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * power >= raw) return m * power;
  }
  return 10 * power;
}

// In the run's unit, with as many decimals as the step needs: "10 s", "0.5 s", "2 ms".
std::string tick_label(double t, double step, const TimeFormat& format) {
  double unit_step = step * format.per_second();
  int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(unit_step) + 1e-9)), 0, 9);
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f %s", decimals, t * format.per_second(), format.unit());
  return buffer;
}

void open_svg(std::string& out, const char* id, const TimelineLayout& layout, double height,
              const TimeScale& scale, const char* description) {
  out += "<svg class=\"timeline\" id=\"";
  out += id;
  out += "\" width=\"" + coordinate(layout.width) + "\" height=\"" + coordinate(height) +
         "\" viewBox=\"0 0 " + coordinate(layout.width) + " " + coordinate(height) +
         "\" data-x0=\"" + coordinate(layout.label_width) + "\" data-x1=\"" +
         coordinate(layout.label_width + layout.plot_width()) + "\" data-end=\"" +
         std::to_string(scale.end()) + "\" data-unit=\"" + scale.format().unit() +
         "\" data-per-second=\"" + std::to_string(scale.format().per_second()) +
         "\" data-decimals=\"" + std::to_string(scale.format().decimals()) +
         "\" role=\"img\">\n<desc>";
  append_html_escaped(out, description);
  out += "</desc>\n";
}

// Tick labels above y_top and grid lines from y_top to y_bottom.
void append_axis(std::string& out, const TimeScale& scale, double y_top, double y_bottom) {
  double step = tick_step(scale.end());
  out += "<g class=\"axis\">\n";
  for (int k = 0;; ++k) {
    double t = k * step;
    if (t > scale.end() * (1 + 1e-9)) break;
    std::string x = coordinate(scale.x(t));
    out += "<line x1=\"" + x + "\" y1=\"" + coordinate(y_top) + "\" x2=\"" + x + "\" y2=\"" +
           coordinate(y_bottom) + "\"/>";
    out += "<text x=\"" + x + "\" y=\"" + coordinate(y_top - 8) + "\">" +
           tick_label(t, step, scale.format()) + "</text>\n";
  }
  // The end of the run, where it is not on a tick.
  std::string x = coordinate(scale.x(scale.end()));
  out += "<line class=\"end\" x1=\"" + x + "\" y1=\"" + coordinate(y_top) + "\" x2=\"" + x +
         "\" y2=\"" + coordinate(y_bottom) +
         "\"><title>end of run: " + scale.format().text(scale.end()) + "</title></line>\n</g>\n";
}

void append_rect(std::string& out, double x, double y, double w, double h, const char* fill,
                 const std::string& title) {
  out += "<rect x=\"" + coordinate(x) + "\" y=\"" + coordinate(y) + "\" width=\"" + coordinate(w) +
         "\" height=\"" + coordinate(h) + "\" fill=\"" + fill + "\"><title>";
  append_html_escaped(out, title);
  out += "</title></rect>\n";
}

void append_label(std::string& out, double x, double y, const char* css_class,
                  const std::string& text, const std::string& title = {}) {
  out += "<text class=\"";
  out += css_class;
  out += "\" x=\"" + coordinate(x) + "\" y=\"" + coordinate(y) + "\">";
  append_html_escaped(out, text);
  if (!title.empty()) {
    out += "<title>";
    append_html_escaped(out, title);
    out += "</title>";
  }
  out += "</text>\n";
}

// The end of a long name (where connection names differ: "Port.in/feed_Source_port"), cut
// on a UTF-8 character boundary.
std::string fit_label(const std::string& name, size_t max_chars) {
  if (name.size() <= max_chars) return name;
  size_t start = name.size() - (max_chars - 1);
  while (start < name.size() && (static_cast<unsigned char>(name[start]) & 0xC0) == 0x80) ++start;
  return "\u2026" + name.substr(start);
}

size_t bin_of(double t, const TimeScale& scale, int bins) {
  double position = std::clamp(t / scale.end(), 0.0, 1.0) * bins;
  return std::min(static_cast<size_t>(position), static_cast<size_t>(bins - 1));
}

std::string bin_span(size_t bin, const TimeScale& scale, int bins) {
  double width = scale.end() / bins;
  return scale.format().span(bin * width, (bin + 1) * width);
}

using ReasonCounts = std::array<uint64_t, kDropReasonCount>;

void append_connection_lane(std::string& out, const ConnectionLane& lane, double y0,
                            const TimeScale& scale, const TimelineLayout& layout) {
  const int bins = layout.bins;
  const double bin_width = layout.plot_width() / bins;
  const double half = kLaneHeight / 2 - 3;  // tallest bar on either side of the midline
  const double mid = y0 + kLaneHeight / 2;

  std::vector<uint64_t> delivered(bins, 0);
  for (double t : lane.deliveries) ++delivered[bin_of(t, scale, bins)];
  std::vector<ReasonCounts> dropped(bins, ReasonCounts{});
  std::vector<uint64_t> drop_total(bins, 0);
  for (const TimedDrop& d : lane.drops) {
    size_t b = bin_of(d.t, scale, bins);
    ++dropped[b][static_cast<int>(d.reason)];
    ++drop_total[b];
  }
  uint64_t most_delivered = *std::max_element(delivered.begin(), delivered.end());
  uint64_t most_dropped = *std::max_element(drop_total.begin(), drop_total.end());

  out += "<g class=\"lane\">\n";
  append_label(out, layout.label_width - 8, mid + 4, "name",
               fit_label(lane.name, layout.label_chars), lane.name);
  for (int b = 0; b < bins; ++b) {
    if (delivered[b] == 0) continue;
    double h = std::max(2.0, half * delivered[b] / most_delivered);
    append_rect(out, layout.label_width + b * bin_width, mid - h, bin_width, h, kDeliveryColor,
                lane.name + ": " + std::to_string(delivered[b]) +
                    (delivered[b] == 1 ? " delivery, " : " deliveries, ") +
                    bin_span(b, scale, bins));
  }
  for (int b = 0; b < bins; ++b) {
    if (drop_total[b] == 0) continue;
    const ReasonCounts& counts = dropped[b];
    int top = static_cast<int>(std::max_element(counts.begin(), counts.end()) - counts.begin());
    std::string title = lane.name + ": dropped, " + bin_span(b, scale, bins) + ":";
    for (int r = 0; r < kDropReasonCount; ++r) {
      if (counts[r] == 0) continue;
      title += " " + std::to_string(counts[r]) + " " + drop_reason_name(static_cast<DropReason>(r));
    }
    double h = std::max(2.0, half * drop_total[b] / most_dropped);
    append_rect(out, layout.label_width + b * bin_width, mid, bin_width, h,
                drop_reason_color(static_cast<DropReason>(top)), title);
  }
  if (lane.quarantined_at) {
    double x = scale.x(*lane.quarantined_at);
    append_rect(out, x - 1, y0 + 1, 3, kLaneHeight - 2, "#ff0000",
                lane.name + ": quarantined at " + scale.format().text(*lane.quarantined_at));
  }
  append_label(out, layout.label_width + layout.plot_width() + 8, mid + 4, "total",
               std::to_string(lane.deliveries.size()) + " / " + std::to_string(lane.drops.size()),
               "delivered / dropped");
  out += "</g>\n";
}

}  // namespace

TimeFormat timeline_time_format(double end, const TimelineLayout& layout) {
  if (!(end > 0)) end = 1;
  return TimeFormat(end, end / layout.plot_width());
}

std::string connection_timeline_svg(const RunTimeline& timeline, size_t first_feed,
                                    const TimelineLayout& layout) {
  TimeScale scale(layout, timeline.end);
  size_t lanes = timeline.connections.size();
  bool feeds = first_feed < lanes;
  double height = kAxisHeight + lanes * kLaneHeight + (feeds ? kHeadingHeight : 0) + 4;
  std::string out;
  open_svg(out, "deliveries", layout, height, scale,
           "Deliveries (above each lane's midline) and drops (below, coloured by reason) per "
           "connection over time");
  append_axis(out, scale, kAxisHeight, height - 4);
  double y = kAxisHeight;
  for (size_t i = 0; i < lanes; ++i) {
    if (i == first_feed) {
      append_label(out, 8, y + 15, "heading",
                   "event feeds (generated; they set events and never deliver)");
      y += kHeadingHeight;
    }
    if (i % 2 == 0) {
      out += "<rect class=\"stripe\" x=\"0\" y=\"" + coordinate(y) + "\" width=\"" +
             coordinate(layout.width) + "\" height=\"" + coordinate(kLaneHeight) + "\"/>\n";
    }
    append_connection_lane(out, timeline.connections[i], y, scale, layout);
    y += kLaneHeight;
  }
  // A broken claim marks every lane: from there the proof no longer covers the run.
  for (const Breach& b : timeline.breaches) {
    double x = scale.x(b.t);
    append_rect(out, x - 1, kAxisHeight, 3, y - kAxisHeight, kBreachColor,
                b.claim + " broken (seen at " + scale.format().text(b.t) + "): " + b.what);
  }
  out += "</svg>\n";
  return out;
}

std::string event_timeline_svg(const RunTimeline& timeline, const TimelineLayout& layout) {
  TimeScale scale(layout, timeline.end);
  size_t ports = 0;
  for (size_t i = 0; i < timeline.events.size(); ++i) {
    if (i == 0 || timeline.events[i].port != timeline.events[i - 1].port) ++ports;
  }
  double height =
      kAxisHeight + ports * kHeadingHeight + timeline.events.size() * kEventLaneHeight + 4;
  std::string out;
  open_svg(out, "events", layout, height, scale,
           "Event presence over time: one lane per event in each arbitrated port's container");
  append_axis(out, scale, kAxisHeight, height - 4);
  double y = kAxisHeight;
  double min_gap = scale.seconds_per_pixel() / 2;
  for (size_t i = 0; i < timeline.events.size(); ++i) {
    const EventLane& lane = timeline.events[i];
    if (i == 0 || lane.port != timeline.events[i - 1].port) {
      append_label(out, 8, y + 15, "heading", lane.port + " (event container)");
      y += kHeadingHeight;
    }
    if (i % 2 == 0) {
      out += "<rect class=\"stripe\" x=\"0\" y=\"" + coordinate(y) + "\" width=\"" +
             coordinate(layout.width) + "\" height=\"" + coordinate(kEventLaneHeight) + "\"/>\n";
    }
    double present = 0;
    for (const Interval& s : lane.present) present += s.end - s.begin;
    out += "<g class=\"lane\">\n";
    append_label(out, layout.label_width - 8, y + 12, "name",
                 fit_label(lane.event, layout.label_chars), lane.event + " in " + lane.port);
    // Spans separated by less than half a pixel are drawn as one bar.
    for (size_t k = 0; k < lane.present.size();) {
      Interval bar = lane.present[k];
      size_t spans = 1;
      while (k + spans < lane.present.size() && lane.present[k + spans].begin - bar.end < min_gap) {
        bar.end = lane.present[k + spans].end;
        ++spans;
      }
      k += spans;
      double x = scale.x(bar.begin);
      double w = std::max(1.0, scale.x(bar.end) - x);
      append_rect(out, x, y + 3, w, kEventLaneHeight - 6, kPresenceColor,
                  lane.event + " in " + lane.port + ": present " +
                      scale.format().span(bar.begin, bar.end) +
                      (spans > 1 ? " (" + std::to_string(spans) + " spans with brief gaps)" : ""));
    }
    char share[32];
    std::snprintf(share, sizeof share, "%.0f%%", 100 * present / scale.end());
    append_label(out, layout.label_width + layout.plot_width() + 8, y + 12, "total", share,
                 "share of the run the event was present");
    out += "</g>\n";
    y += kEventLaneHeight;
  }
  out += "</svg>\n";
  return out;
}

}  // namespace arbc::report
