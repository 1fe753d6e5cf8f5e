// The navigator's state along an open run recorded by `tactile navigate` (or the simulator
// window's autonomous mode): per step the strategy, the integrated status and every group's
// status, read from the run's x_strategy, x_status and x_status_<group> columns. A run without
// those columns has no navigator track (hasTrack() false) and costs one one-step read.
#pragma once

#include <QObject>
#include <QString>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "nav/navigator.h"
#include "run/sensor_layout.h"

namespace tactile::gui {

class RunSession;

class NavigatorTrackModel : public QObject {
  Q_OBJECT

 public:
  explicit NavigatorTrackModel(RunSession* session, QObject* parent = nullptr);

  bool hasTrack() const { return !strategy_.empty(); }
  std::int64_t stepCount() const { return static_cast<std::int64_t>(strategy_.size()); }
  // nullopt where the cell was empty or unreadable, or outside the run.
  std::optional<nav::Strategy> strategyAt(std::int64_t step) const;
  std::optional<nav::ContactStatus> integratedAt(std::int64_t step) const;
  std::optional<nav::ContactStatus> groupAt(std::int64_t step, SensorGroup group) const;
  // Why the open run's columns could not be read (empty when they could, or were absent).
  const QString& error() const { return error_; }

  // Reads the open run's columns again (done on every run the session opens).
  void reload();

 signals:
  void changed();

 private:
  RunSession* session_;
  std::vector<std::int8_t> strategy_;  // -1: unknown
  std::vector<std::optional<nav::ContactStatus>> integrated_;
  std::vector<std::optional<nav::ContactStatus>> groups_;  // steps * kGroupCount
  QString error_;
};

}  // namespace tactile::gui
