#include "app/gui/sim/drive_keys.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>

namespace tactile::gui {
namespace {

constexpr std::array<SimKey, 15> kKeys{{
    {Qt::Key_Up, SimKeyAction::SpeedUpLarge, "Up",
     QT_TRANSLATE_NOOP("SimKeys", "Faster forward by a large step (+20 units/s)")},
    {Qt::Key_Down, SimKeyAction::SlowDownLarge, "Down",
     QT_TRANSLATE_NOOP("SimKeys", "Slower (or backward) by a large step (-20 units/s)")},
    {Qt::Key_W, SimKeyAction::SpeedUpSmall, "W",
     QT_TRANSLATE_NOOP("SimKeys", "Faster forward by a small step (+5 units/s)")},
    {Qt::Key_S, SimKeyAction::SlowDownSmall, "S",
     QT_TRANSLATE_NOOP("SimKeys", "Slower (or backward) by a small step (-5 units/s)")},
    {Qt::Key_Left, SimKeyAction::TurnLeftLarge, "Left",
     QT_TRANSLATE_NOOP("SimKeys", "Turn left by a large step (+0.2 rad/s)")},
    {Qt::Key_Right, SimKeyAction::TurnRightLarge, "Right",
     QT_TRANSLATE_NOOP("SimKeys", "Turn right by a large step (-0.2 rad/s)")},
    {Qt::Key_A, SimKeyAction::TurnLeftSmall, "A",
     QT_TRANSLATE_NOOP("SimKeys", "Turn left by a small step (+0.05 rad/s)")},
    {Qt::Key_D, SimKeyAction::TurnRightSmall, "D",
     QT_TRANSLATE_NOOP("SimKeys", "Turn right by a small step (-0.05 rad/s)")},
    {Qt::Key_Space, SimKeyAction::Stop, "Space",
     QT_TRANSLATE_NOOP("SimKeys", "Stop (v = 0, omega = 0)")},
    {Qt::Key_M, SimKeyAction::ToggleView, "M",
     QT_TRANSLATE_NOOP("SimKeys",
                       "Robot close-up / whole scene (close-up only in experiment mode)")},
    {Qt::Key_T, SimKeyAction::ToggleTouchMap, "T",
     QT_TRANSLATE_NOOP(
         "SimKeys", "The navigator's touch map and plan on the picture / off (autonomous mode)")},
    {Qt::Key_P, SimKeyAction::TogglePause, "P", QT_TRANSLATE_NOOP("SimKeys", "Pause / go on")},
    {Qt::Key_Pause, SimKeyAction::TogglePause, "Pause",
     QT_TRANSLATE_NOOP("SimKeys", "Pause / go on")},
    {Qt::Key_Period, SimKeyAction::StepOnce, ".",
     QT_TRANSLATE_NOOP("SimKeys", "One step (while paused)")},
    {Qt::Key_N, SimKeyAction::StepOnce, "N",
     QT_TRANSLATE_NOOP("SimKeys", "One step (while paused)")},
}};

double clampRounded(double value, double limit) {
  // Steps of 0.05 and 0.2 are not exact in binary; rounding to 1e-9 keeps sums like
  // 0.2 - 0.05 * 4 at exactly 0, so a person who steps back to zero really stops.
  const double rounded = std::round(value * 1e9) / 1e9;
  return std::clamp(rounded, -limit, limit);
}

}  // namespace

std::span<const SimKey> simKeys() {
  return kKeys;
}

const SimKey* simKeyFor(int key) {
  for (const SimKey& k : kKeys) {
    if (k.key == key) return &k;
  }
  return nullptr;
}

bool isDriveAction(SimKeyAction action) {
  return action <= SimKeyAction::Stop;
}

sim::Command applyDriveAction(SimKeyAction action, const sim::Command& current) {
  double dv = 0.0;
  double dw = 0.0;
  switch (action) {
    case SimKeyAction::SpeedUpLarge:
      dv = kLargeSpeedStep;
      break;
    case SimKeyAction::SlowDownLarge:
      dv = -kLargeSpeedStep;
      break;
    case SimKeyAction::SpeedUpSmall:
      dv = kSmallSpeedStep;
      break;
    case SimKeyAction::SlowDownSmall:
      dv = -kSmallSpeedStep;
      break;
    case SimKeyAction::TurnLeftLarge:
      dw = kLargeTurnStep;
      break;
    case SimKeyAction::TurnRightLarge:
      dw = -kLargeTurnStep;
      break;
    case SimKeyAction::TurnLeftSmall:
      dw = kSmallTurnStep;
      break;
    case SimKeyAction::TurnRightSmall:
      dw = -kSmallTurnStep;
      break;
    case SimKeyAction::Stop:
      return {};
    default:
      return current;
  }
  return {clampRounded(current.v + dv, kMaxDriveSpeed),
          clampRounded(current.omega + dw, kMaxDriveTurn)};
}

QString simKeyDescription(const SimKey& key) {
  return QCoreApplication::translate("SimKeys", key.description);
}

}  // namespace tactile::gui
