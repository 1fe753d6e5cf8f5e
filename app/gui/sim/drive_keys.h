// The simulator window's keys in one table (thesis 2.5): the driving keys change the command
// (v, omega) by a large or a small step, Space stops; the others switch the view, pause and step.
// The window binds its keys from this table and Help > Keys lists it, so the two cannot disagree.
#pragma once

#include <QString>

#include <span>

#include "sim/driver.h"

namespace tactile::gui {

// Command steps and limits (units/s, rad/s). At dt 0.1 a large speed step moves the robot 2 units
// a step, a large turn step turns it about 1.1 degrees a step.
inline constexpr double kLargeSpeedStep = 20.0;
inline constexpr double kSmallSpeedStep = 5.0;
inline constexpr double kLargeTurnStep = 0.2;
inline constexpr double kSmallTurnStep = 0.05;
inline constexpr double kMaxDriveSpeed = 120.0;
inline constexpr double kMaxDriveTurn = 1.5;

enum class SimKeyAction {
  SpeedUpLarge,
  SlowDownLarge,
  SpeedUpSmall,
  SlowDownSmall,
  TurnLeftLarge,
  TurnRightLarge,
  TurnLeftSmall,
  TurnRightSmall,
  Stop,
  ToggleView,      // robot close-up / whole scene (where the mode allows)
  ToggleTouchMap,  // the navigator's touch map and plan drawn on the picture, or not
  TogglePause,     // pause / go on
  StepOnce,        // one step while paused
};

struct SimKey {
  int key;  // Qt::Key
  SimKeyAction action;
  const char* keyText;      // as printed in Help (not translated)
  const char* description;  // translated through QCoreApplication::translate("SimKeys", ...)
};

// Every key of the window, in the order Help lists them.
std::span<const SimKey> simKeys();
// The entry of a key, or null.
const SimKey* simKeyFor(int key);
// True for the actions that change the command.
bool isDriveAction(SimKeyAction action);
// The command after a driving action: v and omega change by the action's step and are clamped to
// the limits above (and rounded to 1e-9 so repeated steps come back to exactly 0); Stop gives
// (0, 0). Other actions return `current` unchanged.
sim::Command applyDriveAction(SimKeyAction action, const sim::Command& current);
// The description of a key, translated.
QString simKeyDescription(const SimKey& key);

}  // namespace tactile::gui
