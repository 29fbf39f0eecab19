// The naive exclusivity proof, kept only as the benchmarks' baseline: one solver query per pair
// of rules (push, assert E_i and E_j, check, pop), n(n-1)/2 queries per port. verify_app asks
// one at-least-two question per port instead and enumerates pairs only to explain a refutation.
#pragma once

#include "core/app_model.h"

namespace arbc::verify {

struct PairwiseResult {
  bool ok = false;  // false: the model is malformed for verification
  long long overlapping_pairs = 0;
  long long queries = 0;
};

PairwiseResult pairwise_baseline(const model::App& app);

}  // namespace arbc::verify
