// QSettings keys of the workbench in one place, so a renamed key cannot silently drop a setting.
#pragma once

#include <QLatin1StringView>

namespace tactile::gui::settings_keys {

inline constexpr QLatin1StringView kGeometry{"mainWindow/geometry"};
inline constexpr QLatin1StringView kWindowState{"mainWindow/state"};
inline constexpr QLatin1StringView kRecentDatabases{"mainWindow/recentDatabases"};
// Server addresses opened with File > Open Server, newest first, never with a password.
inline constexpr QLatin1StringView kRecentServers{"mainWindow/recentServers"};
inline constexpr QLatin1StringView kLastDatabase{"mainWindow/lastDatabase"};
inline constexpr QLatin1StringView kLastRun{"mainWindow/lastRun"};
inline constexpr QLatin1StringView kLastLabelSet{"labels/lastSet"};
inline constexpr QLatin1StringView kLabelGroupsMode{"labels/groupsMode"};
inline constexpr QLatin1StringView kPlaySpeed{"steps/playSpeed"};
inline constexpr QLatin1StringView kRunFilter{"runs/filter"};
// Preferences. The interface language: "" follows the system locale, else "en", "de" or "zh_CN"
// (read once at start). The annotator's name is stored on every label segment the GUI writes.
inline constexpr QLatin1StringView kLanguage{"ui/language"};
inline constexpr QLatin1StringView kAnnotator{"labels/annotator"};
// Posterior below which a prediction counts as unsure (Learn > Next Doubt), 0.5 to 0.99.
inline constexpr QLatin1StringView kDoubtThreshold{"labels/doubtThreshold"};
inline constexpr double kDefaultDoubtThreshold = 0.8;
// Height in pixels of one label, truth or model row of the timelines.
inline constexpr QLatin1StringView kTimelineRowHeight{"timelineView/rowHeight"};
inline constexpr int kMaxRecentDatabases = 8;
// The Train and Sweep dialog's last label set and grid (orders, floors, seeds as typed; groups,
// methods, covariance forms, features and decisions as the ticked names).
inline constexpr QLatin1StringView kTrainingLabelSet{"training/labelSet"};
inline constexpr QLatin1StringView kTrainingOrders{"training/orders"};
inline constexpr QLatin1StringView kTrainingFloors{"training/floors"};
inline constexpr QLatin1StringView kTrainingTrees{"training/trees"};
inline constexpr QLatin1StringView kTrainingDepths{"training/depths"};
inline constexpr QLatin1StringView kTrainingLearningRates{"training/learningRates"};
inline constexpr QLatin1StringView kTrainingMinChildWeights{"training/minChildWeights"};
inline constexpr QLatin1StringView kTrainingSeeds{"training/seeds"};
inline constexpr QLatin1StringView kTrainingTicked{"training/ticked"};
inline constexpr QLatin1StringView kTrainingSplit{"training/split"};
// The folder each file dialog last chose in, by purpose ("fileDialogs/<purpose>").
inline constexpr QLatin1StringView kFileDialogs{"fileDialogs/"};

}  // namespace tactile::gui::settings_keys
