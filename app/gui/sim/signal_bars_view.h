// The current signal of the sensor array per group (thesis 2.3, part 2, figure 2.5): one panel per
// group in the order F, FLC, L, RLC, B, RRC, R, FRC, a bar per dome: its normal value (0..5) up
// from the base line on the sequential scale of the heatmap, and its shear (-5..5) in a thin strip
// below on the diverging scale; a legend of both scales under the panels.
#pragma once

#include <QWidget>

#include <array>

#include "run/sensor_layout.h"

class QPainter;

namespace tactile::gui {

class SimSession;

class SignalBarsView : public QWidget {
  Q_OBJECT

 public:
  explicit SignalBarsView(SimSession* session, QWidget* parent = nullptr);
  QSize sizeHint() const override { return {520, 170}; }
  // The panel of a group in widget coordinates (tests).
  QRect groupRect(SensorGroup group) const;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  int legendHeight() const;
  void drawLegend(QPainter& p) const;

  SimSession* session_;
};

}  // namespace tactile::gui
