// The status picture of the simulator window (thesis 2.3, part 1): the robot close-up with its 44
// domes (filled blue to red while in contact), the heading arrow (blue), an arrow to the goal
// (red) and the distance to it; or, where the mode allows, the whole scene with the route so far.
// The close-up shows the robot alone, north up, so a person drives by touch and heading only.
// In autonomous mode, a navigator that keeps a touch map (plan drive) has it drawn over either
// picture: the cells closed to its planner shaded, the touched cells dark, its plan dashed and
// where its odometry puts the robot. All of it is in the navigator's odometry frame, anchored at
// the start, so odometry drift shows as marks off the walls they were made on. T toggles it.
#pragma once

#include <QImage>
#include <QTransform>
#include <QWidget>

#include <cstdint>

namespace tactile::gui {

class SimSession;

class StatusPictureView : public QWidget {
  Q_OBJECT

 public:
  explicit StatusPictureView(SimSession* session, QWidget* parent = nullptr);

  bool wholeScene() const { return wholeScene_; }
  // Whole scene only when the session's mode allows it; returns whether it is now shown.
  bool setWholeScene(bool whole);
  // M: switches between the two pictures where allowed; returns whether it switched.
  bool toggle();

  // The navigator's touch map and plan (autonomous mode, plan drive); on by default.
  bool showTouchMap() const { return showTouchMap_; }
  void setShowTouchMap(bool show);
  // Whether the last paint drew a touch map (tests).
  bool touchMapDrawn() const { return touchMapDrawn_; }
  // World (or odometry) coordinates to widget pixels as of the last paint (tests).
  QTransform worldToWidget() const { return frame_; }
  // The colours the touch map is drawn in (closed cells are drawn translucent).
  static QColor touchedColour();
  static QColor closedColour();
  static QColor planColour();

  QSize sizeHint() const override { return {560, 560}; }

 signals:
  void viewChanged(bool wholeScene);

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  SimSession* session_;
  bool wholeScene_ = false;
  bool showTouchMap_ = true;
  bool touchMapDrawn_ = false;
  QTransform frame_;
  // The touch map as an image, one pixel a cell; remade when the map changes.
  QImage mapImage_;
  const void* mapOf_ = nullptr;
  std::uint64_t mapRevision_ = 0;
};

}  // namespace tactile::gui
