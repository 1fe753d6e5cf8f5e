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

// Eight bytes into a (pre-conditioned) CRC, slicing by eight.
inline std::uint32_t step8(std::uint32_t c, const unsigned char* p) {
  const auto& t = kTables;
  const std::uint32_t a = c ^ load32(p);
  const std::uint32_t b = load32(p + 4);
  return t[7][a & 0xFFU] ^ t[6][(a >> 8) & 0xFFU] ^ t[5][(a >> 16) & 0xFFU] ^ t[4][a >> 24] ^
         t[3][b & 0xFFU] ^ t[2][(b >> 8) & 0xFFU] ^ t[1][(b >> 16) & 0xFFU] ^ t[0][b >> 24];
}

// One pass over bytes; `c` and the result are pre-conditioned (inverted) CRCs.
std::uint32_t crcRaw(const unsigned char* p, std::size_t n, std::uint32_t c) {
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
  return c;
}

// Combining the CRCs of two pieces (zlib's method): multiplication modulo the polynomial in the
// reflected bit order, and x^(8 * len) by squaring.
std::uint32_t multModP(std::uint32_t a, std::uint32_t b) {
  std::uint32_t m = 1U << 31;
  std::uint32_t p = 0;
  for (;;) {
    if ((a & m) != 0) {
      p ^= b;
      if ((a & (m - 1)) == 0) break;
    }
    m >>= 1;
    b = (b & 1U) != 0 ? (b >> 1) ^ 0xEDB88320U : b >> 1;
  }
  return p;
}

std::uint32_t xPowBytes(std::uint64_t len) {
  std::uint32_t square = 1U << 30;  // x^1
  for (int i = 0; i < 3; ++i)
    square = multModP(square, square);  // x^8: one byte
  std::uint32_t p = 1U << 31;           // x^0
  while (len != 0) {
    if ((len & 1U) != 0) p = multModP(square, p);
    square = multModP(square, square);
    len >>= 1;
  }
  return p;
}

// crc32 of A then B from the CRCs of A and of B alone.
std::uint32_t combine(std::uint32_t crcA, std::uint32_t crcB, std::uint64_t lenB) {
  return multModP(xPowBytes(lenB), crcA) ^ crcB;
}

// Below this, one stream; above, three interleaved streams over thirds of the bytes (their table
// lookups overlap instead of waiting on each other), combined at the end.
constexpr std::size_t kThreeStreams = 16 * 1024;

}  // namespace

std::uint32_t crc32(std::string_view bytes, std::uint32_t crc) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size();
  if (n < kThreeStreams) return ~crcRaw(p, n, ~crc);
  const std::size_t third = (n / 3) & ~std::size_t{7};
  const unsigned char* p1 = p + third;
  const unsigned char* p2 = p + 2 * third;
  std::uint32_t c0 = ~crc, c1 = ~0U, c2 = ~0U;
  for (std::size_t i = 0; i < third; i += 8) {
    c0 = step8(c0, p + i);
    c1 = step8(c1, p1 + i);
    c2 = step8(c2, p2 + i);
  }
  c2 = crcRaw(p + 3 * third, n - 3 * third, c2);
  const std::uint32_t a = ~c0, b = ~c1, c = ~c2;
  return combine(combine(a, b, third), c, n - 2 * third);
}

}  // namespace tactile::mcap
