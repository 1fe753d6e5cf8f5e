#include "storage/step_checksum.h"

#include "storage/sqlite/sqlite_connection.h"

#include <sqlite3.h>

#include <array>
#include <bit>
#include <cstring>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define TACTILE_CRC32_CLMUL 1
#endif

namespace tactile::storage {
namespace {

static_assert(std::endian::native == std::endian::little, "crc32 reads little-endian words");

// Slicing-by-8 tables: table[0] is the classic byte-at-a-time table, table[k] advances a byte
// that is k positions further ahead.
constexpr std::array<std::array<std::uint32_t, 256>, 8> makeTables() {
  std::array<std::array<std::uint32_t, 256>, 8> t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k)
      c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[0][i] = c;
  }
  for (std::uint32_t i = 0; i < 256; ++i) {
    for (std::size_t k = 1; k < 8; ++k)
      t[k][i] = (t[k - 1][i] >> 8) ^ t[0][t[k - 1][i] & 0xffu];
  }
  return t;
}

constexpr auto kTables = makeTables();

// The table-driven CRC of `bytes` bytes, on the state `crc` (already inverted).
std::uint32_t crc32Tables(std::uint32_t crc, const unsigned char* p, std::size_t bytes) {
  while (bytes >= 8) {
    std::uint32_t lo = 0;
    std::uint32_t hi = 0;
    std::memcpy(&lo, p, 4);  // little-endian words (storage assumes a little-endian host)
    std::memcpy(&hi, p + 4, 4);
    lo ^= crc;
    crc = kTables[7][lo & 0xffu] ^ kTables[6][(lo >> 8) & 0xffu] ^ kTables[5][(lo >> 16) & 0xffu] ^
          kTables[4][lo >> 24] ^ kTables[3][hi & 0xffu] ^ kTables[2][(hi >> 8) & 0xffu] ^
          kTables[1][(hi >> 16) & 0xffu] ^ kTables[0][hi >> 24];
    p += 8;
    bytes -= 8;
  }
  while (bytes-- > 0)
    crc = kTables[0][(crc ^ *p++) & 0xffu] ^ (crc >> 8);
  return crc;
}

#ifdef TACTILE_CRC32_CLMUL
#define TACTILE_CLMUL __attribute__((target("pclmul,sse4.1")))

TACTILE_CLMUL inline __m128i load16(const unsigned char* at) {
  return _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
}

// `x` folded forward by the distance the constants `k` stand for (512 bits with k1:k2, 128 with
// k3:k4), plus `next`.
TACTILE_CLMUL inline __m128i fold16(__m128i x, __m128i k, __m128i next) {
  return _mm_xor_si128(_mm_xor_si128(_mm_clmulepi64_si128(x, k, 0x11), next),
                       _mm_clmulepi64_si128(x, k, 0x00));
}

// Blocks of 16 bytes folded with carry-less multiplication (PCLMULQDQ), then reduced to the
// 32-bit CRC: "Fast CRC Computation for Generic Polynomials Using PCLMULQDQ Instruction" (Gopal
// et al., Intel, 2009), with its constants for the reflected polynomial 0xEDB88320, as zlib's
// SIMD variants have it. `len` is at least 64 and a multiple of 16; `crc` is the inverted state,
// and so is the result. Run only where the processor has the instructions (hasClmul).
TACTILE_CLMUL std::uint32_t crc32Clmul(const unsigned char* buf, std::size_t len,
                                       std::uint32_t crc) {
  alignas(16) static constexpr std::uint64_t kK1K2[] = {0x0154442bd4, 0x01c6e41596};
  alignas(16) static constexpr std::uint64_t kK3K4[] = {0x01751997d0, 0x00ccaa009e};
  alignas(16) static constexpr std::uint64_t kK5K0[] = {0x0163cd6124, 0x0000000000};
  alignas(16) static constexpr std::uint64_t kPoly[] = {0x01db710641, 0x01f7011641};
  __m128i x1 = _mm_xor_si128(load16(buf), _mm_cvtsi32_si128(static_cast<int>(crc)));
  __m128i x2 = load16(buf + 16);
  __m128i x3 = load16(buf + 32);
  __m128i x4 = load16(buf + 48);
  buf += 64;
  len -= 64;
  __m128i k = _mm_load_si128(reinterpret_cast<const __m128i*>(kK1K2));
  while (len >= 64) {
    x1 = fold16(x1, k, load16(buf));
    x2 = fold16(x2, k, load16(buf + 16));
    x3 = fold16(x3, k, load16(buf + 32));
    x4 = fold16(x4, k, load16(buf + 48));
    buf += 64;
    len -= 64;
  }
  k = _mm_load_si128(reinterpret_cast<const __m128i*>(kK3K4));
  x1 = fold16(x1, k, x2);
  x1 = fold16(x1, k, x3);
  x1 = fold16(x1, k, x4);
  while (len >= 16) {
    x1 = fold16(x1, k, load16(buf));
    buf += 16;
    len -= 16;
  }
  // 128 bits to 64.
  const __m128i low32 = _mm_setr_epi32(~0, 0, ~0, 0);
  x1 = _mm_xor_si128(_mm_srli_si128(x1, 8), _mm_clmulepi64_si128(x1, k, 0x10));
  k = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(kK5K0));
  x1 =
      _mm_xor_si128(_mm_clmulepi64_si128(_mm_and_si128(x1, low32), k, 0x00), _mm_srli_si128(x1, 4));
  // Barrett reduction to 32 bits.
  k = _mm_load_si128(reinterpret_cast<const __m128i*>(kPoly));
  __m128i q = _mm_clmulepi64_si128(_mm_and_si128(x1, low32), k, 0x10);
  q = _mm_clmulepi64_si128(_mm_and_si128(q, low32), k, 0x00);
  return static_cast<std::uint32_t>(_mm_extract_epi32(_mm_xor_si128(x1, q), 1));
}

bool hasClmul() {
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("sse4.1");
  }();
  return has;
}
#endif

// The fixed-size fields of a row, little-endian, into a buffer checksummed in one call.
class Fields {
 public:
  void add(std::uint64_t value) {
    for (int i = 0; i < 8; ++i)
      bytes_[size_++] = static_cast<unsigned char>(value >> (8 * i));
  }
  void add(double value) { add(std::bit_cast<std::uint64_t>(value)); }
  std::uint32_t crc(std::uint32_t crc) const { return crc32(crc, bytes_, size_); }

 private:
  unsigned char bytes_[128] = {};
  std::size_t size_ = 0;
};

// A blob as its length (or all ones for NULL) and its bytes.
std::uint32_t addBlob(std::uint32_t crc, const void* data, std::size_t bytes, bool isNull) {
  Fields length;
  length.add(isNull ? ~std::uint64_t{0} : static_cast<std::uint64_t>(bytes));
  crc = length.crc(crc);
  return bytes > 0 ? crc32(crc, data, bytes) : crc;
}

std::int32_t stored(std::uint32_t crc) {
  return static_cast<std::int32_t>(crc);
}

const void* blobOf(sqlite3_value* v, std::size_t& bytes) {
  const void* data = sqlite3_value_blob(v);
  bytes = static_cast<std::size_t>(sqlite3_value_bytes(v));
  return data;
}

void sqlStepCrc(sqlite3_context* context, int, sqlite3_value** argv) {
  StepRow row;
  row.runId = sqlite3_value_int64(argv[0]);
  row.step = sqlite3_value_int64(argv[1]);
  row.x = sqlite3_value_double(argv[2]);
  row.y = sqlite3_value_double(argv[3]);
  row.theta = sqlite3_value_double(argv[4]);
  row.v = sqlite3_value_double(argv[5]);
  row.omega = sqlite3_value_double(argv[6]);
  row.blocked = sqlite3_value_int64(argv[7]);
  row.sensors = blobOf(argv[8], row.sensorBytes);
  if (sqlite3_value_type(argv[9]) != SQLITE_NULL) {
    row.extra = blobOf(argv[9], row.extraBytes);
    if (row.extra == nullptr) row.extra = "";  // an empty blob is not NULL
  }
  row.hasTruth = sqlite3_value_type(argv[10]) != SQLITE_NULL;
  row.truth = sqlite3_value_int64(argv[10]);
  sqlite3_result_int64(context, stepChecksum(row));
}

void sqlBlockCrc(sqlite3_context* context, int, sqlite3_value** argv) {
  std::size_t bytes = 0;
  const void* data = blobOf(argv[3], bytes);
  sqlite3_result_int64(context,
                       blockChecksum(sqlite3_value_int64(argv[0]), sqlite3_value_int64(argv[1]),
                                     sqlite3_value_int64(argv[2]), data, bytes));
}

void sqlRunCrc(sqlite3_context* context, int, sqlite3_value** argv) {
  const auto* nameText = reinterpret_cast<const char*>(sqlite3_value_text(argv[1]));
  const std::string_view name(nameText != nullptr ? nameText : "",
                              static_cast<std::size_t>(sqlite3_value_bytes(argv[1])));
  std::size_t metadataBytes = 0;
  std::size_t extraBytes = 0;
  const void* metadata = blobOf(argv[4], metadataBytes);
  const void* extra = blobOf(argv[5], extraBytes);
  sqlite3_result_int64(
      context,
      runChecksum(sqlite3_value_int64(argv[0]), name, sqlite3_value_int64(argv[2]),
                  sqlite3_value_int64(argv[3]) != 0, metadata, metadataBytes, extra, extraBytes));
}

}  // namespace

std::uint32_t crc32(std::uint32_t crc, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  crc = ~crc;
#ifdef TACTILE_CRC32_CLMUL
  // A row's sensors blob and fixed fields (64 bytes and more) three times faster than the tables.
  if (bytes >= 64 && hasClmul()) {
    const std::size_t blocks = bytes & ~std::size_t{15};
    crc = crc32Clmul(p, blocks, crc);
    p += blocks;
    bytes -= blocks;
  }
#endif
  return ~crc32Tables(crc, p, bytes);
}

std::int32_t stepChecksum(const StepRow& row) {
  Fields fields;
  fields.add(static_cast<std::uint64_t>(row.runId));
  fields.add(static_cast<std::uint64_t>(row.step));
  for (double value : {row.x, row.y, row.theta, row.v, row.omega})
    fields.add(value);
  fields.add(static_cast<std::uint64_t>(row.blocked));
  fields.add(row.hasTruth ? static_cast<std::uint64_t>(row.truth) : ~std::uint64_t{0});
  fields.add(std::uint64_t{row.hasTruth ? 1u : 0u});
  std::uint32_t crc = fields.crc(0);
  crc = addBlob(crc, row.sensors, row.sensorBytes, false);
  crc = addBlob(crc, row.extra, row.extraBytes, row.extra == nullptr);
  return stored(crc);
}

std::int32_t blockChecksum(std::int64_t runId, std::int64_t level, std::int64_t block,
                           const void* minmax, std::size_t bytes) {
  Fields fields;
  fields.add(static_cast<std::uint64_t>(runId));
  fields.add(static_cast<std::uint64_t>(level));
  fields.add(static_cast<std::uint64_t>(block));
  return stored(addBlob(fields.crc(0), minmax, bytes, false));
}

std::int32_t runChecksum(std::int64_t runId, std::string_view name, std::int64_t stepCount,
                         bool hasTruth, const void* metadata, std::size_t metadataBytes,
                         const void* extraColumns, std::size_t extraColumnsBytes) {
  Fields fields;
  fields.add(static_cast<std::uint64_t>(runId));
  fields.add(static_cast<std::uint64_t>(stepCount));
  fields.add(std::uint64_t{hasTruth ? 1u : 0u});
  std::uint32_t crc = fields.crc(0);
  crc = addBlob(crc, name.data(), name.size(), false);
  crc = addBlob(crc, metadata, metadataBytes, false);
  crc = addBlob(crc, extraColumns, extraColumnsBytes, false);
  return stored(crc);
}

void registerChecksumFunctions(db::Connection& connection) {
  struct Function {
    const char* name;
    int arguments;
    void (*fn)(sqlite3_context*, int, sqlite3_value**);
  };
  for (const Function& f :
       {Function{"tactile_step_crc", 11, sqlStepCrc}, Function{"tactile_block_crc", 4, sqlBlockCrc},
        Function{"tactile_run_crc", 6, sqlRunCrc}}) {
    const int rc = sqlite3_create_function_v2(sqliteHandle(connection), f.name, f.arguments,
                                              SQLITE_UTF8 | SQLITE_DETERMINISTIC, nullptr, f.fn,
                                              nullptr, nullptr, nullptr);
    if (rc != SQLITE_OK) {
      throw db::DbError(connection.file(),
                        std::string("cannot register ") + f.name + ": " + sqlite3_errstr(rc));
    }
  }
}

}  // namespace tactile::storage
