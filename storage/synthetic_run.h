// Synthetic runs shaped like simulator output (mostly-zero sensors with contact episodes, full
// precision values, truth columns) for storage benchmarks and the `tactile bench storage` verb.
#pragma once

#include <cstddef>
#include <cstdint>

#include "run/run.h"

namespace tactile::storage {

// `steps` steps; about `contactFraction` of the groups are in contact at any time, each contact
// lasting tens to hundreds of steps. Deterministic for a given seed.
RunData makeSyntheticRun(std::size_t steps, std::uint64_t seed, double contactFraction = 0.15);

}  // namespace tactile::storage
