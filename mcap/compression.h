// Chunk compression: zstd (libzstd), lz4 frames (liblz4) or none. Public because a writer picks
// one; the reader picks by the chunk's `compression` string.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "mcap/buffer.h"

namespace tactile::mcap {

enum class Compression { None, Zstd, Lz4 };

// "", "zstd", "lz4" (the MCAP registry's names); nullopt for anything else.
std::optional<Compression> parseCompression(std::string_view name);
std::string_view compressionName(Compression c);

// Compresses one chunk's records at a time, reusing its state. Throws std::runtime_error when
// the library fails (it does not for valid input; out of memory is std::bad_alloc).
class Compressor {
 public:
  // `level`: zstd's level (negative levels are its fast modes); `hashLog`: zstd's hash table
  // size (log2 of entries; 0: the level's own). Both unused for lz4 and none.
  Compressor(Compression c, int level, int hashLog = 0);
  ~Compressor();
  Compressor(const Compressor&) = delete;
  Compressor& operator=(const Compressor&) = delete;

  Compression kind() const { return kind_; }
  // The compressed `in`, valid until the next call.
  std::string_view compress(std::string_view in);

 private:
  Compression kind_;
  struct State;
  std::unique_ptr<State> state_;
};

// Decompresses chunks one after another, reusing its decoders' state (a file holds thousands of
// chunks). The output grows only as the decoder produces bytes (never to a size the data does not
// justify), so a forged size allocates nothing.
class Decompressor {
 public:
  Decompressor();
  ~Decompressor();
  Decompressor(const Decompressor&) = delete;
  Decompressor& operator=(const Decompressor&) = delete;

  // Decompresses `in` into `out`, which must come out exactly `expectedSize` bytes long. Returns
  // nullopt on success, else what went wrong ("zstd: ...").
  std::optional<std::string> decompress(Compression c, std::string_view in,
                                        std::uint64_t expectedSize, Buffer& out);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace tactile::mcap
