// Synthetic labelled runs for the learning-pipeline tests (features, sweeps, model files).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>

#include "run/contact_class.h"
#include "run/run.h"
#include "run/sensor_layout.h"

namespace tactile::testdata {

// One step's sensor values with every dome at rest.
inline std::array<double, kValuesPerStep> zeroStep() {
  std::array<double, kValuesPerStep> v{};
  return v;
}

// A run of `steps` steps in which every group cycles through episodes of NoContact (all zero),
// Wall (all sensors of the group pressed about 2 units), Corner (the last third of the group's
// sensors pressed about 3.5) and LeavingWall (the first half pressed about 1). Truth columns hold
// the episode's class. `contactFraction` is the share of contact episodes (the three contact
// classes equally likely among them). Values are clamped to the sensor ranges.
inline RunData makeLabelledRun(std::size_t steps, std::uint64_t seed, double noise = 0.15,
                               double contactFraction = 0.75) {
  RunData run;
  run.reserve(steps, true);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  std::uniform_int_distribution<int> episodeLength(5, 25);
  std::array<ContactClass, kGroupCount> current{};
  std::array<int, kGroupCount> left{};
  const std::array<ContactClass, 4> cycle{ContactClass::NoContact, ContactClass::Wall,
                                          ContactClass::Corner, ContactClass::LeavingWall};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> pick(1, 3);
  for (std::size_t t = 0; t < steps; ++t) {
    auto values = zeroStep();
    std::array<ContactClass, kGroupCount> truth{};
    for (const GroupInfo& info : kSensorGroups) {
      const auto g = static_cast<std::size_t>(groupIndex(info.group));
      if (left[g] == 0) {
        current[g] = unit(rng) < contactFraction ? cycle[static_cast<std::size_t>(pick(rng))]
                                                 : ContactClass::NoContact;
        left[g] = episodeLength(rng);
      }
      --left[g];
      truth[g] = current[g];
      const int n = info.sensorCount;
      for (int i = 0; i < n; ++i) {
        double level = 0.0;
        switch (current[g]) {
          case ContactClass::Wall:
            level = 2.0;
            break;
          case ContactClass::Corner:
            level = i >= n - std::max(1, n / 3) ? 3.5 : 0.0;
            break;
          case ContactClass::LeavingWall:
            level = i < std::max(1, n / 2) ? 1.0 : 0.0;
            break;
          default:
            break;
        }
        if (level == 0.0) continue;
        const int s = info.firstSensor + i;
        values[static_cast<std::size_t>(normalOffset(s))] =
            std::clamp(level + gauss(rng), 0.01, kMaxNormal);
        values[static_cast<std::size_t>(shearOffset(s))] =
            std::clamp(0.3 * level + gauss(rng), -kMaxShear, kMaxShear);
      }
    }
    run.appendStep(0.1 * static_cast<double>(t), 0.0, 0.0, 1.0, 0.0, false, values.data(),
                   truth.data());
  }
  return run;
}

}  // namespace tactile::testdata
