// The status picture of the simulator window (thesis 2.3, part 1): the robot close-up with its 44
// domes (filled blue to red while in contact), the heading arrow (blue), an arrow to the goal
// (red) and the distance to it; or, where the mode allows, the whole scene with the route so far.
// The close-up shows the robot alone, north up, so a person drives by touch and heading only.
#pragma once

#include <QWidget>

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

  QSize sizeHint() const override { return {560, 560}; }

 signals:
  void viewChanged(bool wholeScene);

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  SimSession* session_;
  bool wholeScene_ = false;
};

}  // namespace tactile::gui
