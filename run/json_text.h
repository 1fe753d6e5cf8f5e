// JSON in and out, one way for every part: parsing names the file, line and column of any error
// (number overflow such as 1e400 included), and writing never fails on text that is not UTF-8
// (such bytes become U+FFFD), so `--json` output and JSON files are always valid JSON.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "base/error.h"

namespace tactile {

// Parses a JSON document (RFC 8259, no comments). An error names `fileName`, the 1-based line and
// column, and says what was wrong ("number overflow: '1e400' does not fit a double"); a document
// nested deeper than kMaxJsonDepth is refused, so nothing downstream recurses without bound.
Result<nlohmann::json> parseJsonText(std::string_view text, std::string_view fileName);

inline constexpr std::size_t kMaxJsonDepth = 512;

// The document as text (compact, or indented by `indent` spaces); bytes that are not well-formed
// UTF-8 are replaced by U+FFFD instead of failing.
std::string dumpJson(const nlohmann::json& doc, int indent = -1);

}  // namespace tactile
