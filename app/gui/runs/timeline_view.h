// The timelines on one shared step axis, zoomed and panned together: sensor heatmap (44 rows x
// steps, values 0..5 blue to red, with a colour bar and the group bands F, FLC, L, RLC, B, RRC, R,
// FRC; normal, shear or magnitude), heading strip (coloured by quadrant), command strip (lanes L,
// R, F, B), blocked marks, and per group a label strip with the truth beside it where the run has
// truth and, with a model's predictions, the predicted class (pale when unsure) and a strip
// marking where it disagrees with the label. The current-step cursor and the selected range are
// drawn on an overlay layer.
//
// Mouse: a click seeks (a click on a heatmap cell also selects that sensor's group); a drag, or a
// Shift+click after a click, selects a step range; dragging a label segment's edge moves it; the
// wheel zooms about the pointer; a right or middle drag pans.
//
// Only the visible range is drawn, binned to pixel columns: the heatmap comes from the stored
// min/max summaries, never from every step, and a hidden view does no work.
#pragma once

#include <QRect>
#include <QWidget>

#include <cstdint>

#include "app/gui/runs/run_session_model.h"

class QCustomPlot;
class QSettings;

namespace tactile::gui {

class LabelModel;
class PredictionModel;

class TimelineView : public QWidget {
  Q_OBJECT

 public:
  enum class Channel { Normal, Shear, Magnitude };

  TimelineView(RunSession* session, LabelModel* labels, QWidget* parent = nullptr);
  ~TimelineView() override;

  Channel channel() const;
  void setChannel(Channel channel);

  StepRange visibleRange() const;
  // Shows [first, last] (clamped to the run); emits visibleRangeChanged.
  void setVisibleRange(StepRange range);
  void showWholeRun();

  void saveSettings(QSettings& settings) const;
  void restoreSettings(const QSettings& settings);

  // Geometry for tests and benchmarks, in this widget's coordinates: the x of a step's centre and
  // the rectangles of the heatmap, the heading strip and a group's label strip.
  double stepToX(std::int64_t step) const;
  QRect heatmapRect() const;
  QRect headingRect() const;
  QRect labelStripRect(SensorGroup group) const;
  // With predictions shown: a group's predicted-class strip and its disagreement strip (empty
  // rectangles otherwise).
  QRect predictionStripRect(SensorGroup group) const;
  QRect disagreementStripRect(SensorGroup group) const;
  QRect holesStripRect() const;
  bool showsPredictions() const;
  // The tooltip shown at a point (widget coordinates) of a model row (class and posterior) or of
  // the holes row (each hole's width); empty elsewhere.
  QString predictionTipAt(QPoint widgetPos) const;
  // The tooltip over the heatmap (sensor and value), the heading strip or the command strip.
  QString trackTipAt(QPoint widgetPos) const;

  // Height in pixels of each label, truth and model row (Preferences).
  void setRowHeight(int pixels);
  int rowHeight() const;

  // Draws a model's predictions under the label strips (null: none); follows its changes.
  void setPredictions(const PredictionModel* predictions);
  QCustomPlot* plot() const;

 signals:
  void visibleRangeChanged(tactile::gui::StepRange range);

 protected:
  void showEvent(QShowEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  struct Impl;
  Impl* d_;
};

}  // namespace tactile::gui
