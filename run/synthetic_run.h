// Synthetic runs with realistic value statistics, for tests and benchmarks of run-file handling.
#pragma once

#include <cstddef>
#include <cstdint>

#include "run/run.h"

namespace tactile {

// `steps` steps; about 30% of domes touching per step with full-precision normal and shear values,
// the rest zero; pose and command values with full precision; truth cycling through the classes
// when `withTruth`. The same seed gives the same run.
RunData makeSyntheticRun(std::size_t steps, bool withTruth, std::uint64_t seed = 1);

}  // namespace tactile
