// The navigator's views of a run recorded by `tactile navigate`: strips under the timelines (the
// strategy, the integrated status and the status of F, L, R and B per step, on the timelines' step
// axis and cursor), and a panel like the thesis's experiment panel (5.3.1): the strategies with
// the current one marked, and at the cursor the status of every side and corner and the
// integrated status.
#pragma once

#include <QWidget>

#include <array>
#include <cstdint>

#include "run/sensor_layout.h"

class QLabel;
class QListWidget;

namespace tactile::gui {

class NavigatorTrackModel;
class RunSession;
class TimelineView;

class NavigatorStripView : public QWidget {
  Q_OBJECT

 public:
  NavigatorStripView(RunSession* session, NavigatorTrackModel* track, TimelineView* timeline,
                     QWidget* parent = nullptr);

  static constexpr int kRows = 6;  // strategy, status, F, L, R, B
  // A row's rectangle (widget coordinates) and the step under an x (nullopt outside the steps).
  QRect rowRect(int row) const;
  std::int64_t stepAtX(int x) const;
  // What a row shows at a step, as text ("Follow Wall", "Hole(110)", ...).
  QString textAt(int row, std::int64_t step) const;
  QSize sizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  bool event(QEvent* event) override;

 private:
  // The x of a step's centre in this widget (through the timeline's axis).
  double xOf(double step) const;

  RunSession* session_;
  NavigatorTrackModel* track_;
  TimelineView* timeline_;
};

class NavigatorPanelView : public QWidget {
  Q_OBJECT

 public:
  NavigatorPanelView(RunSession* session, NavigatorTrackModel* track, QWidget* parent = nullptr);

  // For tests: the row of the marked strategy (-1 when none) and a status label's text.
  int markedStrategyRow() const;
  QString statusText(int index) const;  // 0 integrated, then F, FLC, L, RLC, B, RRC, R, FRC

 private:
  void refresh();

  RunSession* session_;
  NavigatorTrackModel* track_;
  QLabel* note_;
  QListWidget* strategies_;
  QLabel* mode_;
  std::array<QLabel*, 1 + kGroupCount> status_{};
};

}  // namespace tactile::gui
