#include "run/builtin_scenes.h"

#include <algorithm>
#include <utility>

namespace tactile {
namespace detail {
extern const std::pair<std::string_view, std::string_view> kBuiltinScenes[];
extern const int kBuiltinSceneCount;
}  // namespace detail

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (int i = 0; i < detail::kBuiltinSceneCount; ++i) {
    names.emplace_back(detail::kBuiltinScenes[i].first);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::optional<std::string_view> builtinSceneJson(std::string_view name) {
  for (int i = 0; i < detail::kBuiltinSceneCount; ++i) {
    if (detail::kBuiltinScenes[i].first == name) return detail::kBuiltinScenes[i].second;
  }
  return std::nullopt;
}

}  // namespace tactile
