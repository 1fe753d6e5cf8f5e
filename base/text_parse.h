// Strict number parsing shared by the run-file reader and metadata getters: the whole field must
// be one std::from_chars literal (no leading '+', no spaces, no hex, no quotes).
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <system_error>
#include <vector>

namespace tactile {

// A finite double in plain decimal or exponent notation.
inline bool parseFiniteDouble(std::string_view text, double& out) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out, std::chars_format::general);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

// A base-10 integer literal.
inline bool parseInteger(std::string_view text, std::int64_t& out) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end;
}

// A count or step number: an integer literal of digits only, no sign, no leading zero ("0" is the
// only literal that starts with 0), that fits an int64.
inline bool parseCount(std::string_view text, std::int64_t& out) {
  if (text.empty() || text[0] < '0' || text[0] > '9') return false;
  if (text[0] == '0' && text.size() > 1) return false;
  return parseInteger(text, out);
}

// Splits "a,b,c" into finite doubles; false unless exactly `count` of them.
inline bool parseDoubleList(std::string_view text, std::size_t count, std::vector<double>& out) {
  out.clear();
  while (true) {
    const std::size_t comma = text.find(',');
    double value = 0.0;
    if (!parseFiniteDouble(text.substr(0, comma), value)) return false;
    out.push_back(value);
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return out.size() == count;
}

}  // namespace tactile
