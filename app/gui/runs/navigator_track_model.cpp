#include "app/gui/runs/navigator_track_model.h"

#include <algorithm>
#include <string>

#include "app/gui/runs/run_session_model.h"
#include "nav/navigate.h"
#include "workspace/workspace.h"

namespace tactile::gui {
namespace {

// Steps read per window (the sensor values come along; windows keep the memory bounded).
constexpr std::int64_t kWindowSteps = 20000;

}  // namespace

NavigatorTrackModel::NavigatorTrackModel(RunSession* session, QObject* parent)
    : QObject(parent), session_(session) {
  connect(session_, &RunSession::runOpened, this, &NavigatorTrackModel::reload);
}

std::optional<nav::Strategy> NavigatorTrackModel::strategyAt(std::int64_t step) const {
  if (step < 0 || step >= stepCount() || strategy_[static_cast<std::size_t>(step)] < 0)
    return std::nullopt;
  return static_cast<nav::Strategy>(strategy_[static_cast<std::size_t>(step)]);
}

std::optional<nav::ContactStatus> NavigatorTrackModel::integratedAt(std::int64_t step) const {
  if (step < 0 || step >= stepCount()) return std::nullopt;
  return integrated_[static_cast<std::size_t>(step)];
}

std::optional<nav::ContactStatus> NavigatorTrackModel::groupAt(std::int64_t step,
                                                               SensorGroup group) const {
  if (step < 0 || step >= stepCount()) return std::nullopt;
  return groups_[static_cast<std::size_t>(step) * kGroupCount +
                 static_cast<std::size_t>(groupIndex(group))];
}

void NavigatorTrackModel::reload() {
  strategy_.clear();
  integrated_.clear();
  groups_.clear();
  error_.clear();
  workspace::Workspace* ws = session_->workspace();
  if (!session_->isOpen() || ws == nullptr) {
    emit changed();
    return;
  }
  const std::string name = session_->info().name;
  const std::int64_t steps = session_->stepCount();
  // Which columns hold what: found by name in the first step's window.
  auto head = ws->loadWindow(name, 0, 1);
  if (!head) {
    error_ = QString::fromStdString(head.errorText());
    emit changed();
    return;
  }
  const std::vector<std::string>& columns = head->data.extraColumns;
  const auto find = [&](std::string_view c) -> int {
    const auto it = std::find(columns.begin(), columns.end(), c);
    return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
  };
  const int strategyColumn = find(nav::kStrategyColumn);
  if (strategyColumn < 0 || steps <= 0) {
    emit changed();
    return;
  }
  const int integratedColumn = find(nav::kIntegratedStatusColumn);
  std::array<int, kGroupCount> groupColumns{};
  for (const GroupInfo& info : kSensorGroups)
    groupColumns[static_cast<std::size_t>(groupIndex(info.group))] =
        find(nav::groupStatusColumn(info.group));
  const auto n = static_cast<std::size_t>(steps);
  strategy_.assign(n, -1);
  integrated_.assign(n, std::nullopt);
  groups_.assign(n * kGroupCount, std::nullopt);
  for (std::int64_t first = 0; first < steps; first += kWindowSteps) {
    auto w = ws->loadWindow(name, first, kWindowSteps);
    if (!w) {
      error_ = QString::fromStdString(w.errorText());
      break;
    }
    const RunData& d = w->data;
    const std::size_t width = d.extraColumns.size();
    for (std::size_t k = 0; k < d.stepCount(); ++k) {
      const auto step = static_cast<std::size_t>(w->firstStep) + k;
      if (step >= n) break;
      const std::string* row = d.extraValues.data() + k * width;
      if (auto s = nav::parseStrategyKey(row[strategyColumn]))
        strategy_[step] = static_cast<std::int8_t>(*s);
      if (integratedColumn >= 0) integrated_[step] = nav::parseStatusText(row[integratedColumn]);
      for (std::size_t g = 0; g < kGroupCount; ++g)
        if (groupColumns[g] >= 0)
          groups_[step * kGroupCount + g] = nav::parseStatusText(row[groupColumns[g]]);
    }
  }
  emit changed();
}

}  // namespace tactile::gui
