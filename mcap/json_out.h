// Appending JSON text fast (the exporter writes millions of messages). Internal to the mcap part.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace tactile::mcap::json_out {

// The shortest text that reads back as the same double; -0 is written "-0.0" so a reader that
// takes "-0" for the integer 0 still keeps the sign.
inline void number(std::string& out, double v) {
  if (v == 0.0) {
    out.append(std::signbit(v) ? "-0.0" : "0");
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, static_cast<std::size_t>(r.ptr - buf));
}

inline void integer(std::string& out, std::uint64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, static_cast<std::size_t>(r.ptr - buf));
}

// A JSON string with the escapes it needs (the text is UTF-8 already).
inline void string(std::string& out, std::string_view s) {
  out.push_back('"');
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(ch);
    } else if (c < 0x20) {
      static constexpr char kHex[] = "0123456789abcdef";
      out.append("\\u00");
      out.push_back(kHex[c >> 4]);
      out.push_back(kHex[c & 15]);
    } else {
      out.push_back(ch);
    }
  }
  out.push_back('"');
}

}  // namespace tactile::mcap::json_out
