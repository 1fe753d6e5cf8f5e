// Whole-run reads into caller-laid-out columns (storage/run_columns.h), and loadRun on top of it.
//
// The cost of a whole-run read is one pass over a million rows: per row, SQLite's column calls,
// the row's checksum and the sensors blob. The pass below makes one column call per stored value
// (no NULL tests on the usual rows), checksums the row as the writer did, and scatters a sparse
// blob's non-zero values straight to their targets. A row that does not match the usual shape
// (a NULL where a value is expected, a checksum that does not match) is checked again column by
// column, so that its error is the one loadWindow gives for the same row.
#include "storage/run_columns.h"

#include <array>
#include <atomic>
#include <bit>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>

#include "storage/database_impl.h"
#include "storage/run_codec.h"
#include "storage/step_checksum.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tactile::storage {
namespace {

// The error for stored data that does not match its checksum (docs/storage.md#checksums).
db::DbError damaged(const RunDatabase::Impl& impl, const std::string& runName, std::int64_t runId,
                    const std::string& what) {
  return db::DbError(impl.path.string(),
                     "run '" + runName + "' (id " + std::to_string(runId) +
                         ") is damaged: " + what +
                         " does not match its checksum; nothing of it is read (`tactile db "
                         "check` lists the damage)");
}

RunShape readShape(RunDatabase::Impl& impl, std::int64_t runId) {
  db::Statement& s = impl.statement(
      "SELECT step_count, has_truth, metadata, extra_columns, name, crc FROM runs WHERE id = ?");
  s.bind(1, runId);
  if (!s.step()) throw db::DbError("no run with id " + std::to_string(runId));
  RunShape shape;
  shape.steps = s.columnInt(0);
  shape.hasTruth = s.columnInt(1) != 0;
  shape.name = s.columnText(4);
  shape.checksum = s.columnIsNull(5) ? 0 : s.columnInt(5);
  if (s.columnIsNull(5) ||
      s.columnInt(5) != runChecksum(runId, shape.name, shape.steps, shape.hasTruth, s.columnBlob(2),
                                    s.columnBytes(2), s.columnBlob(3), s.columnBytes(3))) {
    throw damaged(impl, shape.name, runId, "the run's row (name, step count, metadata)");
  }
  std::vector<std::string> pairs;
  if (!decodeStrings(s.columnBlob(2), s.columnBytes(2), pairs) || pairs.size() % 2 != 0 ||
      !decodeStrings(s.columnBlob(3), s.columnBytes(3), shape.extraColumns)) {
    throw db::DbError("malformed metadata of run " + std::to_string(runId));
  }
  for (std::size_t i = 0; i < pairs.size(); i += 2)
    shape.metadata.emplace_back(std::move(pairs[i]), std::move(pairs[i + 1]));
  s.reset();
  return shape;
}

constexpr std::size_t kBitmapBytes = (kValuesPerStep + 7) / 8;
static_assert(kValuesPerStep % 8 == 0 && kBitmapBytes > 8 && kBitmapBytes <= 16,
              "a step's sparse bitmap is one 64-bit word and a partial second one");

// One step's sensors blob (run_codec.h: dense, or bitmap and non-zero values) into its targets;
// false when the blob is malformed, by decodeValues' rules. Value i of the blob is sensor i / 2's
// normal (i even) or shear (i odd) value.
bool decodeSensors(const unsigned char* p, std::size_t bytes, double* normal, double* shear,
                   std::ptrdiff_t sensorStride, bool zeroed) {
  double* const base[2] = {normal, shear};
  constexpr std::size_t kDense = 8 * kValuesPerStep;
  const bool interleaved = shear == normal + 1 && sensorStride == 2;
  if (bytes == kDense) {
    if (interleaved) {
      std::memcpy(normal, p, kDense);
    } else {
      for (std::size_t i = 0; i < kValuesPerStep; ++i)
        std::memcpy(base[i & 1] + static_cast<std::ptrdiff_t>(i >> 1) * sensorStride, p + 8 * i, 8);
    }
    return true;
  }
  if (bytes < kBitmapBytes || bytes >= kDense) return false;
  if (!zeroed) {
    if (interleaved) {
      std::memset(normal, 0, kDense);
    } else {
      for (std::ptrdiff_t k = 0; k < kSensorCount; ++k)
        normal[k * sensorStride] = shear[k * sensorStride] = 0.0;
    }
  }
  std::uint64_t words[2] = {0, 0};
  std::memcpy(&words[0], p, 8);
  std::memcpy(&words[1], p + 8, kBitmapBytes - 8);  // little-endian host (step_checksum.cpp)
  const unsigned char* next = p + kBitmapBytes;
  const unsigned char* const end = p + bytes;
  for (int w = 0; w < 2; ++w) {
    for (std::uint64_t bits = words[w]; bits != 0; bits &= bits - 1) {
      const auto i = static_cast<std::size_t>(64 * w + std::countr_zero(bits));
      // A bit past the last value, or more bits than values stored: malformed.
      if (i >= kValuesPerStep || end - next < 8) return false;
      std::memcpy(base[i & 1] + static_cast<std::ptrdiff_t>(i >> 1) * sensorStride, next, 8);
      next += 8;
    }
  }
  return next == end;  // as many values as bits
}

// A row the usual pass could not confirm, checked column by column in loadWindow's order with its
// messages: throws unless the row is sound and is step `t` of `n`.
void recheckRow(const RunDatabase::Impl& impl, const db::Statement& s, const RunShape& shape,
                std::int64_t runId, std::size_t t, std::size_t n) {
  const StepRow row = stepRowAt(s, runId);
  if (s.columnIsNull(10) || s.columnInt(10) != stepChecksum(row)) {
    throw damaged(impl, shape.name, runId, "step " + std::to_string(row.step));
  }
  if (t >= n || row.step != static_cast<std::int64_t>(t)) {
    throw db::DbError("run " + std::to_string(runId) + " has a gap or extra row at step " +
                      std::to_string(row.step));
  }
  if (!shape.extraColumns.empty() && row.extra == nullptr) {
    throw db::DbError("malformed x_ values at step " + std::to_string(t));
  }
  if (shape.hasTruth && !row.hasTruth) {
    throw db::DbError("step " + std::to_string(t) + " of run " + std::to_string(runId) +
                      " has missing or malformed truth");
  }
}

constexpr char kStepsSql[] =
    "SELECT step, x, y, theta, v, omega, blocked, sensors, extra, truth, crc FROM steps "
    "WHERE run_id = ? ORDER BY step";

// What can be wrong with a row whose checksum matches.
enum class Fault { None, Sensors, Extra, Truth };

// Writes row `t`'s values to the targets.
Fault store(const StepRow& row, std::size_t t, const RunShape& shape, const RunColumns& out,
            bool zeroed) {
  const auto at = static_cast<std::ptrdiff_t>(t);
  out.x.data[at * out.x.stride] = row.x;
  out.y.data[at * out.y.stride] = row.y;
  out.theta.data[at * out.theta.stride] = row.theta;
  out.v.data[at * out.v.stride] = row.v;
  out.omega.data[at * out.omega.stride] = row.omega;
  out.blocked.data[at * out.blocked.stride] = static_cast<std::uint8_t>(row.blocked);
  if (!decodeSensors(static_cast<const unsigned char*>(row.sensors), row.sensorBytes,
                     out.normal + at * out.stepStride, out.shear + at * out.stepStride,
                     out.sensorStride, zeroed)) {
    return Fault::Sensors;
  }
  if (!shape.extraColumns.empty() && out.extraValues != nullptr &&
      !decodeExtra(row.extra, row.extraBytes, shape.extraColumns.size(), *out.extraValues)) {
    return Fault::Extra;
  }
  if (shape.hasTruth && !unpackTruth(row.truth, out.truth + t * kGroupCount)) return Fault::Truth;
  return Fault::None;
}

// Reads the columns of the usual row under `s`: x_ values exactly when the run has x_ columns,
// truth exactly when it has truth. Its checksum is computed on that assumption, so a row it does
// not hold for fails the comparison. Returns the stored checksum (0 for NULL).
std::int64_t readRow(const db::Statement& s, const RunShape& shape, StepRow& row) {
  row.step = s.columnInt(0);
  row.x = s.columnDouble(1);
  row.y = s.columnDouble(2);
  row.theta = s.columnDouble(3);
  row.v = s.columnDouble(4);
  row.omega = s.columnDouble(5);
  row.blocked = s.columnInt(6);
  row.sensors = s.columnBlob(7);
  row.sensorBytes = s.columnBytes(7);
  if (!shape.extraColumns.empty()) {
    row.extra = s.columnBlob(8);
    row.extraBytes = s.columnBytes(8);
    if (row.extra == nullptr) row.extra = "";
  }
  if (shape.hasTruth) row.truth = s.columnInt(9);
  return s.columnInt(10);
}

// Whether the usual row is confirmed as step `t` of `n` by its checksum.
bool confirmed(const StepRow& row, std::int64_t stored, std::size_t t, std::size_t n) {
  return stored != 0 && t < n && row.step == static_cast<std::int64_t>(t) &&
         stored == stepChecksum(row);
}

// Every row on this thread; throws at the first one that is not sound, with loadWindow's message.
void readSteps(RunDatabase::Impl& impl, std::int64_t runId, const RunShape& shape,
               const RunColumns& out) {
  const auto n = static_cast<std::size_t>(shape.steps);
  db::Statement& s = impl.streamedStatement(kStepsSql);
  s.bind(1, runId);
  StepRow row;
  row.runId = runId;
  row.hasTruth = shape.hasTruth;
  std::size_t t = 0;
  while (s.step()) {
    if (!confirmed(row, readRow(s, shape, row), t, n)) recheckRow(impl, s, shape, runId, t, n);
    switch (store(row, t, shape, out, out.sensorsZeroed)) {
      case Fault::None:
        break;
      case Fault::Sensors:
        throw db::DbError("step " + std::to_string(t) + " of run " + std::to_string(runId) +
                          " has a malformed sensors blob");
      case Fault::Extra:
        throw db::DbError("malformed x_ values at step " + std::to_string(t));
      case Fault::Truth:
        throw db::DbError("step " + std::to_string(t) + " of run " + std::to_string(runId) +
                          " has missing or malformed truth");
    }
    ++t;
  }
  s.reset();
  if (t != n) {
    throw db::DbError("run " + std::to_string(runId) + " is missing steps from " +
                      std::to_string(t));
  }
}

// Rows copied off the statement, for the second thread.
constexpr std::size_t kChunkRows = 4096;
struct Chunk {
  std::size_t first = 0;  // the first row's index
  std::size_t count = 0;
  std::array<StepRow, kChunkRows> rows;  // blob pointers are set by the checker
  std::array<std::int64_t, kChunkRows> stored;
  std::array<std::size_t, kChunkRows> sensorsAt, extraAt;  // blob offsets into `bytes`
  std::vector<unsigned char> bytes;
};

// Chunks handed between the two threads: the reader fills free ones, the checker empties full
// ones. A null full chunk ends the read.
class ChunkQueue {
 public:
  Chunk* take(bool full) {
    std::unique_lock lock(mutex_);
    std::deque<Chunk*>& q = full ? full_ : free_;
    changed_.wait(lock, [&] { return !q.empty(); });
    Chunk* c = q.front();
    q.pop_front();
    return c;
  }
  void put(Chunk* c, bool full) {
    {
      const std::lock_guard lock(mutex_);
      (full ? full_ : free_).push_back(c);
    }
    changed_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Chunk*> free_, full_;
};

// Every row, walked on this thread while a second thread checks and stores them. False when some
// row is not the usual sound one (the caller then reads again with readSteps for the exact error);
// throws what the statement throws.
bool readStepsPipelined(RunDatabase::Impl& impl, std::int64_t runId, const RunShape& shape,
                        const RunColumns& out) {
  const auto n = static_cast<std::size_t>(shape.steps);
  const bool withExtra = !shape.extraColumns.empty();
  constexpr int kChunks = 4;
  std::vector<std::unique_ptr<Chunk>> chunks;
  ChunkQueue queue;
  for (int i = 0; i < kChunks; ++i) {
    chunks.push_back(std::make_unique<Chunk>());
    queue.put(chunks.back().get(), false);
  }
  std::atomic<bool> failed{false};
  std::size_t checked = 0;
  std::thread checker([&] {
    try {
      while (Chunk* c = queue.take(true)) {
        for (std::size_t i = 0; i < c->count && !failed.load(std::memory_order_relaxed); ++i) {
          StepRow& row = c->rows[i];
          const std::size_t t = c->first + i;
          row.sensors = c->bytes.data() + c->sensorsAt[i];
          if (withExtra) row.extra = c->bytes.data() + c->extraAt[i];
          if (!confirmed(row, c->stored[i], t, n) ||
              store(row, t, shape, out, out.sensorsZeroed) != Fault::None) {
            failed = true;
          }
        }
        checked += c->count;
        queue.put(c, false);
      }
    } catch (...) {  // no memory for x_ values: readSteps reports it
      failed = true;
      while (Chunk* c = queue.take(true))
        queue.put(c, false);
    }
  });
  // Ends the checker when the statement throws.
  struct Join {
    ChunkQueue& queue;
    std::thread& thread;
    ~Join() {
      if (!thread.joinable()) return;
      queue.put(nullptr, true);
      thread.join();
    }
  } const join{queue, checker};

  db::Statement& s = impl.streamedStatement(kStepsSql);
  s.bind(1, runId);
  std::size_t t = 0;
  bool more = true;
  while (more && !failed.load(std::memory_order_relaxed)) {
    Chunk* c = queue.take(false);
    c->first = t;
    c->count = 0;
    c->bytes.clear();
    while (c->count < kChunkRows && (more = s.step())) {
      StepRow& row = c->rows[c->count];
      row.runId = runId;
      row.hasTruth = shape.hasTruth;
      c->stored[c->count] = readRow(s, shape, row);
      // The blobs are valid until the next step: copied, and their offsets kept.
      const auto* sensors = static_cast<const unsigned char*>(row.sensors);
      c->sensorsAt[c->count] = c->bytes.size();
      c->bytes.insert(c->bytes.end(), sensors, sensors + row.sensorBytes);
      if (withExtra) {
        const auto* extra = static_cast<const unsigned char*>(row.extra);
        c->extraAt[c->count] = c->bytes.size();
        c->bytes.insert(c->bytes.end(), extra, extra + row.extraBytes);
      }
      ++c->count;
      ++t;
    }
    queue.put(c, true);
  }
  s.reset();
  queue.put(nullptr, true);
  checker.join();
  return !failed && t == n && checked == n;
}

// ---- A long run of an SQLite file, on two connections ----
//
// SQLite lets any number of connections read one file at once, each from its own snapshot. This
// thread and a second one each step ranges of the run's steps on their own connection, checking
// and storing every row themselves: the rows' SQLite walk, checksums and decoding are all split
// between two cores. Both connections read inside one read transaction each; the second one reads
// only when the run's row it sees is the one this thread's snapshot holds (same step count and
// checksum), and leaves every range to this thread otherwise.

// Steps per range. The ranges are handed out in order as the threads ask for them, so a thread
// that gets less of the machine (other processes) reads fewer of them.
constexpr std::int64_t kRangeSteps = 16384;

// Without the step: the rows come in step order, and each is taken as the next step, which its
// checksum confirms (a missing row makes the rows after it fail theirs). The range ends by a
// count (LIMIT) rather than by comparing each row's key with its last step.
constexpr char kRangeSql[] =
    "SELECT x, y, theta, v, omega, blocked, sensors, extra, truth, crc FROM steps "
    "WHERE run_id = ?1 AND step >= ?2 ORDER BY step LIMIT ?3";

// readRow for a row of kRangeSql taken as step `t`.
std::int64_t readRangeRow(const db::Statement& s, const RunShape& shape, std::size_t t,
                          StepRow& row) {
  row.step = static_cast<std::int64_t>(t);
  row.x = s.columnDouble(0);
  row.y = s.columnDouble(1);
  row.theta = s.columnDouble(2);
  row.v = s.columnDouble(3);
  row.omega = s.columnDouble(4);
  row.blocked = s.columnInt(5);
  row.sensors = s.columnBlob(6);
  row.sensorBytes = s.columnBytes(6);
  if (!shape.extraColumns.empty()) {
    row.extra = s.columnBlob(7);
    row.extraBytes = s.columnBytes(7);
    if (row.extra == nullptr) row.extra = "";
  }
  if (shape.hasTruth) row.truth = s.columnInt(8);
  return s.columnInt(9);
}

// The ranges shared by the two threads, and the x_ values of each range when they are kept.
struct SharedRanges {
  std::size_t count = 0;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::vector<std::vector<std::string>> extraValues;  // one per range, or none
};

// The steps [first, last) into their targets; false when some row is not the usual sound one or
// is missing.
bool readRange(db::Statement& s, std::int64_t runId, const RunShape& shape, const RunColumns& out,
               std::size_t first, std::size_t last) {
  const auto n = static_cast<std::size_t>(shape.steps);
  s.bind(1, runId)
      .bind(2, static_cast<std::int64_t>(first))
      .bind(3, static_cast<std::int64_t>(last - first));
  StepRow row;
  row.runId = runId;
  row.hasTruth = shape.hasTruth;
  std::size_t t = first;
  bool sound = true;
  while (sound && s.step()) {
    sound = t < last && confirmed(row, readRangeRow(s, shape, t, row), t, n) &&
            store(row, t, shape, out, out.sensorsZeroed) == Fault::None;
    ++t;
  }
  s.reset();
  return sound && t == last;
}

// Takes ranges off `shared` and reads them on `connection` until none is left or one fails (then
// `shared.failed` is set, and the other thread stops at its next range).
void readRanges(db::Connection& connection, std::int64_t runId, const RunShape& shape,
                const RunColumns& out, SharedRanges& shared) {
  try {
    db::Statement s(connection, kRangeSql);
    RunColumns mine = out;
    const auto n = static_cast<std::size_t>(shape.steps);
    while (!shared.failed.load(std::memory_order_relaxed)) {
      const std::size_t r = shared.next.fetch_add(1, std::memory_order_relaxed);
      if (r >= shared.count) return;
      if (!shared.extraValues.empty()) mine.extraValues = &shared.extraValues[r];
      const std::size_t first = r * static_cast<std::size_t>(kRangeSteps);
      const std::size_t last = std::min(n, first + static_cast<std::size_t>(kRangeSteps));
      if (!readRange(s, runId, shape, mine, first, last)) shared.failed = true;
    }
  } catch (...) {  // a statement that failed, no memory for x_ values: the one-thread read says
    shared.failed = true;
  }
}

// Ends a read transaction opened with beginSnapshot.
struct SnapshotEnd {
  db::Connection& connection;
  ~SnapshotEnd() { connection.backend().endSnapshot(); }
};

// A second connection on the database's file, opened as the first was. Throws DbError.
db::Connection secondConnection(const RunDatabase::Impl& impl) {
  db::Connection c = db::Connection::open(impl.path, false, *impl.fileAccess);
  if (*impl.fileAccess == db::Access::ReadWrite) c.exec("PRAGMA query_only = ON");
  c.exec("PRAGMA cache_size = -" + std::to_string(impl.cacheKiB));
  c.exec("PRAGMA mmap_size = " + std::to_string(impl.mmapBytes));
  return c;
}

// Whether the run's row in the connection's snapshot is the one `shape` was read from.
bool sameRunRow(db::Connection& connection, std::int64_t runId, const RunShape& shape) {
  db::Statement s(connection, "SELECT step_count, crc FROM runs WHERE id = ?");
  s.bind(1, runId);
  const bool same = s.step() && !s.columnIsNull(1) && s.columnInt(0) == shape.steps &&
                    s.columnInt(1) == shape.checksum;
  s.reset();
  return same;
}

// Every row, on this thread (the main connection, inside its read transaction) and a second one.
// False when some row is not the usual sound one or a statement failed: the caller then reads
// again on one thread for the exact error.
bool readStepsOnTwoConnections(RunDatabase::Impl& impl, std::int64_t runId, const RunShape& shape,
                               const RunColumns& out) {
  const auto n = static_cast<std::size_t>(shape.steps);
  SharedRanges shared;
  shared.count = (n + kRangeSteps - 1) / kRangeSteps;
  const bool keepExtra = out.extraValues != nullptr && !shape.extraColumns.empty();
  if (keepExtra) shared.extraValues.resize(shared.count);
  std::thread second;
  try {
    second = std::thread([&] {
      // A second connection that cannot be opened, or whose snapshot holds another version of
      // the run, reads nothing: this thread reads every range.
      db::Connection* c = nullptr;
      try {
        if (!impl.secondReader.isOpen()) impl.secondReader = secondConnection(impl);
        c = &impl.secondReader;
        c->backend().beginSnapshot();
      } catch (...) {  // nothing may leave this thread
        impl.secondReader = db::Connection();
        return;
      }
      const SnapshotEnd end{*c};
      bool same = false;
      try {
        same = sameRunRow(*c, runId, shape);
      } catch (...) {
      }
      if (same) readRanges(*c, runId, shape, out, shared);
    });
  } catch (const std::system_error&) {  // no thread: this one reads every range
  }
  readRanges(impl.connection, runId, shape, out, shared);
  if (second.joinable()) second.join();
  if (shared.failed) return false;
  if (keepExtra) {
    for (std::vector<std::string>& values : shared.extraValues) {
      out.extraValues->insert(out.extraValues->end(), std::make_move_iterator(values.begin()),
                              std::make_move_iterator(values.end()));
    }
  }
  return true;
}

// Sizes a column for a whole run. On Linux a long column's pages are first asked to be huge
// ones: filling a 1,000,000-step run's 704 MB of sensor values then takes a few hundred page
// faults instead of about 170,000.
template <class T>
void sizeColumn(std::vector<T>& column, std::size_t n) {
  column.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kPage = 4096;
  const std::size_t bytes = n * sizeof(T);
  if (bytes >= (std::size_t{4} << 20)) {
    const auto start = (reinterpret_cast<std::uintptr_t>(column.data()) + kPage - 1) & ~(kPage - 1);
    const auto stop = (reinterpret_cast<std::uintptr_t>(column.data()) + bytes) & ~(kPage - 1);
    // Advice only: when the kernel declines, the column is filled with ordinary pages.
    if (stop > start) (void)madvise(reinterpret_cast<void*>(start), stop - start, MADV_HUGEPAGE);
  }
#endif
  column.resize(n);
}

}  // namespace

// Runs shorter than this are read on this thread alone: a second thread would not pay for itself.
constexpr std::int64_t kPipelinedSteps = 50000;

void readRunColumns(RunDatabase::Impl& impl, std::int64_t runId,
                    const std::function<RunColumns(const RunShape&)>& layout) {
  // An SQLite file read outside any transaction (a second connection would not see what an open
  // one wrote): the run's row and its steps from one snapshot, a long run on two connections.
  const bool twoThreads = std::thread::hardware_concurrency() >= 2;
  if (impl.fileAccess && !impl.connection.inTransaction()) {
    impl.connection.backend().beginSnapshot();
    const SnapshotEnd end{impl.connection};
    const RunShape shape = readShape(impl, runId);
    RunColumns out = layout(shape);
    if (shape.steps >= kPipelinedSteps && twoThreads) {
      const std::size_t extraBefore = out.extraValues != nullptr ? out.extraValues->size() : 0;
      if (readStepsOnTwoConnections(impl, runId, shape, out)) return;
      if (out.extraValues != nullptr) out.extraValues->resize(extraBefore);
      out.sensorsZeroed = false;
    }
    readSteps(impl, runId, shape, out);
    return;
  }
  const RunShape shape = readShape(impl, runId);
  RunColumns out = layout(shape);
  if (shape.steps >= kPipelinedSteps && twoThreads) {
    const std::size_t extraBefore = out.extraValues != nullptr ? out.extraValues->size() : 0;
    if (readStepsPipelined(impl, runId, shape, out)) return;
    // Some row is not sound: read again on this thread, which stops at it with its error.
    if (out.extraValues != nullptr) out.extraValues->resize(extraBefore);
    out.sensorsZeroed = false;
  }
  readSteps(impl, runId, shape, out);
}

Result<RunData> RunStore::load(std::int64_t runId) {
  return guarded<RunData>(*impl_, [&] {
    RunData run;
    readRunColumns(*impl_, runId, [&](const RunShape& shape) {
      const auto n = static_cast<std::size_t>(shape.steps);
      run.metadata = shape.metadata;
      run.extraColumns = shape.extraColumns;
      for (auto* column : {&run.x, &run.y, &run.theta, &run.v, &run.omega})
        sizeColumn(*column, n);
      sizeColumn(run.blocked, n);
      sizeColumn(run.sensors, n * kValuesPerStep);
      if (!run.extraColumns.empty()) run.extraValues.reserve(n * run.extraColumns.size());
      if (shape.hasTruth) sizeColumn(run.truth, n * kGroupCount);
      RunColumns columns;
      columns.normal = run.sensors.data();
      columns.shear = run.sensors.data() + 1;
      columns.stepStride = kValuesPerStep;
      columns.sensorStride = 2;
      columns.sensorsZeroed = true;  // resize value-initialises
      columns.x = {run.x.data(), 1};
      columns.y = {run.y.data(), 1};
      columns.theta = {run.theta.data(), 1};
      columns.v = {run.v.data(), 1};
      columns.omega = {run.omega.data(), 1};
      columns.blocked = {run.blocked.data(), 1};
      columns.truth = run.truth.data();
      columns.extraValues = &run.extraValues;
      return columns;
    });
    return run;
  });
}

}  // namespace tactile::storage
