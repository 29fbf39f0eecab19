// What a stand-in source publishes with `arbc run --stub` (docs/testing.md, `--stub`): a sample
// of its port's type, drawn so that the spec's feeds and conditions see both outcomes. A status
// port (`events from`) lists each flag its feeds read in half of the samples; a part of the
// message the spec compares with constants (core/compared_values.h) is drawn around them: half
// of the time at or just beside one of them (`c`, and `c` minus or plus a step), else uniformly
// over a range that reaches past all of them; a string compared with `==` is one of the strings
// it is compared with, or "sample". Parts no condition compares are drawn as before any was:
// floats in [0, 1), ints in 0..9, vec3 components in [-1, 1], one to three list elements.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/compared_values.h"
#include "core/value.h"

namespace arbc {

struct SamplePlan {
  std::vector<std::string> flags;  // the flags a status port's feeds read (`e = "flag"`: flag)
  model::ComparedParts compared;
};

// The plan for `port` ("Module.port", an out-port) of `app`.
SamplePlan sample_plan(const model::App& app, const std::string& port);

// A sample of type t drawn from rng by `plan`.
Value sample_value(const Type& t, std::mt19937_64& rng, const SamplePlan& plan);

// The most elements a sampled list has, whatever length a condition compares with.
inline constexpr int64_t kMaxSampleListLength = 32;

}  // namespace arbc
