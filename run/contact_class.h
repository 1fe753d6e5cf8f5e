// Contact classes (docs/domain.md#contact-classes), with their exact file spellings.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace tactile {

enum class ContactClass : std::uint8_t { NoContact, Wall, Corner, LeavingWall, DeadPath };

inline constexpr int kContactClassCount = 5;

inline constexpr std::array<std::string_view, kContactClassCount> kContactClassNames{
    "NoContact", "Wall", "Corner", "LeavingWall", "DeadPath"};

constexpr std::string_view contactClassName(ContactClass c) {
  return kContactClassNames[static_cast<std::size_t>(c)];
}

// Exact, case-sensitive match against the spellings above.
constexpr std::optional<ContactClass> parseContactClass(std::string_view name) {
  for (std::size_t i = 0; i < kContactClassNames.size(); ++i) {
    if (kContactClassNames[i] == name) return static_cast<ContactClass>(i);
  }
  return std::nullopt;
}

}  // namespace tactile
