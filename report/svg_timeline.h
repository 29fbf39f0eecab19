// The run report's two timelines as inline SVG (no script needed to see them): deliveries and
// drops per connection, and event presence per port and event. Dense lanes are aggregated
// into time bins so the SVG stays small however long the run.
#pragma once

#include <cstddef>
#include <string>

#include "core/time_format.h"
#include "report/run_timeline.h"
#include "runtime/drop_reason.h"

namespace arbc::report {

// The colour of a drop reason, shared by the timeline marks and the report's tables.
const char* drop_reason_color(DropReason reason);
inline constexpr const char* kDeliveryColor = "#009e73";
inline constexpr const char* kPresenceColor = "#3a6fb0";
// A runtime check found a claim of the proof broken: a mark across every lane.
inline constexpr const char* kBreachColor = "#000000";

// Geometry shared by both timelines, so their time axes line up on the page.
struct TimelineLayout {
  double width = 1200;       // whole SVG, px
  double label_width = 300;  // lane names, left of the plot
  size_t label_chars = 42;   // longer names keep their end, after a "…" (full name on hover)
  double right_width = 110;  // per-lane totals, right of the plot
  int bins = 300;            // time bins across the plot (deliveries and drops)
  double plot_width() const { return width - label_width - right_width; }
};

// How the timelines write the instants of a run that ended at `end`: its unit, and the decimals
// a pixel of the plot tells apart. The rest of the page (the header, the log) writes times the
// same way.
TimeFormat timeline_time_format(double end, const TimelineLayout& layout = {});

// One lane per connection: delivery bars above the lane's midline, drop bars below it
// coloured by the bin's most frequent reason, a red rule where it was quarantined. Bar height
// is relative to the lane's busiest bin; every bar has a tooltip with the exact counts.
// Lanes from index `first_feed` on are headed "event feeds" (pass the lane count for none).
std::string connection_timeline_svg(const RunTimeline& timeline, size_t first_feed,
                                    const TimelineLayout& layout = {});

// One lane per (port, event), grouped under a heading per port: a bar while it is present.
// Absences shorter than half a pixel are not drawn (they could not be seen).
std::string event_timeline_svg(const RunTimeline& timeline, const TimelineLayout& layout = {});

}  // namespace arbc::report
