#include "mcap/crc32.h"

#include <array>

namespace tactile::mcap {
namespace {

// Slicing-by-16: sixteen tables, sixteen bytes a step, plain table lookups (no instruction beyond
// baseline x86-64, so the build does not depend on the CPU).
using Tables = std::array<std::array<std::uint32_t, 256>, 16>;

constexpr Tables makeTables() {
  Tables t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k)
      c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    t[0][i] = c;
  }
  for (std::size_t s = 1; s < 16; ++s) {
    for (std::size_t i = 0; i < 256; ++i)
      t[s][i] = (t[s - 1][i] >> 8) ^ t[0][t[s - 1][i] & 0xFFU];
  }
  return t;
}

constexpr Tables kTables = makeTables();

inline std::uint32_t load32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

}  // namespace

std::uint32_t crc32(std::string_view bytes, std::uint32_t crc) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t n = bytes.size();
  std::uint32_t c = ~crc;
  const auto& t = kTables;
  while (n >= 16) {
    const std::uint32_t a = c ^ load32(p);
    const std::uint32_t b = load32(p + 4);
    const std::uint32_t d = load32(p + 8);
    const std::uint32_t e = load32(p + 12);
    c = t[15][a & 0xFFU] ^ t[14][(a >> 8) & 0xFFU] ^ t[13][(a >> 16) & 0xFFU] ^ t[12][a >> 24] ^
        t[11][b & 0xFFU] ^ t[10][(b >> 8) & 0xFFU] ^ t[9][(b >> 16) & 0xFFU] ^ t[8][b >> 24] ^
        t[7][d & 0xFFU] ^ t[6][(d >> 8) & 0xFFU] ^ t[5][(d >> 16) & 0xFFU] ^ t[4][d >> 24] ^
        t[3][e & 0xFFU] ^ t[2][(e >> 8) & 0xFFU] ^ t[1][(e >> 16) & 0xFFU] ^ t[0][e >> 24];
    p += 16;
    n -= 16;
  }
  while (n-- > 0)
    c = t[0][(c ^ *p++) & 0xFFU] ^ (c >> 8);
  return ~c;
}

}  // namespace tactile::mcap
