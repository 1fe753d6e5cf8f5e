// A duration as the workbench shows it: m:ss, or h:mm:ss from an hour.
#pragma once

#include <QString>

#include <algorithm>
#include <cmath>

namespace tactile::gui {

inline QString durationText(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  return s >= 3600 ? QStringLiteral("%1:%2:%3")
                         .arg(s / 3600)
                         .arg((s / 60) % 60, 2, 10, QLatin1Char('0'))
                         .arg(s % 60, 2, 10, QLatin1Char('0'))
                   : QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

}  // namespace tactile::gui
