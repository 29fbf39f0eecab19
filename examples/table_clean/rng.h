// The world's random generator type (one per run, seeded by the run's seed).
#pragma once

#include <random>

namespace arbc::table_clean {

using Rng = std::mt19937_64;

}  // namespace arbc::table_clean
