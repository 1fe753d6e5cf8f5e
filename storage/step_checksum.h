// Checksums of the stored run data (docs/storage.md#checksums): every steps row, every summary
// block row and every run row carries a CRC-32 of its content, written with the row and verified
// whenever the row is read and by `db check`, so that a flipped bit in the file is reported instead
// of being read back as a different value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "storage/db.h"

namespace tactile::storage {

// CRC-32 (IEEE 802.3 polynomial, reflected, as zlib's crc32): `crc` is the value so far (0 to
// start).
std::uint32_t crc32(std::uint32_t crc, const void* data, std::size_t bytes);

// The columns of one steps row. `extra` is null for SQL NULL; `hasTruth` false for a NULL truth.
struct StepRow {
  std::int64_t runId = 0;
  std::int64_t step = 0;
  double x = 0.0, y = 0.0, theta = 0.0, v = 0.0, omega = 0.0;
  std::int64_t blocked = 0;
  const void* sensors = nullptr;
  std::size_t sensorBytes = 0;
  const void* extra = nullptr;
  std::size_t extraBytes = 0;
  bool hasTruth = false;
  std::int64_t truth = 0;
};

// The step row of run `runId` under `s`, read from the columns `step, x, y, theta, v, omega,
// blocked, sensors, extra, truth` starting at column 0 (every read of whole step rows selects them
// in this order, then `crc`). The blobs point into `s`'s row: valid until it steps on.
inline StepRow stepRowAt(const db::Statement& s, std::int64_t runId) {
  StepRow row;
  row.runId = runId;
  row.step = s.columnInt(0);
  row.x = s.columnDouble(1);
  row.y = s.columnDouble(2);
  row.theta = s.columnDouble(3);
  row.v = s.columnDouble(4);
  row.omega = s.columnDouble(5);
  row.blocked = s.columnInt(6);
  row.sensors = s.columnBlob(7);
  row.sensorBytes = s.columnBytes(7);
  if (!s.columnIsNull(8)) {
    row.extra = s.columnBlob(8);
    row.extraBytes = s.columnBytes(8);
    if (row.extra == nullptr) row.extra = "";  // an empty blob is not a missing one
  }
  row.hasTruth = !s.columnIsNull(9);
  row.truth = s.columnInt(9);
  return row;
}

// The stored checksum of a row: its CRC-32 as a signed 32-bit value (4 bytes in an SQLite record).
// Keys are included, so a row moved to another step or run by damage does not match either.
std::int32_t stepChecksum(const StepRow& row);
std::int32_t blockChecksum(std::int64_t runId, std::int64_t level, std::int64_t block,
                           const void* minmax, std::size_t bytes);
// Of the run row's fields that identify and make up the run as exported (id, name, step count,
// truth flag, metadata and x_ column names).
std::int32_t runChecksum(std::int64_t runId, std::string_view name, std::int64_t stepCount,
                         bool hasTruth, const void* metadata, std::size_t metadataBytes,
                         const void* extraColumns, std::size_t extraColumnsBytes);

// Registers tactile_step_crc(run_id, step, x, y, theta, v, omega, blocked, sensors, extra, truth),
// tactile_block_crc(run_id, level, block, minmax) and tactile_run_crc(id, name, step_count,
// has_truth, metadata, extra_columns) on a connection, for the migration that adds the checksums
// and for `db check`. Throws DbError.
void registerChecksumFunctions(db::Connection& connection);

}  // namespace tactile::storage
