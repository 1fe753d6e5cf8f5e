// The navigator's state as a run's extra columns, as `tactile navigate` writes them
// (docs/navigation.md#run-files): x_strategy, x_status, then x_status_<group> in sensor-group
// order, one row a step. The column names and the spellings are nav/'s (kStrategyColumn,
// strategyKey, statusText); the simulator window's autonomous mode records its runs with these,
// so the workbench shows the navigator's strips for them.
#pragma once

#include <string>
#include <vector>

namespace tactile::nav {
class Navigator;
}

namespace tactile::gui {

// The column names, in order.
std::vector<std::string> navigatorColumns();
// Appends the navigator's state after its last step: one value per column, in column order.
void appendNavigatorState(const nav::Navigator& navigator, std::vector<std::string>& values);

}  // namespace tactile::gui
