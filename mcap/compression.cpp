#include "mcap/compression.h"

#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <stdexcept>

namespace tactile::mcap {

std::optional<Compression> parseCompression(std::string_view name) {
  if (name.empty()) return Compression::None;
  if (name == "zstd") return Compression::Zstd;
  if (name == "lz4") return Compression::Lz4;
  return std::nullopt;
}

std::string_view compressionName(Compression c) {
  switch (c) {
    case Compression::Zstd:
      return "zstd";
    case Compression::Lz4:
      return "lz4";
    case Compression::None:
      break;
  }
  return "";
}

struct Compressor::State {
  ZSTD_CCtx* zstd = nullptr;
  std::unique_ptr<char[]> buffer;
  std::size_t capacity = 0;
  ~State() { ZSTD_freeCCtx(zstd); }
};

Compressor::Compressor(Compression c, int level, int hashLog)
    : kind_(c), state_(std::make_unique<State>()) {
  if (c == Compression::Zstd) {
    state_->zstd = ZSTD_createCCtx();
    if (state_->zstd == nullptr) throw std::bad_alloc();
    ZSTD_CCtx_setParameter(state_->zstd, ZSTD_c_compressionLevel, level);
    if (hashLog != 0) {
      const ZSTD_bounds b = ZSTD_cParam_getBounds(ZSTD_c_hashLog);
      ZSTD_CCtx_setParameter(state_->zstd, ZSTD_c_hashLog,
                             std::clamp(hashLog, b.lowerBound, b.upperBound));
    }
  }
}

Compressor::~Compressor() = default;

std::string_view Compressor::compress(std::string_view in) {
  if (kind_ == Compression::None) return in;
  std::size_t bound = 0;
  LZ4F_preferences_t prefs{};
  prefs.frameInfo.contentSize = in.size();
  bound = kind_ == Compression::Zstd ? ZSTD_compressBound(in.size())
                                     : LZ4F_compressFrameBound(in.size(), &prefs);
  if (bound > state_->capacity) {
    // Grown once to the largest bound needed, never zero-filled.
    state_->buffer = std::make_unique_for_overwrite<char[]>(bound);
    state_->capacity = bound;
  }
  char* out = state_->buffer.get();
  std::size_t n = 0;
  if (kind_ == Compression::Zstd) {
    n = ZSTD_compress2(state_->zstd, out, bound, in.data(), in.size());
    if (ZSTD_isError(n) != 0U) {
      throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
    }
  } else {
    n = LZ4F_compressFrame(out, bound, in.data(), in.size(), &prefs);
    if (LZ4F_isError(n) != 0U) {
      throw std::runtime_error(std::string("lz4: ") + LZ4F_getErrorName(n));
    }
  }
  return {out, n};
}

namespace {

// The next output size: double what is there (at least 64 KiB), never past `expected`.
std::size_t grown(std::size_t have, std::uint64_t expected) {
  const std::uint64_t want =
      std::max<std::uint64_t>(std::uint64_t{64} << 10, 2 * std::uint64_t{have});
  return static_cast<std::size_t>(std::min(want, expected));
}

std::string sizeMismatch(std::uint64_t got, std::uint64_t expected, bool more) {
  return "the chunk's records decompress to " + std::string(more ? "more than " : "") +
         std::to_string(got) + " bytes, its uncompressed_size says " + std::to_string(expected);
}

// The output's size set to n (never zero-filled; what was produced is kept).
void resizeTo(Buffer& out, std::size_t n) {
  out.reserve(n);
  out.setSize(n);
}

std::optional<std::string> decompressZstd(ZSTD_DCtx* ctx, std::string_view in,
                                          std::uint64_t expected, Buffer& out) {
  ZSTD_DCtx_reset(ctx, ZSTD_reset_session_only);
  out.clear();
  // Sized from what the compressed bytes can hold at most, not from the claim alone.
  resizeTo(out, grown(std::min<std::uint64_t>(expected, 16 * std::uint64_t{in.size()}), expected));
  ZSTD_inBuffer src{in.data(), in.size(), 0};
  std::size_t produced = 0;
  while (true) {
    ZSTD_outBuffer dst{out.data(), out.size(), produced};
    const std::size_t rc = ZSTD_decompressStream(ctx, &dst, &src);
    if (ZSTD_isError(rc) != 0U) return std::string("zstd: ") + ZSTD_getErrorName(rc);
    produced = dst.pos;
    if (rc == 0 && src.pos == in.size()) break;  // a frame ended with the input
    if (produced == out.size()) {
      if (produced == expected) {
        // Full: anything still to come is too much.
        char probe = 0;
        ZSTD_outBuffer extra{&probe, 1, 0};
        const std::size_t more = ZSTD_decompressStream(ctx, &extra, &src);
        if (ZSTD_isError(more) != 0U) return std::string("zstd: ") + ZSTD_getErrorName(more);
        if (extra.pos > 0) return sizeMismatch(expected, expected, true);
        if (more == 0 && src.pos == in.size()) break;
        if (src.pos == in.size())
          return std::string("zstd: the compressed data ends inside a frame");
        continue;
      }
      resizeTo(out, grown(out.size(), expected));
    } else if (src.pos == in.size()) {
      if (rc != 0) return std::string("zstd: the compressed data ends inside a frame");
      break;
    }
  }
  if (produced != expected) return sizeMismatch(produced, expected, false);
  out.setSize(produced);
  return std::nullopt;
}

std::optional<std::string> decompressLz4(LZ4F_dctx* ctx, std::string_view in,
                                         std::uint64_t expected, Buffer& out) {
  LZ4F_resetDecompressionContext(ctx);
  out.clear();
  resizeTo(out, grown(std::min<std::uint64_t>(expected, 16 * std::uint64_t{in.size()}), expected));
  std::size_t consumed = 0;
  std::size_t produced = 0;
  std::size_t hint = 1;
  while (consumed < in.size()) {
    if (produced == out.size()) {
      if (produced == expected) return sizeMismatch(expected, expected, true);
      resizeTo(out, grown(out.size(), expected));
    }
    std::size_t dstSize = out.size() - produced;
    std::size_t srcSize = in.size() - consumed;
    hint = LZ4F_decompress(ctx, out.data() + produced, &dstSize, in.data() + consumed, &srcSize,
                           nullptr);
    if (LZ4F_isError(hint) != 0U) return std::string("lz4: ") + LZ4F_getErrorName(hint);
    consumed += srcSize;
    produced += dstSize;
    if (srcSize == 0 && dstSize == 0 && produced < out.size()) {
      return std::string("lz4: the decoder made no progress");
    }
    if (hint == 0 && consumed < in.size()) {
      // A frame ended; another may follow (LZ4F resets itself after a frame).
      continue;
    }
  }
  // Output the decoder still holds (it may have filled the buffer exactly).
  while (hint != 0) {
    if (produced == out.size()) {
      if (produced == expected) {
        char probe = 0;
        std::size_t one = 1;
        std::size_t none = 0;
        hint = LZ4F_decompress(ctx, &probe, &one, nullptr, &none, nullptr);
        if (LZ4F_isError(hint) != 0U) return std::string("lz4: ") + LZ4F_getErrorName(hint);
        if (one > 0) return sizeMismatch(expected, expected, true);
        if (hint != 0) return std::string("lz4: the compressed data ends inside a frame");
        break;
      }
      resizeTo(out, grown(out.size(), expected));
    }
    std::size_t dstSize = out.size() - produced;
    std::size_t srcSize = 0;
    hint = LZ4F_decompress(ctx, out.data() + produced, &dstSize, nullptr, &srcSize, nullptr);
    if (LZ4F_isError(hint) != 0U) return std::string("lz4: ") + LZ4F_getErrorName(hint);
    produced += dstSize;
    if (dstSize == 0 && hint != 0)
      return std::string("lz4: the compressed data ends inside a frame");
  }
  if (produced != expected) return sizeMismatch(produced, expected, false);
  out.setSize(produced);
  return std::nullopt;
}

}  // namespace

struct Decompressor::State {
  ZSTD_DCtx* zstd = nullptr;
  LZ4F_dctx* lz4 = nullptr;
  ~State() {
    ZSTD_freeDCtx(zstd);
    if (lz4 != nullptr) LZ4F_freeDecompressionContext(lz4);
  }
};

Decompressor::Decompressor() : state_(std::make_unique<State>()) {}
Decompressor::~Decompressor() = default;

std::optional<std::string> Decompressor::decompress(Compression c, std::string_view in,
                                                    std::uint64_t expectedSize, Buffer& out) {
  switch (c) {
    case Compression::None:
      if (in.size() != expectedSize) return sizeMismatch(in.size(), expectedSize, false);
      out.clear();
      out.append(in);
      return std::nullopt;
    case Compression::Zstd:
      if (state_->zstd == nullptr) {
        state_->zstd = ZSTD_createDCtx();
        if (state_->zstd == nullptr) throw std::bad_alloc();
      }
      return decompressZstd(state_->zstd, in, expectedSize, out);
    case Compression::Lz4:
      if (state_->lz4 == nullptr &&
          LZ4F_isError(LZ4F_createDecompressionContext(&state_->lz4, LZ4F_VERSION)) != 0U) {
        state_->lz4 = nullptr;
        throw std::bad_alloc();
      }
      return decompressLz4(state_->lz4, in, expectedSize, out);
  }
  return std::string("unknown compression");
}

}  // namespace tactile::mcap
