#include "app/gui/common/plot_style.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>

namespace tactile::gui {

namespace {

using Rgb = std::array<int, 3>;

// Linear interpolation between equally spaced stops, t in [0, 1].
QColor interpolated(const Rgb* stops, std::size_t count, double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * static_cast<double>(count - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), count - 2);
  const double f = t - static_cast<double>(i);
  auto mix = [&](std::size_t c) {
    return static_cast<int>(std::lround(stops[i][c] + f * (stops[i + 1][c] - stops[i][c])));
  };
  return {mix(0), mix(1), mix(2)};
}

// Viridis (van der Walt and Smith, 2015) at nine equally spaced points, as published: dark
// purple through blue and green to yellow, lightness rising all the way.
constexpr std::array<Rgb, 9> kSequential{{{68, 1, 84},
                                          {71, 45, 123},
                                          {59, 82, 139},
                                          {44, 114, 142},
                                          {33, 145, 140},
                                          {40, 174, 128},
                                          {94, 201, 98},
                                          {173, 220, 48},
                                          {253, 231, 37}}};

// Blue, a light neutral grey at zero, red (the ColorBrewer red-blue scheme's seven classes):
// lightness falls equally to both sides of zero.
constexpr std::array<Rgb, 7> kDiverging{{{33, 102, 172},
                                         {103, 169, 207},
                                         {209, 229, 240},
                                         {247, 247, 247},
                                         {253, 219, 199},
                                         {239, 138, 98},
                                         {178, 24, 43}}};

}  // namespace

QColor valueColor(double value, double maxValue) {
  return interpolated(kSequential.data(), kSequential.size(),
                      maxValue > 0.0 && std::isfinite(value) ? value / maxValue : 0.0);
}

QColor signedValueColor(double value, double maxAbs) {
  return interpolated(kDiverging.data(), kDiverging.size(),
                      maxAbs > 0.0 && std::isfinite(value) ? 0.5 + 0.5 * value / maxAbs : 0.5);
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
