// The run report's inline style sheet and script: the only assets the page has, embedded so
// the file is self-contained (no network, no other file).
#pragma once

namespace arbc::report {

// The CSS for the page and its SVG timelines (system fonts only).
extern const char* const kReportStyle;
// Progressive enhancement only: a vertical cursor over each timeline with the time under the
// mouse. Everything else is static HTML and SVG. It adds one <line class="cursor"> per
// timeline when it runs; tests/report checks for them to know it ran to its end.
extern const char* const kReportScript;

}  // namespace arbc::report
