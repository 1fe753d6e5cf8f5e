// CRC-32 as MCAP uses it (the IEEE 802.3 / zlib polynomial 0xEDB88320, reflected, initial value
// and final xor 0xFFFFFFFF): crc32("123456789") == 0xCBF43926. Portable table code (slicing by
// sixteen), the same on every processor.
#pragma once

#include <cstdint>
#include <string_view>

namespace tactile::mcap {

// The CRC of `bytes`, continuing from `crc` (the CRC of the bytes before them; 0 to start).
std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0);

}  // namespace tactile::mcap
