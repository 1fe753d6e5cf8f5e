// Run import: worker threads read, hash, parse and encode files chunk by chunk; the calling
// thread writes each file in its own transaction as its chunks arrive.
#include <algorithm>
#include <atomic>
#include <bit>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>
#include <unordered_set>

#include "base/file_text.h"
#include "run/builtin_scenes.h"
#include "run/run_csv.h"
#include "storage/database_impl.h"
#include "storage/run_codec.h"

namespace tactile::storage {

static_assert(std::endian::native == std::endian::little,
              "the sensors BLOB is little-endian float64; add byte swapping for this platform");

std::string checksumHex(std::string_view bytes) {
  // Two independent multiply-xorshift lanes over 8-byte words (for instruction-level
  // parallelism), then the tail and the length, then a final avalanche.
  constexpr std::uint64_t kMul1 = 0x9E3779B97F4A7C15ull;
  constexpr std::uint64_t kMul2 = 0xC2B2AE3D27D4EB4Full;
  std::uint64_t a = 0x243F6A8885A308D3ull;
  std::uint64_t b = 0x13198A2E03707344ull;
  const char* p = bytes.data();
  std::size_t n = bytes.size();
  auto mix = [](std::uint64_t h, std::uint64_t w, std::uint64_t mul) {
    w *= mul;
    w ^= w >> 29;
    return (h ^ w) * kMul2 + 0x165667B19E3779F9ull;
  };
  while (n >= 16) {
    std::uint64_t w1 = 0;
    std::uint64_t w2 = 0;
    std::memcpy(&w1, p, 8);
    std::memcpy(&w2, p + 8, 8);
    a = mix(a, w1, kMul1);
    b = mix(b, w2, kMul2);
    p += 16;
    n -= 16;
  }
  std::uint64_t tail = 0;
  std::memcpy(&tail, p, std::min<std::size_t>(n, 8));
  a = mix(a, tail, kMul1);
  if (n > 8) {
    tail = 0;
    std::memcpy(&tail, p + 8, n - 8);
    b = mix(b, tail, kMul2);
  }
  std::uint64_t h = mix(a ^ std::rotl(b, 31), bytes.size(), kMul1);
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 33;
  char text[17];
  static constexpr char kHex[] = "0123456789abcdef";
  for (int i = 15; i >= 0; --i) {
    text[i] = kHex[h & 15];
    h >>= 4;
  }
  text[16] = '\0';
  return text;
}

namespace {

constexpr std::size_t kDefaultChunkBytes = std::size_t{4} << 20;

// What the writer needs of a file before its steps; made off the writer thread.
struct FileHead {
  std::string file;  // as given, for messages
  std::string name;
  std::string checksum;
  std::string error;  // non-empty: the file is rejected
  std::vector<std::string> warnings;
  RunData header;  // metadata and x_ column names, no steps
  bool hasTruth = false;
  std::size_t chunkCount = 0;
  std::string noStepsError;  // the reader's error for a file without rows; empty: allowed
  std::string sceneValue;    // the `scene` metadata value
  std::string sceneName;
  std::string sceneJson;  // empty when unresolved
  std::string sceneChecksum;
  std::string metadataBlob;
  std::string extraColumnsBlob;
};

// Consecutive steps of a run, parsed and encoded off the writer thread.
struct StepChunk {
  std::string error;  // non-empty: the file is rejected (the reader's message)
  RunData rows;       // no metadata
  std::size_t firstStep = 0;
  EncodedBlobs sensors;                   // one per step
  std::vector<std::int64_t> packedTruth;  // one per step when the run has truth
  std::vector<std::string> extraBlobs;    // one per step when there are x_ columns
  PartialSummary summary;                 // finest-level blocks of these steps
};

// Rejects runs that cannot be stored faithfully (hand-built ones; the reader checks files).
std::string validateRun(const RunData& run) {
  const std::size_t n = run.stepCount();
  if (run.y.size() != n || run.theta.size() != n || run.v.size() != n || run.omega.size() != n ||
      run.blocked.size() != n) {
    return "pose, command and blocked columns differ in length";
  }
  if (run.sensors.size() != n * kValuesPerStep) return "sensor values do not match the step count";
  if (!run.truth.empty() && run.truth.size() != n * kGroupCount) {
    return "truth classes do not match the step count";
  }
  if (run.extraValues.size() != n * run.extraColumns.size()) {
    return "x_ column values do not match the step count";
  }
  for (const auto* column : {&run.x, &run.y, &run.theta, &run.v, &run.omega, &run.sensors}) {
    for (double value : *column) {
      if (!std::isfinite(value)) return "a value is not finite";
    }
  }
  for (std::uint8_t b : run.blocked) {
    if (b > 1) return "blocked must be 0 or 1";
  }
  for (ContactClass c : run.truth) {
    if (static_cast<int>(c) >= kContactClassCount) return "unknown truth class";
  }
  return {};
}

void resolveScene(FileHead& head, const std::filesystem::path& baseDir,
                  const SceneResolver& resolver) {
  const std::string* scene = head.header.meta("scene");
  if (scene == nullptr || scene->empty()) return;
  head.sceneValue = *scene;
  std::string json;
  if (auto builtin = builtinSceneJson(*scene)) {
    json = std::string(*builtin);
  } else if (std::optional<std::string> resolved = resolver ? resolver(*scene) : std::nullopt) {
    json = std::move(*resolved);
  } else {
    std::filesystem::path scenePath(*scene);
    if (scenePath.is_relative()) scenePath = baseDir / scenePath;
    std::string error;
    if (!readFileText(scenePath, json, error)) {
      head.warnings.push_back("scene '" + *scene +
                              "' is neither a built-in scene nor a readable file (" +
                              scenePath.string() + "); the run is stored without its scene");
      return;
    }
  }
  const nlohmann::json parsed = nlohmann::json::parse(json, nullptr, false);
  if (parsed.is_discarded() || !parsed.is_object()) {
    head.warnings.push_back("scene '" + *scene +
                            "' is not a JSON object; the run is stored without its scene");
    return;
  }
  const auto name = parsed.find("name");
  head.sceneName = name != parsed.end() && name->is_string() ? name->get<std::string>() : *scene;
  head.sceneChecksum = checksumHex(json);
  head.sceneJson = std::move(json);
}

// Metadata blobs and the scene, from the header (metadata and x_ names) of a run.
void describeHead(FileHead& head, const std::filesystem::path& baseDir,
                  const SceneResolver& resolver) {
  // Length-prefixed bytes rather than JSON: metadata is kept byte for byte, even text that is not
  // valid UTF-8 (which a JSON library would refuse or alter).
  std::vector<std::string> pairs;
  for (const auto& [key, value] : head.header.metadata) {
    pairs.push_back(key);
    pairs.push_back(value);
  }
  head.metadataBlob = encodeExtra(pairs.data(), pairs.size());
  head.extraColumnsBlob =
      encodeExtra(head.header.extraColumns.data(), head.header.extraColumns.size());
  resolveScene(head, baseDir, resolver);
}

StepChunk encodeChunk(RunData rows, std::size_t firstStep, std::size_t extraColumns) {
  StepChunk chunk;
  chunk.firstStep = firstStep;
  const std::size_t n = rows.stepCount();
  chunk.sensors = encodeStepSensors(rows.sensors.data(), n);
  chunk.summary = summarizeSteps(rows.sensors.data(), firstStep, n);
  if (rows.hasTruth()) {
    chunk.packedTruth.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      chunk.packedTruth[i] = packTruth(rows.truth.data() + i * kGroupCount);
  }
  if (extraColumns > 0) {
    chunk.extraBlobs.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      chunk.extraBlobs[i] = encodeExtra(rows.extraValues.data() + i * extraColumns, extraColumns);
  }
  chunk.rows = std::move(rows);
  return chunk;
}

// Never throws: any failure (even out of memory on a worker thread) becomes the chunk's error.
StepChunk parseChunk(const RunCsvChunks& chunks, std::size_t index, const std::string& file) {
  try {
    RunCsvResult parsed = chunks.parse(index);
    if (!parsed.ok()) {
      StepChunk failed;
      failed.error = parsed.errorText();
      return failed;
    }
    return encodeChunk(std::move(parsed.value()), chunks.firstStep(index),
                       chunks.header().extraColumns.size());
  } catch (const std::exception& e) {
    StepChunk failed;
    failed.error = file + ": " + e.what();
    return failed;
  }
}

// The head of a file's text once split into chunks (the header read).
void describeText(FileHead& head, const RunCsvChunks& chunks, const SceneResolver& resolver) {
  if (const Error* error = chunks.error()) {
    head.error = error->text();
    return;
  }
  head.header.metadata = chunks.header().metadata;
  head.header.extraColumns = chunks.header().extraColumns;
  head.hasTruth = chunks.hasTruth();
  head.chunkCount = chunks.size();
  if (auto error = chunks.checkStepCount(0)) head.noStepsError = error->text();
  describeHead(head, std::filesystem::path(head.file).parent_path(), resolver);
}

// Writes one run in its own transaction: the run row, then the steps chunk by chunk as
// `takeChunk(i)` hands them over, then the summary blocks. A chunk with an error, or any failure,
// rolls everything back.
ImportOutcome writeRun(RunDatabase::Impl& impl, FileHead& head,
                       const std::function<StepChunk(std::size_t)>& takeChunk,
                       std::int64_t failAfterSteps) {
  ImportOutcome outcome;
  outcome.file = head.file;
  outcome.runName = head.name;
  outcome.warnings = std::move(head.warnings);
  if (!head.error.empty()) {
    outcome.message = std::move(head.error);
    return outcome;
  }
  const RunData& header = head.header;
  try {
    // The steps and block rows reference the run row written in this same transaction, so their
    // per-row foreign-key lookups can be skipped; the pragma only works outside a transaction and
    // is restored on every path.
    struct ForeignKeysOff {
      db::Connection& c;
      explicit ForeignKeysOff(db::Connection& connection) : c(connection) {
        c.exec("PRAGMA foreign_keys = OFF");
      }
      ~ForeignKeysOff() {
        try {
          c.exec("PRAGMA foreign_keys = ON");
        } catch (const std::exception&) {
        }
      }
    } foreignKeysOff(impl.connection);
    // The checksum and name are checked inside the write transaction: another process importing
    // into the same file at the same time may have stored this file or name since this one
    // looked (docs/storage.md#concurrency), and then it is skipped or refused, never a raw
    // UNIQUE-constraint error.
    db::Transaction transaction(impl.connection);
    {
      db::Statement& dup =
          impl.statement("SELECT id, name, step_count FROM runs WHERE checksum = ?");
      dup.bind(1, head.checksum);
      if (dup.step()) {
        outcome.status = ImportStatus::Skipped;
        outcome.runId = dup.columnInt(0);
        outcome.runName = dup.columnText(1);
        outcome.steps = dup.columnInt(2);
        outcome.message = head.file + ": already imported as run '" + outcome.runName +
                          "' (same checksum " + head.checksum + "); skipped";
        dup.reset();
        return outcome;
      }
      dup.reset();
    }
    {
      db::Statement& named = impl.statement("SELECT source_file FROM runs WHERE name = ?");
      named.bind(1, head.name);
      if (named.step()) {
        outcome.message = head.file + ": a run named '" + head.name +
                          "' already exists (imported from " + named.columnText(0) +
                          ", other content); not imported: give this batch a name prefix "
                          "(tactile import --prefix P names runs P_<stem>) or the file "
                          "another name (--name)";
        named.reset();
        return outcome;
      }
      named.reset();
    }

    std::int64_t sceneId = 0;
    if (!head.sceneJson.empty()) {
      impl.statement("INSERT OR IGNORE INTO scenes(name, checksum, json) VALUES(?, ?, ?)")
          .bind(1, head.sceneName)
          .bind(2, head.sceneChecksum)
          .bind(3, head.sceneJson)
          .run();
      db::Statement& id = impl.statement("SELECT id FROM scenes WHERE checksum = ?");
      id.bind(1, head.sceneChecksum);
      id.step();
      sceneId = id.columnInt(0);
      id.reset();
    }
    const std::string now = utcNow();
    // step_count is set once the steps are in.
    db::Statement& insertRun = impl.statement(
        "INSERT INTO runs(name, source_file, checksum, scene, scene_id, subject, outcome, dt, "
        "step_count, has_truth, metadata, extra_columns, imported_at) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, 0, ?, ?, ?, ?)");
    insertRun.bind(1, head.name).bind(2, head.file).bind(3, head.checksum);
    if (head.sceneValue.empty()) {
      insertRun.bindNull(4);
    } else {
      insertRun.bind(4, head.sceneValue);
    }
    if (sceneId != 0) {
      insertRun.bind(5, sceneId);
    } else {
      insertRun.bindNull(5);
    }
    const std::string* subject = header.meta("subject");
    if (subject != nullptr) {
      insertRun.bind(6, *subject);
    } else {
      insertRun.bindNull(6);
    }
    insertRun.bind(7, runOutcomeName(header.outcome()));
    if (auto dt = header.dtSeconds()) {
      insertRun.bind(8, *dt);
    } else {
      insertRun.bindNull(8);
    }
    insertRun.bind(9, head.hasTruth ? 1 : 0)
        .bindBlob(10, head.metadataBlob.data(), head.metadataBlob.size())
        .bindBlob(11, head.extraColumnsBlob.data(), head.extraColumnsBlob.size())
        .bind(12, now)
        .run();
    const std::int64_t runId = impl.connection.lastInsertRowId();

    db::Statement& step = impl.statement(
        "INSERT INTO steps(run_id, step, x, y, theta, v, omega, blocked, sensors, extra, truth) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    step.bind(1, runId);
    const bool hasExtra = !header.extraColumns.empty();
    if (!hasExtra) step.bindNull(10);
    if (!head.hasTruth) step.bindNull(11);
    SummaryBuilder summary;
    std::int64_t steps = 0;
    for (std::size_t c = 0; c < head.chunkCount; ++c) {
      StepChunk chunk = takeChunk(c);
      if (!chunk.error.empty()) {
        outcome.message = std::move(chunk.error);
        return outcome;  // rolls back
      }
      const RunData& rows = chunk.rows;
      const std::size_t n = rows.stepCount();
      if (n > 0 && static_cast<std::int64_t>(chunk.firstStep) != steps) {
        throw db::DbError("steps out of order at step " + std::to_string(chunk.firstStep));
      }
      for (std::size_t i = 0; i < n; ++i, ++steps) {
        if (steps == failAfterSteps) {
          throw db::DbError("injected failure after " + std::to_string(steps) + " steps");
        }
        step.bind(2, steps)
            .bind(3, rows.x[i])
            .bind(4, rows.y[i])
            .bind(5, rows.theta[i])
            .bind(6, rows.v[i])
            .bind(7, rows.omega[i])
            .bind(8, static_cast<std::int64_t>(rows.blocked[i]))
            .bindBlob(9, chunk.sensors.data(i), chunk.sensors.bytes(i));
        if (hasExtra) step.bindBlob(10, chunk.extraBlobs[i].data(), chunk.extraBlobs[i].size());
        if (head.hasTruth) step.bind(11, chunk.packedTruth[i]);
        step.step();
      }
      step.reset();
      if (n > 0) summary.merge(chunk.summary);
    }
    if (steps == 0 && !head.noStepsError.empty()) {
      outcome.message = std::move(head.noStepsError);
      return outcome;  // rolls back
    }

    const std::vector<EncodedBlobs> levels = encodeSummaryBlocks(std::move(summary).finish());
    db::Statement& block =
        impl.statement("INSERT INTO step_blocks(run_id, level, block, minmax) VALUES(?, ?, ?, ?)");
    block.bind(1, runId);
    for (std::size_t level = 0; level < levels.size(); ++level) {
      const EncodedBlobs& blobs = levels[level];
      block.bind(2, static_cast<std::int64_t>(level));
      for (std::size_t b = 0; b < blobs.size(); ++b) {
        block.bind(3, static_cast<std::int64_t>(b))
            .bindBlob(4, blobs.data(b), blobs.bytes(b))
            .step();
      }
    }
    block.reset();
    impl.statement("UPDATE runs SET step_count = ? WHERE id = ?")
        .bind(1, steps)
        .bind(2, runId)
        .run();
    transaction.commit();
    outcome.status = ImportStatus::Imported;
    outcome.runId = runId;
    outcome.steps = steps;
  } catch (const std::exception& e) {
    outcome.status = ImportStatus::Failed;
    outcome.runId = 0;
    // An SQLite failure names the database too (docs/storage.md#errors).
    outcome.message = head.file + ": not stored in " + impl.path.string() + ": " + e.what();
  }
  return outcome;
}

// The given name, else `PREFIX_<stem>` (or the stem without a prefix); docs/storage.md#import.
std::string runName(const ImportOptions& options, const std::filesystem::path& file) {
  if (!options.name.empty()) return options.name;
  if (options.namePrefix.empty()) return file.stem().string();
  return options.namePrefix + "_" + file.stem().string();
}

ImportOutcome cancelledOutcome(const std::filesystem::path& file) {
  ImportOutcome outcome;
  outcome.file = file.string();
  outcome.message = file.string() + ": cancelled";
  return outcome;
}

}  // namespace

ImportOutcome RunDatabase::importText(std::string_view text, const std::string& fileName,
                                      const ImportOptions& options) {
  FileHead head;
  head.file = fileName;
  head.name = runName(options, fileName);
  std::optional<RunCsvChunks> chunks;
  try {
    head.checksum = checksumHex(text);
    chunks.emplace(text, fileName,
                   options.chunkBytes != 0 ? options.chunkBytes : kDefaultChunkBytes);
    describeText(head, *chunks, options.sceneResolver);
  } catch (const std::exception& e) {
    head.error = fileName + ": " + e.what();
  }
  return writeRun(
      *impl_, head, [&](std::size_t i) { return parseChunk(*chunks, i, fileName); },
      options.failAfterSteps);
}

ImportOutcome RunDatabase::importRun(const RunData& run, const std::string& name,
                                     const std::string& sourceFile,
                                     const SceneResolver& sceneResolver) {
  FileHead head;
  head.file = sourceFile.empty() ? name : sourceFile;
  head.name = name;
  std::optional<StepChunk> chunk;
  if (std::string problem = validateRun(run); !problem.empty()) {
    head.error = head.file + ": " + problem;
  } else {
    try {
      head.checksum = checksumHex(formatRunCsv(run));
      head.header.metadata = run.metadata;
      head.header.extraColumns = run.extraColumns;
      head.hasTruth = run.hasTruth();
      head.chunkCount = 1;
      describeHead(head, std::filesystem::path(sourceFile).parent_path(), sceneResolver);
      RunData rows = run.clone();
      rows.metadata.clear();
      chunk = encodeChunk(std::move(rows), 0, run.extraColumns.size());
    } catch (const std::exception& e) {
      head.error = head.file + ": " + e.what();
    }
  }
  return writeRun(
      *impl_, head, [&](std::size_t) { return std::move(*chunk); }, -1);
}

std::vector<ImportOutcome> RunDatabase::importFiles(const std::vector<std::filesystem::path>& files,
                                                    const ImportOptions& options,
                                                    const ProgressFn& progress) {
  std::vector<ImportOutcome> outcomes;
  outcomes.reserve(files.size());
  if (files.empty()) return outcomes;
  if (!options.name.empty() && files.size() > 1) {
    for (const auto& file : files) {
      ImportOutcome outcome;
      outcome.file = file.string();
      outcome.message = "a run name can only be given for a single file";
      outcomes.push_back(std::move(outcome));
    }
    return outcomes;
  }
  const unsigned threads =
      std::max(1u, options.threads != 0 ? options.threads : std::thread::hardware_concurrency());
  const std::size_t chunkBytes = options.chunkBytes != 0 ? options.chunkBytes : kDefaultChunkBytes;

  // Checksums already stored: such a file is only read and hashed, not parsed (the writer then
  // reports it as skipped). Read-only once the workers run.
  std::unordered_set<std::string> known;
  try {
    db::Statement& stored = impl_->statement("SELECT checksum FROM runs");
    while (stored.step())
      known.insert(stored.columnText(0));
    stored.reset();
  } catch (const std::exception&) {
    known.clear();  // only an optimisation; the writer checks each file anyway
  }

  // Worker threads read, hash and split each file (its head task, which also parses the first
  // chunk), then parse the remaining chunks; the writer (this thread) takes the files in order
  // and each file's chunks in order. Parsed chunks of the file being written are bounded by
  // `window`, and so are tasks claimed for the files after it.
  struct Source {
    FileText text;
    std::optional<RunCsvChunks> chunks;
  };
  struct Job {
    FileHead head;
    std::shared_ptr<const Source> source;  // kept by whoever parses one of its chunks
    bool headClaimed = false;
    bool headReady = false;
    bool abandoned = false;     // the writer is done with it; late results are dropped
    std::size_t nextChunk = 0;  // next chunk to claim (the head task parses chunk 0)
    std::size_t taken = 0;      // chunks the writer took
    std::vector<std::optional<StepChunk>> parsed;
  };
  std::vector<Job> jobs(files.size());
  const std::size_t window = 2 * static_cast<std::size_t>(threads) + 2;
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t current = 0;   // the file being written
  std::size_t inFlight = 0;  // claimed tasks whose results are not yet taken or dropped
  bool stop = false;

  constexpr std::size_t kHead = static_cast<std::size_t>(-1);
  // Under the lock: the next task, preferring the file being written, which is never held back
  // by the later files (so the writer always gets what it waits for).
  auto claim = [&](std::size_t& file, std::size_t& chunk) {
    for (std::size_t j = current; j < jobs.size(); ++j) {
      Job& job = jobs[j];
      const bool allowed = j == current ? job.nextChunk < job.taken + window : inFlight < window;
      if (!allowed) return false;
      if (!job.headClaimed) {
        job.headClaimed = true;
        job.nextChunk = 1;
        file = j;
        chunk = kHead;
        ++inFlight;
        return true;
      }
      if (job.headReady && !job.abandoned && job.nextChunk < job.head.chunkCount) {
        file = j;
        chunk = job.nextChunk++;
        ++inFlight;
        return true;
      }
      if (j > current + window) return false;
    }
    return false;
  };

  auto runHead = [&](std::size_t j) {
    FileHead head;
    head.file = files[j].string();
    head.name = runName(options, files[j]);
    auto source = std::make_shared<Source>();
    std::optional<StepChunk> first;
    try {
      std::string error;
      if (!source->text.load(files[j], error)) {
        head.error = head.file + ": " + error;
      } else {
        head.checksum = checksumHex(source->text.view());
        if (!known.contains(head.checksum)) {
          source->chunks.emplace(source->text.view(), head.file, chunkBytes);
          describeText(head, *source->chunks, options.sceneResolver);
          if (head.error.empty()) first = parseChunk(*source->chunks, 0, head.file);
        }
      }
    } catch (const std::exception& e) {
      head.error = head.file + ": " + e.what();
      first.reset();
    }
    if (!head.error.empty() || !first) head.chunkCount = 0;
    std::lock_guard lock(mutex);
    Job& job = jobs[j];
    job.head = std::move(head);
    job.source = std::move(source);
    job.parsed.resize(job.head.chunkCount);
    if (first) {
      job.parsed[0] = std::move(*first);
    } else {
      --inFlight;
    }
    job.headReady = true;
  };

  auto worker = [&] {
    std::unique_lock lock(mutex);
    while (true) {
      std::size_t j = 0;
      std::size_t c = 0;
      changed.wait(lock, [&] { return stop || claim(j, c); });
      if (stop) return;
      if (c == kHead) {
        lock.unlock();
        runHead(j);
      } else {
        std::shared_ptr<const Source> source = jobs[j].source;
        const std::string file = jobs[j].head.file;
        lock.unlock();
        StepChunk chunk = parseChunk(*source->chunks, c, file);
        source.reset();
        lock.lock();
        if (jobs[j].abandoned) {
          --inFlight;
        } else {
          jobs[j].parsed[c] = std::move(chunk);
        }
        lock.unlock();
      }
      changed.notify_all();
      lock.lock();
    }
  };

  auto stopWorkers = [&] {
    {
      std::lock_guard lock(mutex);
      stop = true;
    }
    changed.notify_all();
  };
  std::vector<std::thread> workers;
  // Stops and joins the workers on every way out, exceptions included.
  struct Joiner {
    std::vector<std::thread>& threads;
    const std::function<void()> stop;
    ~Joiner() {
      stop();
      for (std::thread& t : threads)
        t.join();
    }
  } joiner{workers, stopWorkers};
  for (unsigned t = 0; t < threads; ++t)
    workers.emplace_back(worker);

  bool cancelled = false;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (cancelled) {
      outcomes.push_back(cancelledOutcome(files[i]));
      continue;
    }
    Job& job = jobs[i];
    {
      std::unique_lock lock(mutex);
      current = i;
      changed.notify_all();
      changed.wait(lock, [&] { return job.headReady; });
    }
    auto take = [&](std::size_t c) {
      std::unique_lock lock(mutex);
      changed.wait(lock, [&] { return job.parsed[c].has_value(); });
      StepChunk chunk = std::move(*job.parsed[c]);
      job.parsed[c].reset();
      ++job.taken;
      --inFlight;
      lock.unlock();
      changed.notify_all();
      return chunk;
    };
    outcomes.push_back(writeRun(*impl_, job.head, take, options.failAfterSteps));
    {
      std::lock_guard lock(mutex);
      job.abandoned = true;
      for (auto& chunk : job.parsed) {
        if (chunk) {
          chunk.reset();
          --inFlight;
        }
      }
      job.source.reset();
      job.head = FileHead{};
      if (i + 1 < files.size()) current = i + 1;
    }
    changed.notify_all();
    if (progress && !progress(i + 1, files.size())) {
      cancelled = true;
      stopWorkers();
    }
  }
  return outcomes;
}

}  // namespace tactile::storage
