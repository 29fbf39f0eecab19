#include "verify/temporal/report_text.h"

#include <cstdio>

#include "core/duration_literal.h"
#include "core/join.h"
#include "core/time_text.h"
#include "verify/temporal/assumption.h"
#include "verify/temporal/counterexample.h"
#include "verify/temporal/property.h"
#include "verify/temporal/rates.h"

namespace arbc::verify::temporal {
namespace {

// What "holds up to the bound" assumes, printed with every verdict.
constexpr const char* kAssumptions =
    "    assuming: sources publish at any times; monitors accept or reject any message (data is\n"
    "    not modelled); exclusive groups and invariants are not used\n";
constexpr const char* kAssumptionsLine =
    "assuming: sources publish at any times; monitors accept or reject any message (data is not "
    "modelled); exclusive groups and invariants are not used\n";

std::string wrap(const std::string& text, const std::string& by, size_t width = 96);

// A sentence of the report: wrapped and indented in the text report; one line as it is in a
// diagnostic's message (SARIF), whose viewer wraps it.
std::string paragraph(const std::string& text, bool plain) {
  return plain ? text + "\n" : wrap(text, "    ");
}

// The spec's environment assumptions the verdict is under, one line each (none: nothing), after
// what a verdict decided among the runs a replay makes takes for granted.
std::string environment_text(const TemporalResult& r, bool plain) {
  std::string out;
  if (r.faithful) {
    out += paragraph(
        "assuming, as the runtime hands them out, that each message of a source "
        "reaches all its rules and feeds into " +
            r.property.port +
            " together, at one instant (the free model's violation did not replay; "
            "a module that publishes while it takes a delivery could interleave "
            "other messages)",
        plain);
  }
  for (const model::Assumption& a : r.assumptions) {
    std::string where = a.loc.line ? " (line " + std::to_string(a.loc.line) + ")" : "";
    out += std::string(plain ? "" : "    ") +
           "assuming the environment as the spec states: " + model::assumption_text(a) + where +
           "\n";
  }
  return out;
}

// The assumptions line; the rates the verdict relies on replace "at any times" for their sources.
std::string assumptions(const TemporalResult& r, bool plain) {
  if (r.rates.empty()) return plain ? kAssumptionsLine : kAssumptions;
  std::string out = "assuming:";
  for (const model::SourceRate& rate : r.rates) out += " " + rate_words(rate) + ";";
  return paragraph(out +
                       " other sources publish at any times; monitors accept or reject any "
                       "message (data is not modelled; a rule with no `accept` accepts every "
                       "message); exclusive groups and invariants are not used",
                   plain);
}

std::string property_text(const model::TemporalProperty& p) {
  std::string where = p.loc.line ? " (" + p.loc.file + ":" + std::to_string(p.loc.line) + ")" : "";
  return property_words(p) + where;
}

// "    at 250ms    ObjectDetector.objects -> take: accepted, delivered; sets e_x"
std::string step_text(const TraceStep& s, bool plain) {
  char time[32];
  std::snprintf(time, sizeof time, "%-8s", (duration_literal(s.time)).c_str());
  std::string line =
      (plain ? "at " + duration_literal(s.time) + ":" : "    at " + std::string(time)) + " " +
      s.source + " -> " + s.connection + ": ";
  line += s.feed        ? "feed"
          : s.delivered ? "accepted, delivered"
          : s.accepted  ? "accepted, not delivered"
                        : "rejected";
  if (!s.set.empty()) line += "; sets " + join(s.set);
  if (!s.unset.empty()) line += "; unsets " + join(s.unset);
  return line + "\n";
}

std::string indent(const std::string& text, const std::string& by) {
  std::string out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start) out += by + text.substr(start, end - start);
    out += "\n";
    start = end + 1;
  }
  return out;
}

// `text` as lines of at most about `width` characters, each starting with `by`.
std::string wrap(const std::string& text, const std::string& by, size_t width) {
  std::string out, line;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(start, end - start);
    if (!line.empty() && by.size() + line.size() + 1 + word.size() > width) {
      out += by + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return line.empty() ? out : out + by + line + "\n";
}

}  // namespace

std::string outcome_counts(const size_t counts[kOutcomes]) {
  using O = TemporalResult::Outcome;
  const std::pair<O, const char*> order[] = {{O::Violated, " violated"},
                                             {O::Unknown, " unknown"},
                                             {O::Vacuous, " vacuous"},
                                             {O::HoldsToBound, " hold up to the bound"},
                                             {O::Proved, " proved"}};
  std::string out;
  for (const auto& [outcome, words] : order) {
    size_t n = counts[static_cast<int>(outcome)];
    if (!n) continue;
    std::string said = n == 1 && outcome == O::HoldsToBound ? " holds up to the bound" : words;
    out += (out.empty() ? "" : ", ") + std::to_string(n) + said;
  }
  return out;
}

std::string spec_name(const model::TemporalProperty& p) {
  const std::string& file = p.loc.file;
  size_t slash = file.find_last_of('/');
  return slash == std::string::npos ? file : file.substr(slash + 1);
}

namespace {

// Who reads the verdict: the text report (wrapped and indented), SARIF (one line per step and
// sentence; the tests file is the result's properties.test) or an editor (one line per step and
// sentence, with the tests file, which the editor has nowhere else to show).
enum class Reader { Report, Sarif, Editor };

std::string render(const TemporalResult& r, Reader reader) {
  const bool plain = reader != Reader::Report;
  const std::string port = r.property.port;
  std::string out =
      plain ? property_words(r.property) + ": " : "  " + property_text(r.property) + ": ";
  std::string messages = std::to_string(r.bound) + " message" + (r.bound == 1 ? "" : "s");
  switch (r.outcome) {
    case TemporalResult::Outcome::HoldsToBound:
      out += "holds up to " + messages + " into " + port + " (bounded; not proved)\n";
      // The rates force messages in, so the bound is also a limit on time: say which.
      if (r.window_bound > r.bound) {
        out += paragraph("with the rates given, no window closes within " + messages + " into " +
                             port + ", so this says nothing (temporal-bound, above)",
                         plain);
      } else if (r.rated_span > Nanos(0)) {
        out += paragraph("with the rates given, the runs searched (" + messages + " into " + port +
                             ") last at most " + duration_literal(r.rated_span) +
                             ": a violation that needs a longer run is not searched "
                             "(--temporal-bound N searches further)",
                         plain);
      }
      break;
    case TemporalResult::Outcome::Proved:
      out += "proved for runs of any length into " + port + ": " + r.proof +
             " (no violation up to " + messages + " either)\n";
      break;
    case TemporalResult::Outcome::Vacuous:
      out += "vacuous, not proved: " + r.proof + " [vacuous]\n";
      break;
    case TemporalResult::Outcome::Unknown:
      out += "unknown (" + r.unknown_reason + ") after " + messages + " into " + port + "\n";
      for (const TraceStep& s : r.trace) out += step_text(s, plain);
      break;
    case TemporalResult::Outcome::Violated:
      out += "violated: a shortest trace of " + messages + " into " + port + ":\n";
      for (const TraceStep& s : r.trace) out += step_text(s, plain);
      if (!r.explanation.empty()) out += paragraph(r.explanation, plain);
      if (reader == Reader::Sarif) {
        out +=
            "replayed on the runtime in simulated time, which shows the violation "
            "(the tests file is the result's properties.test; --counterexamples DIR writes "
            "it)\n";
        break;
      }
      if (reader == Reader::Editor) {
        out +=
            "replayed on the runtime in simulated time, which shows the violation; as a tests "
            "file (arbc verify --counterexamples DIR writes it):\n";
        out += test_file_text(*r.replay_test, r.property, spec_name(r.property));
        break;
      }
      out +=
          "    replayed on the runtime in simulated time, which shows the violation; as a tests\n"
          "    file (--counterexamples DIR writes it):\n";
      out += indent(test_file_text(*r.replay_test, r.property, spec_name(r.property)), "      ");
      break;
  }
  return out + assumptions(r, plain) + environment_text(r, plain);
}

}  // namespace

std::string temporal_text(const TemporalResult& r) { return render(r, Reader::Report); }

namespace {
std::string without_last_newlines(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}
}  // namespace

std::string temporal_message(const TemporalResult& r) {
  return without_last_newlines(render(r, Reader::Sarif));
}

std::string temporal_editor_message(const TemporalResult& r) {
  return without_last_newlines(render(r, Reader::Editor));
}

}  // namespace arbc::verify::temporal
