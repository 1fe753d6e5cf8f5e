// The stepping controls: a step spin box, - and + buttons, a slider over the run, and play/pause
// at a chosen speed (steps per second). They move the session's one cursor; the keyboard stepping
// lives in the main window so it works whichever view has focus.
#pragma once

#include <QWidget>

#include <cstdint>

class QComboBox;
class QSlider;
class QSpinBox;
class QTimer;
class QToolButton;
class QLabel;

namespace tactile::gui {

class RunSession;

class StepControlsView : public QWidget {
  Q_OBJECT

 public:
  explicit StepControlsView(RunSession* session, QWidget* parent = nullptr);

  bool playing() const;
  int speed() const;  // steps per second
  void setSpeed(int stepsPerSecond);

 public slots:
  void setPlaying(bool play);
  void togglePlaying() { setPlaying(!playing()); }

 signals:
  void speedChanged(int stepsPerSecond);

 private:
  void syncToRun();
  void showStep(std::int64_t step);
  void advance();

  RunSession* session_;
  QToolButton* minus_;
  QSpinBox* spin_;
  QToolButton* plus_;
  QSlider* slider_;
  QToolButton* play_;
  QComboBox* speed_;
  QLabel* total_;
  QTimer* timer_;
  double carry_ = 0.0;  // fractional steps owed by the play timer
};

}  // namespace tactile::gui
