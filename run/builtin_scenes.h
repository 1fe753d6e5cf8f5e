// Built-in scenes (resources/scenes/*.json), embedded in the binary at build time so that the
// tools and the workbench work without the source tree.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tactile {

// Names of the built-in scenes ("practice", "room1", ...), sorted.
std::vector<std::string> builtinSceneNames();

// The JSON text of a built-in scene, or nullopt for an unknown name.
std::optional<std::string_view> builtinSceneJson(std::string_view name);

}  // namespace tactile
