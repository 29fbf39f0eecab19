// When a DDS run says that connected topics still have no peer. The first report comes a few
// wall seconds in (DdsOptions::unmatched_after, 10 s); a peer that never comes is said again at
// growing intervals, so that a mediator left running for hours keeps saying so, now and then,
// without filling its log: for a first report at 10 s, at 30 s, 1 min, 2 min, 5 min, then
// every 5 min. The end-of-run summary names the topics that never had one.
#pragma once

#include <string>

namespace arbc::dds {

// The wall seconds after the start of the k-th report (k = 0: the first, at `first`).
double no_peer_report_at(int k, double first);

// A wall-clock span as the reports write it: "10 s", "1 min", "1.5 min".
std::string wall_span_text(double seconds);

}  // namespace arbc::dds
