// Known answers for the row checksums (docs/storage.md#checksums), independent of the writer:
// the expected values of a few hand-written rows were computed outside this code (Python's
// zlib.crc32 over the documented byte layout, struct.pack), and a bitwise CRC-32 over the same
// layout, written here from the documentation, checks a change of every field. A checksum that
// skips a field (say `omega`) fails both.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "storage/sqlite/sqlite_connection.h"
#include "storage/step_checksum.h"

namespace tactile::storage {
namespace {
namespace checksum_known {  // its own names in a unity build

// ---- the reference, from the documented layout -------------------------------------------------

// CRC-32 bit by bit (reflected IEEE polynomial 0xEDB88320, initial and final inversion).
std::uint32_t bitwiseCrc32(const std::vector<unsigned char>& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char byte : bytes) {
    crc ^= byte;
    for (int k = 0; k < 8; ++k)
      crc = (crc & 1u) != 0 ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
  }
  return ~crc;
}

void put64(std::vector<unsigned char>& out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i)
    out.push_back(static_cast<unsigned char>((value >> (8 * i)) & 0xFFu));
}

void putBlob(std::vector<unsigned char>& out, const std::optional<std::string>& blob) {
  put64(out, blob ? blob->size() : std::numeric_limits<std::uint64_t>::max());
  if (blob) out.insert(out.end(), blob->begin(), blob->end());
}

// One steps row as plain values (a blob as bytes in a string, NULL as nullopt).
struct Row {
  std::int64_t runId = 0;
  std::int64_t step = 0;
  double x = 0, y = 0, theta = 0, v = 0, omega = 0;
  std::int64_t blocked = 0;
  std::string sensors;
  std::optional<std::string> extra;
  std::optional<std::int64_t> truth;
};

std::int32_t referenceChecksum(const Row& r) {
  std::vector<unsigned char> bytes;
  put64(bytes, static_cast<std::uint64_t>(r.runId));
  put64(bytes, static_cast<std::uint64_t>(r.step));
  for (double value : {r.x, r.y, r.theta, r.v, r.omega})
    put64(bytes, std::bit_cast<std::uint64_t>(value));
  put64(bytes, static_cast<std::uint64_t>(r.blocked));
  put64(bytes,
        r.truth ? static_cast<std::uint64_t>(*r.truth) : std::numeric_limits<std::uint64_t>::max());
  put64(bytes, r.truth ? 1u : 0u);
  putBlob(bytes, r.sensors);
  putBlob(bytes, r.extra);
  return static_cast<std::int32_t>(bitwiseCrc32(bytes));
}

std::int32_t productChecksum(const Row& r) {
  StepRow row;
  row.runId = r.runId;
  row.step = r.step;
  row.x = r.x;
  row.y = r.y;
  row.theta = r.theta;
  row.v = r.v;
  row.omega = r.omega;
  row.blocked = r.blocked;
  row.sensors = r.sensors.data();
  row.sensorBytes = r.sensors.size();
  if (r.extra) {
    row.extra = r.extra->data();
    row.extraBytes = r.extra->size();
  }
  row.hasTruth = r.truth.has_value();
  row.truth = r.truth.value_or(0);
  return stepChecksum(row);
}

// ---- hand-written rows
// ----------------------------------------------------------------------------

Row rowA() {
  Row r;
  r.runId = 1;
  r.step = 0;
  r.x = 1.5;
  r.y = -2.25;
  r.theta = 0.5;
  r.v = 100.0;
  r.omega = -0.125;
  r.blocked = 0;
  r.sensors = std::string("\x01\x02\x03\x04\x05\x06\x07\x08", 8);
  return r;  // extra NULL, truth NULL
}

Row rowB() {
  Row r;
  r.runId = 7;
  r.step = 123456;
  r.x = 0.1;
  r.y = 1e300;
  r.theta = -0.0;
  r.v = 0.0;
  r.omega = 3.0;
  r.blocked = 1;
  r.sensors = std::string("\x00\x00\x80\x3f\x00\x00\x00\xc0", 8);
  r.extra = "note";
  r.truth = 5;
  return r;
}

Row rowC() {
  Row r;
  r.runId = 2;
  r.step = 41;
  r.extra = "";  // an empty blob, not NULL
  r.truth = 0;
  return r;
}

TEST(StepChecksumKnownAnswer, TheReferenceCrcIsTheStandardOne) {
  const std::string check = "123456789";
  EXPECT_EQ(bitwiseCrc32({check.begin(), check.end()}), 0xCBF43926u);
}

// Values computed by Python's zlib.crc32 over struct.pack of the documented layout.
// crc32 against the bitwise reference at every length up to 600 bytes and every alignment, in one
// call and continued over two: 16-byte blocks folded with carry-less multiplication (from 64
// bytes, where the processor has it), 8 bytes a step from the tables, and the bytes left.
TEST(StepChecksumKnownAnswer, Crc32IsTheBitwiseOneAtEveryLengthAndAlignment) {
  std::vector<unsigned char> bytes(608);
  std::uint32_t state = 12345;
  for (unsigned char& b : bytes) {
    state = state * 1103515245u + 12345u;
    b = static_cast<unsigned char>(state >> 16);
  }
  for (std::size_t offset = 0; offset < 8; ++offset) {
    for (std::size_t n = 0; n <= 600; ++n) {
      const std::vector<unsigned char> part(
          bytes.begin() + static_cast<std::ptrdiff_t>(offset),
          bytes.begin() + static_cast<std::ptrdiff_t>(offset + n));
      const std::uint32_t expected = bitwiseCrc32(part);
      ASSERT_EQ(crc32(0, part.data(), n), expected) << n << " bytes at offset " << offset;
      const std::size_t split = n / 3;
      ASSERT_EQ(crc32(crc32(0, part.data(), split), part.data() + split, n - split), expected)
          << n << " bytes split at " << split;
    }
  }
}

TEST(StepChecksumKnownAnswer, HandWrittenRows) {
  EXPECT_EQ(productChecksum(rowA()), 1551069607);
  EXPECT_EQ(productChecksum(rowB()), 1951361881);
  EXPECT_EQ(productChecksum(rowC()), 584465392);
  Row omega = rowA();
  omega.omega = 0.125;
  EXPECT_EQ(productChecksum(omega), 1118537673);
  // The in-test reference agrees with the outside values (so the next test checks the layout).
  EXPECT_EQ(referenceChecksum(rowA()), 1551069607);
  EXPECT_EQ(referenceChecksum(rowB()), 1951361881);
  EXPECT_EQ(referenceChecksum(rowC()), 584465392);
  EXPECT_EQ(referenceChecksum(omega), 1118537673);
}

TEST(StepChecksumKnownAnswer, EveryFieldChangedOnceChangesTheChecksum) {
  struct Change {
    const char* field;
    std::function<void(Row&)> apply;
  };
  const std::vector<Change> changes{
      {"runId", [](Row& r) { r.runId += 1; }},
      {"step", [](Row& r) { r.step += 1; }},
      {"x", [](Row& r) { r.x = std::nextafter(r.x, 1e9); }},
      {"y", [](Row& r) { r.y = std::nextafter(r.y, 1e9); }},
      {"theta", [](Row& r) { r.theta = std::nextafter(r.theta, 1e9); }},
      {"v", [](Row& r) { r.v = std::nextafter(r.v, 1e9); }},
      {"omega", [](Row& r) { r.omega = std::nextafter(r.omega, 1e9); }},
      {"omega sign", [](Row& r) { r.omega = -r.omega; }},
      {"blocked", [](Row& r) { r.blocked = 1 - r.blocked; }},
      {"sensors byte", [](Row& r) { r.sensors[3] ^= 0x10; }},
      {"sensors length", [](Row& r) { r.sensors.push_back('\0'); }},
      {"extra NULL/empty",
       [](Row& r) { r.extra = r.extra ? std::nullopt : std::optional<std::string>(""); }},
      {"extra text", [](Row& r) { r.extra = r.extra.value_or("") + "!"; }},
      {"truth NULL/0",
       [](Row& r) { r.truth = r.truth ? std::nullopt : std::optional<std::int64_t>(0); }},
      {"truth value", [](Row& r) { r.truth = r.truth.value_or(0) + 1; }},
  };
  for (const Row& base : {rowA(), rowB(), rowC()}) {
    const std::int32_t original = productChecksum(base);
    ASSERT_EQ(original, referenceChecksum(base));
    for (const Change& c : changes) {
      Row changed = base;
      c.apply(changed);
      if (c.field == std::string("sensors byte") && changed.sensors.empty()) continue;
      SCOPED_TRACE(::testing::Message() << "row " << base.runId << ", " << c.field);
      EXPECT_NE(productChecksum(changed), original);
      EXPECT_EQ(productChecksum(changed), referenceChecksum(changed));
    }
  }
}

// The SQL function `db check` recomputes rows with gives the same known answers (rows whose
// numbers SQL literals hold exactly).
TEST(StepChecksumKnownAnswer, SqlFunctionGivesTheSameValues) {
  db::Connection c = db::Connection::open(":memory:", true);
  registerChecksumFunctions(c);
  EXPECT_EQ(c.queryInt("SELECT tactile_step_crc(1, 0, 1.5, -2.25, 0.5, 100.0, -0.125, 0, "
                       "X'0102030405060708', NULL, NULL)"),
            1551069607);
  EXPECT_EQ(c.queryInt("SELECT tactile_step_crc(2, 41, 0.0, 0.0, 0.0, 0.0, 0.0, 0, X'', X'', 0)"),
            584465392);
}

// Summary blocks and run rows, likewise from Python's zlib.crc32.
TEST(StepChecksumKnownAnswer, BlockAndRunRows) {
  EXPECT_EQ(blockChecksum(3, 2, 17, "\x01\x02\x03\x04\x05", 5), -259539260);
  const std::string metadata(
      "\x02\x00\x00\x00"
      "dt",
      6);
  EXPECT_EQ(runChecksum(4, "run_0001", 300, true, metadata.data(), metadata.size(), "", 0),
            1330256245);
}

}  // namespace checksum_known
}  // namespace
}  // namespace tactile::storage
