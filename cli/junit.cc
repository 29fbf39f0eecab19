#include "cli/junit.h"

#include <cstdio>

namespace arbc::cli {

namespace {

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        // XML 1.0 admits no other control characters than tab and line breaks.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') {
          out += '?';
        } else {
          out += c;
        }
    }
  }
  return out;
}

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", s);
  return text;
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
    out += "  <testsuite name=\"" + xml_escaped(suite.spec) + "\" tests=\"" +
           std::to_string(suite.tests.size()) + "\" failures=\"" + std::to_string(failures) +
           "\" errors=\"0\" time=\"" + seconds(total) + "\">\n";
    for (const TestOutcome& t : suite.tests) {
      out += "    <testcase name=\"" + xml_escaped(t.name) + "\" classname=\"" +
             xml_escaped(suite.app) + "\" time=\"" + seconds(t.seconds) + "\"";
      if (t.passed) {
        out += "/>\n";
        continue;
      }
      std::string first = t.detail.substr(0, t.detail.find('\n'));
      out += ">\n      <failure message=\"" + xml_escaped(first) + "\">" + xml_escaped(t.detail) +
             "</failure>\n    </testcase>\n";
    }
    out += "  </testsuite>\n";
  }
  return out + "</testsuites>\n";
}

}  // namespace arbc::cli
