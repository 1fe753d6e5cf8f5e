#include "app/gui/common/plot_style.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>

namespace tactile::gui {

QColor valueColor(double value, double maxValue) {
  // Blue, cyan, yellow, red: the thesis's blue-to-red scale with a readable middle.
  static constexpr std::array<std::array<int, 3>, 4> kStops{
      {{30, 60, 220}, {40, 200, 220}, {250, 210, 40}, {215, 30, 30}}};
  double t = maxValue > 0.0 && std::isfinite(value) ? value / maxValue : 0.0;
  t = std::clamp(t, 0.0, 1.0) * static_cast<double>(kStops.size() - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), kStops.size() - 2);
  const double f = t - static_cast<double>(i);
  auto mix = [&](int c) {
    return static_cast<int>(std::lround(kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c])));
  };
  return {mix(0), mix(1), mix(2)};
}

QColor classColor(ContactClass cls) {
  switch (cls) {
    case ContactClass::NoContact:
      return {215, 215, 215};
    case ContactClass::Wall:
      return {40, 110, 220};
    case ContactClass::Corner:
      return {230, 130, 20};
    case ContactClass::LeavingWall:
      return {40, 170, 80};
    case ContactClass::DeadPath:
      return {200, 40, 60};
  }
  return Qt::black;
}

QString className(ContactClass cls) {
  switch (cls) {
    case ContactClass::NoContact:
      return QCoreApplication::translate("ContactClass", "No contact");
    case ContactClass::Wall:
      return QCoreApplication::translate("ContactClass", "Wall");
    case ContactClass::Corner:
      return QCoreApplication::translate("ContactClass", "Corner");
    case ContactClass::LeavingWall:
      return QCoreApplication::translate("ContactClass", "Leaving wall");
    case ContactClass::DeadPath:
      return QCoreApplication::translate("ContactClass", "Dead path");
  }
  return {};
}

QColor headingColor(double theta) {
  return std::cos(theta) >= 0.0 ? QColor(40, 90, 220) : QColor(215, 40, 40);
}

}  // namespace tactile::gui
