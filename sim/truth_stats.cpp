#include "sim/truth_stats.h"

namespace tactile::sim {

void TruthStats::add(const RunData& run) {
  const std::size_t n = run.stepCount();
  steps += static_cast<std::int64_t>(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!run.blocked[k]) continue;
    ++blockedSteps;
    const double* v = run.stepSensors(k);
    bool any = false;
    for (int i = 0; i < kValuesPerStep && !any; ++i)
      any = v[i] != 0.0;
    if (!any) ++blockedWithoutReadings;
  }
  if (!run.hasTruth()) return;
  for (const GroupInfo& info : kSensorGroups) {
    const auto g = static_cast<std::size_t>(groupIndex(info.group));
    ContactClass previous = ContactClass::NoContact;
    for (std::size_t k = 0; k < n; ++k) {
      const ContactClass c = run.truthAt(k, info.group);
      ++classSteps[g][static_cast<std::size_t>(c)];
      if (k > 0 && c != previous && c != ContactClass::NoContact &&
          previous != ContactClass::NoContact) {
        ++contactChanges[g];
      }
      previous = c;
    }
  }
}

void TruthStats::merge(const TruthStats& other) {
  for (std::size_t g = 0; g < classSteps.size(); ++g) {
    for (std::size_t c = 0; c < classSteps[g].size(); ++c)
      classSteps[g][c] += other.classSteps[g][c];
    contactChanges[g] += other.contactChanges[g];
  }
  steps += other.steps;
  blockedSteps += other.blockedSteps;
  blockedWithoutReadings += other.blockedWithoutReadings;
}

std::int64_t TruthStats::contactSteps(SensorGroup g) const {
  const auto& row = classSteps[static_cast<std::size_t>(groupIndex(g))];
  std::int64_t sum = 0;
  for (std::size_t c = 1; c < row.size(); ++c)
    sum += row[c];
  return sum;
}

double TruthStats::changesPer100ContactSteps(SensorGroup g) const {
  const std::int64_t contact = contactSteps(g);
  if (contact == 0) return 0.0;
  return 100.0 * static_cast<double>(contactChanges[static_cast<std::size_t>(groupIndex(g))]) /
         static_cast<double>(contact);
}

double TruthStats::blockedWithoutReadingsShare() const {
  if (blockedSteps == 0) return 0.0;
  return static_cast<double>(blockedWithoutReadings) / static_cast<double>(blockedSteps);
}

}  // namespace tactile::sim
