#include "base/text_rules.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace tactile {
namespace {

// Length of the well-formed UTF-8 sequence at `i`, or 0 when the byte there starts none.
std::size_t sequenceAt(const unsigned char* s, std::size_t n, std::size_t i) {
  const unsigned char c = s[i];
  if (c < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80;
  unsigned char high = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    length = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    length = 3;
    if (c == 0xE0) low = 0xA0;   // overlong
    if (c == 0xED) high = 0x9F;  // surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    length = 4;
    if (c == 0xF0) low = 0x90;   // overlong
    if (c == 0xF4) high = 0x8F;  // above U+10FFFF
  } else {
    return 0;
  }
  if (i + length > n) return 0;
  if (s[i + 1] < low || s[i + 1] > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (s[i + k] < 0x80 || s[i + k] > 0xBF) return 0;
  }
  return length;
}

// U+0000-U+001F and U+007F (one byte) or U+0080-U+009F (C2 80 .. C2 9F).
bool isControlAt(const unsigned char* s, std::size_t length, std::size_t i) {
  if (length == 1) return s[i] < 0x20 || s[i] == 0x7F;
  return length == 2 && s[i] == 0xC2 && s[i + 1] <= 0x9F;
}

void appendHex(std::string& out, unsigned char byte) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned>(byte));
  out += hex;
}

}  // namespace

std::size_t invalidUtf8At(std::string_view text) {
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  std::size_t i = 0;
  while (i < n) {
    // ASCII runs, eight bytes at a time.
    while (i + 8 <= n) {
      std::uint64_t word;
      std::memcpy(&word, s + i, 8);
      if ((word & 0x8080808080808080ULL) != 0) break;
      i += 8;
    }
    if (i >= n) break;
    const std::size_t length = sequenceAt(s, n, i);
    if (length == 0) return i;
    i += length;
  }
  return std::string_view::npos;
}

std::optional<std::string> nameProblem(std::string_view name) {
  if (name.empty()) return std::string("is empty");
  const auto* s = reinterpret_cast<const unsigned char*>(name.data());
  const std::size_t n = name.size();
  for (std::size_t i = 0; i < n;) {
    const std::size_t length = sequenceAt(s, n, i);
    const std::string at = " at byte " + std::to_string(i + 1);
    if (length == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(s[i]));
      return "is not valid UTF-8 (byte " + std::string(hex) + at + ")";
    }
    if (isControlAt(s, length, i)) {
      std::string shown;
      appendHex(shown, s[i + length - 1]);
      if (length == 2) shown = "U+00" + shown.substr(2);
      return "holds a control character (" + shown + ")" + at;
    }
    if (s[i] == ',') return "holds a comma" + at;
    i += length;
  }
  if (n > kMaxNameBytes) {
    return "is " + std::to_string(n) + " bytes long (at most " + std::to_string(kMaxNameBytes) +
           ")";
  }
  return std::nullopt;
}

Status checkName(std::string_view name, std::string_view what) {
  const std::optional<std::string> problem = nameProblem(name);
  if (!problem) return Status::success();
  if (name.empty()) return Error("a " + std::string(what) + " needs a name (it is empty)");
  return Error("a " + std::string(what) +
               " name must be valid UTF-8 of at most 200 bytes without commas or control "
               "characters: '" +
               shownText(name, 60) + "' " + *problem);
}

std::string nameFromFileStem(std::string_view stem) {
  std::string out(stem);
  const auto* s = reinterpret_cast<const unsigned char*>(out.data());
  const std::size_t n = out.size();
  for (std::size_t i = 0; i < n;) {
    const std::size_t length = sequenceAt(s, n, i);
    if (length == 0) {
      ++i;
      continue;
    }
    if (s[i] == ',' || isControlAt(s, length, i)) {
      out.replace(i, length, length, '_');
    }
    i += length;
  }
  return out;
}

std::string shownText(std::string_view text, std::size_t maxBytes) {
  const bool cut = text.size() > maxBytes;
  if (cut) {
    // Not inside a UTF-8 sequence: back off over at most three continuation bytes.
    std::size_t end = maxBytes;
    for (int k = 0; k < 3 && end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80; ++k)
      --end;
    text = text.substr(0, end == 0 ? maxBytes : end);
  }
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  std::string out;
  out.reserve(n);
  for (std::size_t i = 0; i < n;) {
    const std::size_t length = sequenceAt(s, n, i);
    if (length == 0 || isControlAt(s, length, i)) {
      // Each byte of an invalid or control sequence on its own.
      const std::size_t bytes = length == 0 ? 1 : length;
      for (std::size_t k = 0; k < bytes; ++k)
        appendHex(out, s[i + k]);
      i += bytes;
      continue;
    }
    out.append(text.substr(i, length));
    i += length;
  }
  if (cut) out += "...";
  return out;
}

std::string quotedInput(std::string_view text) {
  return "'" + shownText(text, kMaxQuotedBytes) + "'";
}

std::string validUtf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  while (!text.empty()) {
    const std::size_t bad = invalidUtf8At(text);
    out.append(text.substr(0, bad));
    if (bad == std::string_view::npos) break;
    out += "\xEF\xBF\xBD";
    text.remove_prefix(bad + 1);
  }
  return out;
}

}  // namespace tactile
