// The current signal of the sensor array per group (thesis 2.3, part 2, figure 2.5): one panel per
// group in the order F, FLC, L, RLC, B, RRC, R, FRC, a bar per dome: its normal value (0..5) up
// from the base line, blue to red, and its shear (-5..5) in a thin strip below.
#pragma once

#include <QWidget>

#include <array>

#include "run/sensor_layout.h"

namespace tactile::gui {

class SimSession;

class SignalBarsView : public QWidget {
  Q_OBJECT

 public:
  explicit SignalBarsView(SimSession* session, QWidget* parent = nullptr);
  QSize sizeHint() const override { return {520, 150}; }
  // The panel of a group in widget coordinates (tests).
  QRect groupRect(SensorGroup group) const;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  SimSession* session_;
};

}  // namespace tactile::gui
