#include "storage/synthetic_run.h"

#include <array>
#include <cmath>
#include <random>

namespace tactile::storage {

RunData makeSyntheticRun(std::size_t steps, std::uint64_t seed, double contactFraction) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RunData run;
  run.metadata = {
      {"format", "tactile-run 1"}, {"scene", "practice"}, {"subject", "synthetic"}, {"dt", "0.1"},
      {"start", "150,400,0"},      {"goal", "1050,400"},  {"outcome", "success"}};
  run.reserve(steps, true);
  std::array<int, kGroupCount> remaining{};  // steps left in each group's current contact
  std::array<ContactClass, kGroupCount> truth{};
  std::array<double, kValuesPerStep> values{};
  double x = 150.0;
  double y = 400.0;
  double theta = 0.0;
  for (std::size_t i = 0; i < steps; ++i) {
    for (int g = 0; g < kGroupCount; ++g) {
      if (remaining[g] > 0) {
        --remaining[g];
      } else if (unit(rng) < contactFraction / 60.0) {
        remaining[g] = 20 + static_cast<int>(unit(rng) * 180.0);
        truth[g] = static_cast<ContactClass>(1 + static_cast<int>(unit(rng) * 4.0) % 4);
      } else {
        truth[g] = ContactClass::NoContact;
      }
      const GroupInfo& info = kSensorGroups[g];
      for (int s = info.firstSensor; s < info.firstSensor + info.sensorCount; ++s) {
        const bool touching = remaining[g] > 0 && unit(rng) < 0.6;
        values[normalOffset(s)] = touching ? 5.0 * unit(rng) : 0.0;
        values[shearOffset(s)] = touching ? 10.0 * unit(rng) - 5.0 : 0.0;
      }
    }
    const double v = 20.0 * unit(rng);
    const double omega = unit(rng) - 0.5;
    theta = std::remainder(theta + 0.1 * omega, 2.0 * M_PI);
    x += 0.1 * v * std::cos(theta);
    y += 0.1 * v * std::sin(theta);
    run.appendStep(x, y, theta, v, omega, unit(rng) < 0.01, values.data(), truth.data());
  }
  return run;
}

}  // namespace tactile::storage
