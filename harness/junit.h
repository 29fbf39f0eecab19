// JUnit XML of an `arbc test` run, for CI (docs/testing.md#in-ci-and-pre-commit): one <testsuite>
// per spec, one <testcase> per test, a <failure> with the expectation and what happened.
#pragma once

#include <string>
#include <vector>

#include "harness/test_runner.h"

namespace arbc::harness {

struct SuiteOutcome {
  std::string spec;  // the spec file
  std::string app;   // the app's name: the test cases' classname
  std::vector<TestOutcome> tests;
};

std::string junit_xml(const std::vector<SuiteOutcome>& suites);

}  // namespace arbc::harness
