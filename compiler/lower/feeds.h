// Event feeds (docs/design.md#feeds): for each event source port whose events an arbitrated
// port reads, one generated connection into that port that sets and unsets exactly those
// events and never delivers. In the paper's table-cleaning app these are C3, C5, C6, C7, C11,
// C12 and C13, plus the FaceDetector feed into Speak.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "compiler/frontend/ast.h"
#include "compiler/lower/lowered_app.h"

namespace arbc::lower {

// One feed to generate: its source, what it sets and unsets, and its monitor plan (status
// flags and derived events, in declaration order).
struct FeedGroup {
  std::string source;  // "Module.port"
  std::vector<std::string> sets, unsets;
  model::SourceLocation loc;  // the declaration of its first event
  MonitorPlan plan;
};

// The feeds one arbitrated port needs for the events in `read`, ordered by the declaration of
// each source's first event. Events set by monitor code need no feed.
std::vector<FeedGroup> plan_feeds(const ast::Spec& spec, const std::set<std::string>& read);

}  // namespace arbc::lower
