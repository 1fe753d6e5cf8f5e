// The names of strategies, status sources and contact statuses, and the status text the runs
// record (Hole(<width>) for a hole), read back by parseStatusText.
#include <cmath>
#include <cstdio>

#include "nav/navigator.h"

namespace tactile::nav {
namespace {

constexpr std::array<std::string_view, kStrategyCount> kTitles{
    "Go Straight",       "Head to Destination", "Check Contact", "Follow Wall",
    "Move through Wall", "Right U Turn",        "Left U Turn"};
constexpr std::array<std::string_view, kStrategyCount> kKeys{
    "GoStraight",      "HeadToDestination", "CheckContact", "FollowWall",
    "MoveThroughWall", "RightUTurn",        "LeftUTurn"};
constexpr std::array<std::string_view, 3> kSourceNames{"model", "truth", "bumper"};
constexpr std::array<std::string_view, 7> kKindNames{"NoContact", "Wall", "Corner",   "LeavingWall",
                                                     "DeadPath",  "Hole", "Undecided"};

}  // namespace

std::string_view strategyTitle(Strategy s) {
  return kTitles[static_cast<std::size_t>(s)];
}
std::string_view strategyKey(Strategy s) {
  return kKeys[static_cast<std::size_t>(s)];
}
std::optional<Strategy> parseStrategyKey(std::string_view key) {
  for (std::size_t i = 0; i < kKeys.size(); ++i)
    if (kKeys[i] == key) return static_cast<Strategy>(i);
  return std::nullopt;
}
std::string_view statusSourceName(StatusSource s) {
  return kSourceNames[static_cast<std::size_t>(s)];
}
std::optional<StatusSource> parseStatusSource(std::string_view name) {
  for (std::size_t i = 0; i < kSourceNames.size(); ++i)
    if (kSourceNames[i] == name) return static_cast<StatusSource>(i);
  return std::nullopt;
}

ContactStatus ContactStatus::of(ContactClass c) {
  return ContactStatus{static_cast<StatusKind>(c), 0.0};
}

std::string statusText(const ContactStatus& s) {
  if (s.kind == StatusKind::Hole) {
    const double w = std::isfinite(s.holeWidthUnits) ? std::round(s.holeWidthUnits) : 0.0;
    char buf[48];
    std::snprintf(buf, sizeof buf, "Hole(%.0f)", w == 0.0 ? 0.0 : w);
    return buf;
  }
  return std::string(kKindNames[static_cast<std::size_t>(s.kind)]);
}

std::optional<ContactStatus> parseStatusText(std::string_view text) {
  for (std::size_t i = 0; i < kKindNames.size(); ++i) {
    if (i == static_cast<std::size_t>(StatusKind::Hole)) continue;
    if (kKindNames[i] == text) return ContactStatus{static_cast<StatusKind>(i), 0.0};
  }
  if (text.size() > 6 && text.starts_with("Hole(") && text.ends_with(")")) {
    const std::string_view digits = text.substr(5, text.size() - 6);
    double w = 0.0;
    for (char c : digits) {
      if (c < '0' || c > '9') return std::nullopt;
      w = 10.0 * w + (c - '0');
    }
    return ContactStatus{StatusKind::Hole, w};
  }
  return std::nullopt;
}

}  // namespace tactile::nav
