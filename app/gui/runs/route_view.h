// The route view: the scene's obstacles and bounds, start and goal, the route (coloured by time or
// by the selected group's labels), and the robot at the current step with its 44 domes (contacting
// domes filled blue to red by value), its heading arrow, an arrow to the goal and the distance,
// and with a model's predictions the holes found along the route with their widths.
// Click a route point to move the cursor to the nearest step; the wheel zooms and a drag pans; M
// switches between the robot close-up and the whole scene.
//
// The route is decimated to the pixels it covers before drawing, and a hidden view does no work.
#pragma once

#include <QWidget>

#include <cstdint>
#include <optional>

class QSettings;

namespace tactile::gui {

class RunSession;
class LabelModel;
class PredictionModel;

class RouteView : public QWidget {
  Q_OBJECT

 public:
  enum class ColourMode { Time, Label };

  RouteView(RunSession* session, LabelModel* labels, QWidget* parent = nullptr);
  ~RouteView() override;

  ColourMode colourMode() const;
  void setColourMode(ColourMode mode);
  // Whole scene (true) or the close-up following the robot (false).
  bool wholeScene() const;
  // The badge at the top: the mode, or the zoom once zoomed or panned.
  QString badgeText() const;
  void setWholeScene(bool whole);

  void saveSettings(QSettings& settings) const;
  void restoreSettings(const QSettings& settings);

  // Where a step's route point is drawn, in widget coordinates (for tests and benchmarks).
  QPointF stepToWidget(std::int64_t step) const;
  // The step whose route point is nearest to a widget position, if any lies within `radius`
  // pixels.
  std::optional<std::int64_t> stepAt(QPointF widgetPos, double radius = 8.0) const;
  // How many points the decimated route holds at the current scale (for tests and benchmarks).
  int drawnRoutePoints() const;

  // Marks the holes a model's run scan found (thesis 4.5), with their widths (null: none).
  void setPredictions(const PredictionModel* predictions);
  // Holes drawn across the robot at a step (for tests).
  int holeMarksAt(std::int64_t step) const;

 signals:
  void viewSettingsChanged();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  struct Impl;
  Impl* d_;
};

}  // namespace tactile::gui
