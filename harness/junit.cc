#include "harness/junit.h"

#include <cstdio>

#include "core/artifact_path.h"
#include "core/xml_text.h"

namespace arbc::harness {

namespace {

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", s);
  return text;
}

// The failure's headline, for CI pages that show only the `message` attribute: the expectation
// and what happened instead (the first two lines of the detail, which are indented for the
// terminal), "f.spec:24:3: expected ... at 100ms; but nothing reached Base.vel at 100ms".
std::string headline(const std::string& detail) {
  std::string out;
  size_t at = 0;
  for (int line = 0; line < 2 && at < detail.size(); ++line) {
    size_t end = detail.find('\n', at);
    if (end == std::string::npos) end = detail.size();
    size_t text = detail.find_first_not_of(' ', at);
    if (text < end) {
      std::string part = detail.substr(text, end - text);
      if (line == 1 && part.rfind("but ", 0) != 0) break;  // a trace, not the account
      if (part.back() == ':') part.pop_back();  // "received other values at 0.1s:" a list
      out += (out.empty() ? "" : "; ") + part;
    }
    at = end + 1;
  }
  return out;
}

// The detail as the terminal shows it cites the spec as given ("/home/me/x.test.spec:9:3:");
// the report names it as artifacts do (core/artifact_path.h), for CI pages on other machines.
std::string with_artifact_paths(std::string detail, const std::string& spec) {
  std::string given = spec + ":", named = artifact_path(spec) + ":";
  if (given == named) return detail;
  for (size_t at = detail.find(given); at != std::string::npos;
       at = detail.find(given, at + named.size()))
    detail.replace(at, given.size(), named);
  return detail;
}

}  // namespace

std::string junit_xml(const std::vector<SuiteOutcome>& suites) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
  for (const SuiteOutcome& suite : suites) {
    size_t failures = 0;
    double total = 0;
    for (const TestOutcome& t : suite.tests) {
      failures += !t.passed;
      total += t.seconds;
    }
    out += "  <testsuite name=\"" + xml_escaped(artifact_path(suite.spec)) + "\" tests=\"" +
           std::to_string(suite.tests.size()) + "\" failures=\"" + std::to_string(failures) +
           "\" errors=\"0\" time=\"" + seconds(total) + "\">\n";
    for (const TestOutcome& t : suite.tests) {
      out += "    <testcase name=\"" + xml_escaped(t.name) + "\" classname=\"" +
             xml_escaped(suite.app) + "\" time=\"" + seconds(t.seconds) + "\"";
      if (t.passed) {
        out += "/>\n";
        continue;
      }
      std::string detail = with_artifact_paths(t.detail, suite.spec);
      out += ">\n      <failure message=\"" + xml_escaped(headline(detail)) + "\">" +
             xml_escaped(detail) + "</failure>\n    </testcase>\n";
    }
    out += "  </testsuite>\n";
  }
  return out + "</testsuites>\n";
}

}  // namespace arbc::harness
