// Little-endian integers in and out of byte buffers, the MCAP way (spec: "Serialization"), with
// every read checked against the bytes that are there. Internal to the mcap part.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace tactile::mcap::bytes {

// `Out` is std::string or mcap::Buffer (anything with push_back, append(p, n) and operator[]).
template <class Out>
inline void putU8(Out& out, std::uint8_t v) {
  out.push_back(static_cast<char>(v));
}
template <class Out>
inline void putU16(Out& out, std::uint16_t v) {
  const char b[2] = {static_cast<char>(v & 0xFF), static_cast<char>(v >> 8)};
  out.append(b, 2);
}
template <class Out>
inline void putU32(Out& out, std::uint32_t v) {
  char b[4];
  for (int i = 0; i < 4; ++i)
    b[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
  out.append(b, 4);
}
template <class Out>
inline void putU64(Out& out, std::uint64_t v) {
  char b[8];
  for (int i = 0; i < 8; ++i)
    b[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
  out.append(b, 8);
}
template <class Out>
inline void putString(Out& out, std::string_view s) {
  putU32(out, static_cast<std::uint32_t>(s.size()));
  out.append(s);
}
// Overwrites 8 bytes at `at` (a length written before its content was known).
template <class Out>
inline void patchU64(Out& out, std::size_t at, std::uint64_t v) {
  for (int i = 0; i < 8; ++i)
    out[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

inline std::uint16_t getU16(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return static_cast<std::uint16_t>(u[0] | (u[1] << 8));
}
inline std::uint32_t getU32(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return static_cast<std::uint32_t>(u[0]) | (static_cast<std::uint32_t>(u[1]) << 8) |
         (static_cast<std::uint32_t>(u[2]) << 16) | (static_cast<std::uint32_t>(u[3]) << 24);
}
inline std::uint64_t getU64(const char* p) {
  return static_cast<std::uint64_t>(getU32(p)) | (static_cast<std::uint64_t>(getU32(p + 4)) << 32);
}

}  // namespace tactile::mcap::bytes
