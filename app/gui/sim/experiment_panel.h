// The experiment panel of the simulator window's autonomous mode (thesis 5.3.1): the navigator's
// strategies with the current one marked, and the status of every sensor group and the
// integrated status, live, read from the navigator after every step.
#pragma once

#include <QWidget>

#include <array>

#include "nav/navigator.h"
#include "run/sensor_layout.h"

class QLabel;
class QListWidget;

namespace tactile::gui {

class SimSession;

class ExperimentPanel : public QWidget {
  Q_OBJECT

 public:
  explicit ExperimentPanel(SimSession* session, QWidget* parent = nullptr);

  // The row of the marked strategy (-1 when none) and a status label's text (0 integrated, then
  // F, FLC, L, RLC, B, RRC, R, FRC), for tests.
  int markedStrategyRow() const;
  QString statusText(int index) const;

  // What the panel shows for a strategy and a status, translated ("Follow Wall", "Wall",
  // "Hole, 110 wide", ...).
  static QString strategyTitle(nav::Strategy strategy);
  static QString statusTitle(const nav::ContactStatus& status);

 private:
  void refresh();
  const nav::Navigator* navigator() const;

  SimSession* session_;
  QListWidget* strategies_;
  std::array<QLabel*, 1 + kGroupCount> status_{};
};

}  // namespace tactile::gui
