#include "app/gui/runs/run_session_model.h"

#include <algorithm>

#include "workspace/workspace.h"

namespace tactile::gui {

RunSession::RunSession(QObject* parent) : QObject(parent) {}
RunSession::~RunSession() = default;

void RunSession::setWorkspace(workspace::Workspace* workspace) {
  if (workspace_ == workspace) return;
  close();
  workspace_ = workspace;
}

Status RunSession::open(const std::string& runName) {
  if (workspace_ == nullptr) return Error("no database is open");
  storage::RunStore runs = workspace_->runStore();
  auto info = runs.find(runName);
  if (!info) return info.error();
  auto track = runs.loadTrack(info->id);
  if (!track) return track.error();
  // The metadata (start, goal) comes with an empty window.
  auto head = runs.loadWindow(info->id, 0, 0);
  if (!head) return head.error();
  std::optional<sim::Scene> scene;
  auto sceneText = runs.sceneJson(info->id);
  if (!sceneText) return sceneText.error();
  if (sceneText.value()) {
    auto parsed = sim::parseSceneJson(*sceneText.value(), info->scene);
    // A stored scene that no longer parses is shown as no scene rather than refusing the run.
    if (parsed) scene = std::move(parsed.value());
  }

  info_ = std::move(info.value());
  track_ = std::move(track.value());
  scene_ = std::move(scene);
  start_ = head->data.start();
  goal_ = head->data.goal();
  if (!start_ && scene_) start_ = scene_->start;
  if (!goal_ && scene_) goal_ = std::make_pair(scene_->goal.x(), scene_->goal.y());
  open_ = true;
  step_ = 0;
  selection_.reset();
  loadSensors();
  emit runOpened();
  emit currentStepChanged(step_);
  emit selectionChanged();
  return Status::success();
}

void RunSession::close() {
  if (!open_) return;
  open_ = false;
  info_ = {};
  track_ = {};
  scene_.reset();
  start_.reset();
  goal_.reset();
  step_ = 0;
  sensors_.fill(0.0);
  selection_.reset();
  emit runOpened();
}

void RunSession::setCurrentStep(std::int64_t step) {
  if (!open_) return;
  step = std::clamp<std::int64_t>(step, 0, std::max<std::int64_t>(0, stepCount() - 1));
  if (step == step_) return;
  step_ = step;
  loadSensors();
  emit currentStepChanged(step_);
}

void RunSession::loadSensors() {
  sensors_.fill(0.0);
  if (!open_ || workspace_ == nullptr || stepCount() == 0) return;
  // One indexed row: a few microseconds, so nothing is cached.
  auto window = workspace_->runStore().loadWindow(info_.id, step_, 1);
  if (!window) {
    emit errorOccurred(QString::fromStdString(window.errorText()));
    return;
  }
  if (window->data.stepCount() == 1)
    std::copy_n(window->data.stepSensors(0), kValuesPerStep, sensors_.begin());
}

Result<storage::RunSummary> RunSession::summary(std::int64_t first, std::int64_t last,
                                                int buckets) {
  if (!open_ || workspace_ == nullptr) return Error("no run is open");
  return workspace_->runStore().loadSummary(info_.id, first, last, buckets);
}

void RunSession::setSelectedGroup(SensorGroup group) {
  if (group == group_) return;
  group_ = group;
  emit selectedGroupChanged(group_);
}

void RunSession::setSelection(std::int64_t first, std::int64_t last) {
  if (!open_ || stepCount() == 0) return;
  if (first > last) std::swap(first, last);
  const std::int64_t end = stepCount() - 1;
  const StepRange range{std::clamp<std::int64_t>(first, 0, end),
                        std::clamp<std::int64_t>(last, 0, end)};
  if (selection_ && *selection_ == range) return;
  selection_ = range;
  emit selectionChanged();
}

void RunSession::clearSelection() {
  if (!selection_) return;
  selection_.reset();
  emit selectionChanged();
}

}  // namespace tactile::gui
