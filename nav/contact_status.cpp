#include "nav/contact_status.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/features.h"
#include "analysis/temporal.h"

namespace tactile::nav {

bool groupTouches(const std::array<double, kValuesPerStep>& values, SensorGroup group) {
  const GroupInfo& info = groupInfo(group);
  for (int i = 0; i < 2 * info.sensorCount; ++i)
    if (values[static_cast<std::size_t>(normalOffset(info.firstSensor) + i)] != 0.0) return true;
  return false;
}

ModelStatusEstimator::ModelStatusEstimator(std::shared_ptr<const analysis::ModelBundle> models)
    : models_(std::move(models)), decider_(*models_) {}

const GroupClasses& ModelStatusEstimator::update(const std::array<double, kValuesPerStep>& values,
                                                 const std::array<ContactClass, kGroupCount>*) {
  decider_.update(values.data(), v_, omega_);
  for (const GroupInfo& info : kSensorGroups) {
    const auto g = static_cast<std::size_t>(groupIndex(info.group));
    const std::optional<ContactClass> c = decider_.decided(info.group);
    if (c) {
      out_[g] = *c;
    } else {
      out_[g] = groupTouches(values, info.group) ? ContactClass::Wall : ContactClass::NoContact;
    }
  }
  return out_;
}

const GroupClasses& TruthStatusEstimator::update(
    const std::array<double, kValuesPerStep>&, const std::array<ContactClass, kGroupCount>* truth) {
  for (std::size_t g = 0; g < kGroupCount; ++g)
    out_[g] = truth ? (*truth)[g] : ContactClass::NoContact;
  return out_;
}

const GroupClasses& BumperStatusEstimator::update(const std::array<double, kValuesPerStep>& values,
                                                  const std::array<ContactClass, kGroupCount>*) {
  for (const GroupInfo& info : kSensorGroups) {
    out_[static_cast<std::size_t>(groupIndex(info.group))] =
        groupTouches(values, info.group) ? ContactClass::Wall : ContactClass::NoContact;
  }
  return out_;
}

}  // namespace tactile::nav
