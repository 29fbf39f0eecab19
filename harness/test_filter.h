// `arbc test --filter GLOB`: which tests run, and what to say when none does. The glob must match
// the whole name, so `--filter joystick` matches no test named "joystick wins"; a filter that
// matches nothing is a mistake that would otherwise pass a CI job with no test run.
#pragma once

#include <string>
#include <vector>

namespace arbc::harness {

// Whether the test `name` is chosen by `glob` (fnmatch over the whole name).
bool filter_matches(const std::string& glob, const std::string& name);

// The error for a glob that chose none of `names` (the tests the specs declare): the names, and
// "*GLOB*" when that would have matched (the glob was meant as a part of a name).
std::string filter_matched_none(const std::string& glob, const std::vector<std::string>& names);

}  // namespace arbc::harness
