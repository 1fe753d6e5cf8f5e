#include "run/synthetic_run.h"

#include <array>
#include <random>

namespace tactile {

RunData makeSyntheticRun(std::size_t steps, bool withTruth, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RunData run;
  run.metadata = {{"format", std::string(kRunFormat)},
                  {"scene", "practice"},
                  {"dt", "0.1"},
                  {"start", "100,200,0.5"},
                  {"goal", "900,400"},
                  {"outcome", "success"}};
  run.reserve(steps, withTruth);
  std::array<double, kValuesPerStep> values{};
  std::array<ContactClass, kGroupCount> truth{};
  for (std::size_t i = 0; i < steps; ++i) {
    for (int s = 0; s < kSensorCount; ++s) {
      const bool touching = unit(rng) < 0.3;
      values[normalOffset(s)] = touching ? kMaxNormal * unit(rng) : 0.0;
      values[shearOffset(s)] = touching ? kMaxShear * (2.0 * unit(rng) - 1.0) : 0.0;
    }
    for (int g = 0; g < kGroupCount; ++g) {
      truth[g] = static_cast<ContactClass>((i / 7 + g) % kContactClassCount);
    }
    run.appendStep(1000 * unit(rng), -1e-7 * unit(rng), 6.283 * unit(rng) - 3.14, 20 * unit(rng),
                   unit(rng) - 0.5, (i % 17) == 3, values.data(),
                   withTruth ? truth.data() : nullptr);
  }
  return run;
}

}  // namespace tactile
