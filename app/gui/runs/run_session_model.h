// The open run as every view sees it: its catalogue entry, scene, track (pose, command, blocked,
// truth for every step), the one current-step cursor, the selected sensor group and the selected
// step range. Views read from it and write the cursor, group and selection back through it; it
// emits a signal for each change, so every view follows one cursor.
//
// Sensor values are never held for the whole run: the current step's values are read on demand,
// and timelines ask for min/max summaries of the range they show (RunDatabase::loadSummary), so a
// million-step run stays within a few tens of megabytes.
#pragma once

#include <QObject>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "base/error.h"
#include "run/run.h"
#include "run/sensor_layout.h"
#include "sim/scene.h"
#include "storage/run_database.h"

namespace tactile::workspace {
class Workspace;
}

namespace tactile::gui {

// An inclusive step range.
struct StepRange {
  std::int64_t first = 0;
  std::int64_t last = 0;
  std::int64_t size() const { return last - first + 1; }
  bool contains(std::int64_t step) const { return step >= first && step <= last; }
  bool operator==(const StepRange&) const = default;
};

class RunSession : public QObject {
  Q_OBJECT

 public:
  explicit RunSession(QObject* parent = nullptr);
  ~RunSession() override;

  // The workspace the runs come from (not owned; null closes the run).
  void setWorkspace(workspace::Workspace* workspace);
  workspace::Workspace* workspace() const { return workspace_; }

  // Opens a stored run: catalogue entry, scene (when stored), metadata and track; the cursor goes
  // to step 0, the selection is cleared. On failure the previous run stays open.
  Status open(const std::string& runName);
  void close();
  bool isOpen() const { return open_; }

  const storage::RunInfo& info() const { return info_; }
  const storage::RunTrack& track() const { return track_; }
  std::int64_t stepCount() const { return static_cast<std::int64_t>(track_.stepCount()); }
  // The scene the run was recorded in, when it was stored with the run.
  const std::optional<sim::Scene>& scene() const { return scene_; }
  std::optional<Pose2d> start() const { return start_; }
  std::optional<std::pair<double, double>> goal() const { return goal_; }

  // ---- the cursor ----
  std::int64_t currentStep() const { return step_; }
  // Clamped to the run; emits currentStepChanged when it moves.
  void setCurrentStep(std::int64_t step);
  // The 88 sensor values (n0, s0, ..., n43, s43) of the current step; zeros when no run is open.
  const std::array<double, kValuesPerStep>& currentSensors() const { return sensors_; }

  // ---- sensor summaries for plots ----
  // Min/max per bucket over [first, last] (clipped to the run), about `buckets` buckets.
  Result<storage::RunSummary> summary(std::int64_t first, std::int64_t last, int buckets);

  // ---- selection ----
  SensorGroup selectedGroup() const { return group_; }
  void setSelectedGroup(SensorGroup group);
  std::optional<StepRange> selection() const { return selection_; }
  // Clamped to the run and ordered; emits selectionChanged.
  void setSelection(std::int64_t first, std::int64_t last);
  void clearSelection();

 signals:
  void runOpened();  // also after close(): check isOpen()
  void currentStepChanged(std::int64_t step);
  void selectedGroupChanged(tactile::SensorGroup group);
  void selectionChanged();
  void errorOccurred(const QString& message);

 private:
  void loadSensors();

  workspace::Workspace* workspace_ = nullptr;
  bool open_ = false;
  storage::RunInfo info_;
  storage::RunTrack track_;
  std::optional<sim::Scene> scene_;
  std::optional<Pose2d> start_;
  std::optional<std::pair<double, double>> goal_;
  std::int64_t step_ = 0;
  std::array<double, kValuesPerStep> sensors_{};
  SensorGroup group_ = SensorGroup::Front;
  std::optional<StepRange> selection_;
};

}  // namespace tactile::gui
