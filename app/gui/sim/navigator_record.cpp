#include "app/gui/sim/navigator_record.h"

#include "nav/navigate.h"
#include "nav/navigator.h"
#include "run/sensor_layout.h"

namespace tactile::gui {

std::vector<std::string> navigatorColumns() {
  std::vector<std::string> names;
  names.reserve(2 + kGroupCount);
  names.emplace_back(nav::kStrategyColumn);
  names.emplace_back(nav::kIntegratedStatusColumn);
  for (const GroupInfo& info : kSensorGroups)
    names.push_back(nav::groupStatusColumn(info.group));
  return names;
}

void appendNavigatorState(const nav::Navigator& navigator, std::vector<std::string>& values) {
  values.emplace_back(nav::strategyKey(navigator.strategy()));
  values.push_back(nav::statusText(navigator.integratedStatus()));
  for (const nav::ContactStatus& s : navigator.groupStatus())
    values.push_back(nav::statusText(s));
}

}  // namespace tactile::gui
