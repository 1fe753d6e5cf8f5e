// JSON in and out, one way for every part: parsing names the file, line and column of any error
// (number overflow such as 1e400 included), and writing never fails on text that is not UTF-8
// (such bytes become U+FFFD), so `--json` output and JSON files are always valid JSON.
#pragma once

#include <exception>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/error.h"

namespace tactile {

// Where the elements of a parsed document are: the 1-based line of every object member (the line
// of its key) and every array element (the line it starts on), by JSON pointer
// ("/segments/0/first_step"; "" is the whole document, on line 1).
struct JsonLines {
  std::unordered_map<std::string, std::size_t> lines;
  // Integers written as "-0" (a value the reader's rules may refuse: it is 0 in the DOM), by
  // pointer.
  std::vector<std::string> negativeZeros;
  // The line of `pointer`, or 0 when it is not known.
  std::size_t lineOf(const std::string& pointer) const {
    const auto it = lines.find(pointer);
    return it == lines.end() ? 0 : it->second;
  }
};

// Parses a JSON document (RFC 8259, no comments). An error names `fileName`, the 1-based line and
// column, and says what was wrong ("number overflow: '1e400' does not fit a double"); a document
// nested deeper than kMaxJsonDepth is refused, so nothing downstream recurses without bound, and an
// object that repeats a key is refused ("duplicate key 'x' (first on line 3)") instead of keeping
// one of the values. With `lines`, also records where every element is, so that content errors
// can name a line too.
Result<nlohmann::json> parseJsonText(std::string_view text, std::string_view fileName,
                                     JsonLines* lines = nullptr);

// An exception the JSON library threw while a reader looked at a parsed document (a value of the
// wrong type, a missing key), in plain words: "expected a number, found a string".
std::string plainJsonError(const std::exception& e);

inline constexpr std::size_t kMaxJsonDepth = 512;

// The document as text (compact, or indented by `indent` spaces); bytes that are not well-formed
// UTF-8 are replaced by U+FFFD instead of failing.
std::string dumpJson(const nlohmann::json& doc, int indent = -1);

}  // namespace tactile
