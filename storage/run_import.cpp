// Run import: parse (on worker threads), encode sensors and block summaries, then write
// each file in its own transaction on the calling thread.
#include <algorithm>
#include <atomic>
#include <bit>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "sim/builtin_scenes.h"
#include "sim/file_text.h"
#include "sim/run_csv.h"
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

// Everything a writer needs, computed off the writer thread.
struct PreparedRun {
  std::string file;  // as given, for messages
  std::string name;
  std::string checksum;
  std::string error;  // non-empty: the file is rejected
  RunData run;
  std::string sceneValue;  // the `scene` metadata value
  std::string sceneName;
  std::string sceneJson;  // empty when unresolved
  std::string sceneChecksum;
  std::vector<std::string> warnings;
  std::vector<std::int64_t> packedTruth;   // one per step when the run has truth
  EncodedBlobs sensorBlobs;                // one per step
  std::vector<EncodedBlobs> summaryBlobs;  // one list per summary level
  std::string metadataBlob;
  std::string extraColumnsBlob;
  std::vector<std::string> extraBlobs;  // one per step when there are x_ columns
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

void resolveScene(PreparedRun& prepared, const std::filesystem::path& baseDir) {
  const std::string* scene = prepared.run.meta("scene");
  if (scene == nullptr || scene->empty()) return;
  prepared.sceneValue = *scene;
  std::string json;
  if (auto builtin = builtinSceneJson(*scene)) {
    json = std::string(*builtin);
  } else {
    std::filesystem::path scenePath(*scene);
    if (scenePath.is_relative()) scenePath = baseDir / scenePath;
    std::string error;
    if (!readFileText(scenePath, json, error)) {
      prepared.warnings.push_back("scene '" + *scene +
                                  "' is neither a built-in scene nor a readable file (" +
                                  scenePath.string() + "); the run is stored without its scene");
      return;
    }
  }
  const nlohmann::json parsed = nlohmann::json::parse(json, nullptr, false);
  if (parsed.is_discarded() || !parsed.is_object()) {
    prepared.warnings.push_back("scene '" + *scene +
                                "' is not a JSON object; the run is stored without its scene");
    return;
  }
  const auto name = parsed.find("name");
  prepared.sceneName =
      name != parsed.end() && name->is_string() ? name->get<std::string>() : *scene;
  prepared.sceneChecksum = checksumHex(json);
  prepared.sceneJson = std::move(json);
}

// Derived data and JSON columns, shared by every import path.
void deriveColumns(PreparedRun& prepared, const std::filesystem::path& baseDir) {
  const RunData& run = prepared.run;
  // Length-prefixed bytes rather than JSON: metadata is kept byte for byte, even text that is not
  // valid UTF-8 (which a JSON library would refuse or alter).
  std::vector<std::string> pairs;
  for (const auto& [key, value] : run.metadata) {
    pairs.push_back(key);
    pairs.push_back(value);
  }
  prepared.metadataBlob = encodeExtra(pairs.data(), pairs.size());
  prepared.extraColumnsBlob = encodeExtra(run.extraColumns.data(), run.extraColumns.size());
  if (!run.extraColumns.empty()) {
    const std::size_t columns = run.extraColumns.size();
    prepared.extraBlobs.resize(run.stepCount());
    for (std::size_t i = 0; i < run.stepCount(); ++i) {
      prepared.extraBlobs[i] = encodeExtra(run.extraValues.data() + i * columns, columns);
    }
  }
  if (run.hasTruth()) {
    prepared.packedTruth.resize(run.stepCount());
    for (std::size_t i = 0; i < run.stepCount(); ++i)
      prepared.packedTruth[i] = packTruth(run.truth.data() + i * kGroupCount);
  }
  prepared.sensorBlobs = encodeStepSensors(run.sensors.data(), run.stepCount());
  prepared.summaryBlobs =
      encodeSummaryBlocks(computeSummaryBlocks(run.sensors.data(), run.stepCount()));
  resolveScene(prepared, baseDir);
}

PreparedRun prepareTextUnguarded(std::string_view text, const std::string& fileName,
                                 std::string name, std::string checksum) {
  PreparedRun prepared;
  prepared.file = fileName;
  const std::filesystem::path filePath(fileName);
  prepared.name = name.empty() ? filePath.stem().string() : std::move(name);
  prepared.checksum = checksum.empty() ? checksumHex(text) : std::move(checksum);
  RunCsvResult parsed = parseRunCsv(text, fileName);
  if (!parsed.ok()) {
    prepared.error = parsed.error().toString();
    return prepared;
  }
  // The reader already refuses everything validateRun checks (non-finite values, bad blocked
  // and truth cells, ragged columns), each with its line and column.
  prepared.run = std::move(parsed.run());
  deriveColumns(prepared, filePath.parent_path());
  return prepared;
}

// Never throws: any failure (even out of memory on a worker thread) becomes the file's error.
PreparedRun prepareText(std::string_view text, const std::string& fileName, std::string name,
                        std::string checksum) {
  try {
    return prepareTextUnguarded(text, fileName, std::move(name), std::move(checksum));
  } catch (const std::exception& e) {
    PreparedRun prepared;
    prepared.file = fileName;
    prepared.error = fileName + ": " + e.what();
    return prepared;
  }
}

PreparedRun prepareFile(const std::filesystem::path& path, const std::string& name) {
  FileText text;
  std::string error;
  bool read = false;
  try {
    read = text.load(path, error);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!read) {
    PreparedRun prepared;
    prepared.file = path.string();
    prepared.name = name.empty() ? path.stem().string() : name;
    prepared.error = path.string() + ": " + error;
    return prepared;
  }
  return prepareText(text.view(), path.string(), name, {});
}

ImportOutcome writePrepared(RunDatabase::Impl& impl, PreparedRun& prepared,
                            std::int64_t failAfterSteps) {
  ImportOutcome outcome;
  outcome.file = prepared.file;
  outcome.runName = prepared.name;
  outcome.warnings = std::move(prepared.warnings);
  if (!prepared.error.empty()) {
    outcome.message = std::move(prepared.error);
    return outcome;
  }
  const RunData& run = prepared.run;
  try {
    {
      db::Statement& dup = impl.statement("SELECT id, name FROM runs WHERE checksum = ?");
      dup.bind(1, prepared.checksum);
      if (dup.step()) {
        outcome.status = ImportStatus::Skipped;
        outcome.runId = dup.columnInt(0);
        outcome.runName = dup.columnText(1);
        outcome.steps = static_cast<std::int64_t>(run.stepCount());
        outcome.message = prepared.file + ": already imported as run '" + outcome.runName +
                          "' (same checksum " + prepared.checksum + "); skipped";
        dup.reset();
        return outcome;
      }
      dup.reset();
    }
    {
      db::Statement& named = impl.statement("SELECT source_file FROM runs WHERE name = ?");
      named.bind(1, prepared.name);
      if (named.step()) {
        outcome.message = prepared.file + ": a run named '" + prepared.name +
                          "' already exists (imported from " + named.columnText(0) +
                          "); choose another name";
        named.reset();
        return outcome;
      }
      named.reset();
    }

    // The steps and block rows reference the run row written in this same transaction, so
    // their per-row foreign-key lookups can be skipped; the pragma only works outside a
    // transaction and is restored on every path.
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
    db::Transaction transaction(impl.connection);
    std::int64_t sceneId = 0;
    if (!prepared.sceneJson.empty()) {
      impl.statement("INSERT OR IGNORE INTO scenes(name, checksum, json) VALUES(?, ?, ?)")
          .bind(1, prepared.sceneName)
          .bind(2, prepared.sceneChecksum)
          .bind(3, prepared.sceneJson)
          .run();
      db::Statement& id = impl.statement("SELECT id FROM scenes WHERE checksum = ?");
      id.bind(1, prepared.sceneChecksum);
      id.step();
      sceneId = id.columnInt(0);
      id.reset();
    }
    const std::string now = utcNow();
    db::Statement& insertRun = impl.statement(
        "INSERT INTO runs(name, source_file, checksum, scene, scene_id, subject, outcome, dt, "
        "step_count, has_truth, metadata, extra_columns, imported_at) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    insertRun.bind(1, prepared.name).bind(2, prepared.file).bind(3, prepared.checksum);
    if (prepared.sceneValue.empty()) {
      insertRun.bindNull(4);
    } else {
      insertRun.bind(4, prepared.sceneValue);
    }
    if (sceneId != 0) {
      insertRun.bind(5, sceneId);
    } else {
      insertRun.bindNull(5);
    }
    const std::string* subject = run.meta("subject");
    if (subject != nullptr) {
      insertRun.bind(6, *subject);
    } else {
      insertRun.bindNull(6);
    }
    insertRun.bind(7, runOutcomeName(run.outcome()));
    if (auto dt = run.dtSeconds()) {
      insertRun.bind(8, *dt);
    } else {
      insertRun.bindNull(8);
    }
    insertRun.bind(9, static_cast<std::int64_t>(run.stepCount()))
        .bind(10, run.hasTruth() ? 1 : 0)
        .bindBlob(11, prepared.metadataBlob.data(), prepared.metadataBlob.size())
        .bindBlob(12, prepared.extraColumnsBlob.data(), prepared.extraColumnsBlob.size())
        .bind(13, now)
        .run();
    const std::int64_t runId = impl.connection.lastInsertRowId();

    db::Statement& step = impl.statement(
        "INSERT INTO steps(run_id, step, x, y, theta, v, omega, blocked, sensors, extra, truth) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    step.bind(1, runId);
    const bool hasExtra = !prepared.extraBlobs.empty();
    if (!hasExtra) step.bindNull(10);
    const bool hasTruth = !prepared.packedTruth.empty();
    if (!hasTruth) step.bindNull(11);
    const EncodedBlobs& sensors = prepared.sensorBlobs;
    for (std::size_t i = 0; i < run.stepCount(); ++i) {
      if (failAfterSteps >= 0 && static_cast<std::int64_t>(i) == failAfterSteps) {
        throw db::DbError("injected failure after " + std::to_string(i) + " steps");
      }
      step.bind(2, static_cast<std::int64_t>(i))
          .bind(3, run.x[i])
          .bind(4, run.y[i])
          .bind(5, run.theta[i])
          .bind(6, run.v[i])
          .bind(7, run.omega[i])
          .bind(8, static_cast<std::int64_t>(run.blocked[i]))
          .bindBlob(9, sensors.data(i), sensors.bytes(i));
      if (hasExtra) step.bindBlob(10, prepared.extraBlobs[i].data(), prepared.extraBlobs[i].size());
      if (hasTruth) step.bind(11, prepared.packedTruth[i]);
      step.step();
    }
    step.reset();

    db::Statement& block =
        impl.statement("INSERT INTO step_blocks(run_id, level, block, minmax) VALUES(?, ?, ?, ?)");
    block.bind(1, runId);
    for (std::size_t level = 0; level < prepared.summaryBlobs.size(); ++level) {
      const EncodedBlobs& blobs = prepared.summaryBlobs[level];
      block.bind(2, static_cast<std::int64_t>(level));
      for (std::size_t b = 0; b < blobs.size(); ++b) {
        block.bind(3, static_cast<std::int64_t>(b))
            .bindBlob(4, blobs.data(b), blobs.bytes(b))
            .step();
      }
    }
    block.reset();
    transaction.commit();
    outcome.status = ImportStatus::Imported;
    outcome.runId = runId;
    outcome.steps = static_cast<std::int64_t>(run.stepCount());
  } catch (const std::exception& e) {
    outcome.status = ImportStatus::Failed;
    outcome.runId = 0;
    outcome.message = prepared.file + ": not stored: " + e.what();
  }
  return outcome;
}

}  // namespace

ImportOutcome RunDatabase::importText(std::string_view text, const std::string& fileName,
                                      const ImportOptions& options) {
  PreparedRun prepared = prepareText(text, fileName, options.name, {});
  return writePrepared(*impl_, prepared, options.failAfterSteps);
}

ImportOutcome RunDatabase::importRun(const RunData& run, const std::string& name,
                                     const std::string& sourceFile) {
  PreparedRun prepared;
  prepared.file = sourceFile.empty() ? name : sourceFile;
  prepared.name = name;
  if (std::string problem = validateRun(run); !problem.empty()) {
    prepared.error = prepared.file + ": " + problem;
    return writePrepared(*impl_, prepared, -1);
  }
  try {
    prepared.run = run.clone();
    prepared.checksum = checksumHex(formatRunCsv(run));
    deriveColumns(prepared, std::filesystem::path(sourceFile).parent_path());
  } catch (const std::exception& e) {
    prepared.error = prepared.file + ": " + e.what();
  }
  return writePrepared(*impl_, prepared, -1);
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
  unsigned threads = options.threads != 0 ? options.threads : std::thread::hardware_concurrency();
  threads = std::clamp<unsigned>(threads, 1, static_cast<unsigned>(files.size()));

  if (threads == 1 || files.size() == 1) {
    for (std::size_t i = 0; i < files.size(); ++i) {
      PreparedRun prepared = prepareFile(files[i], options.name);
      outcomes.push_back(writePrepared(*impl_, prepared, options.failAfterSteps));
      if (progress && !progress(i + 1, files.size())) {
        for (std::size_t j = i + 1; j < files.size(); ++j) {
          ImportOutcome cancelled;
          cancelled.file = files[j].string();
          cancelled.message = files[j].string() + ": cancelled";
          outcomes.push_back(std::move(cancelled));
        }
        break;
      }
    }
    return outcomes;
  }

  // Parsers claim files in order and park their results in slots; the writer (this thread)
  // takes slot after slot. At most `window` parsed runs wait in memory.
  const std::size_t window = threads + 1;
  std::vector<std::optional<PreparedRun>> slots(files.size());
  std::mutex mutex;
  std::condition_variable readyCv;
  std::condition_variable spaceCv;
  std::size_t nextToClaim = 0;
  std::size_t written = 0;
  bool stop = false;

  auto parser = [&] {
    while (true) {
      std::size_t index = 0;
      {
        std::unique_lock lock(mutex);
        spaceCv.wait(lock, [&] { return stop || nextToClaim < written + window; });
        if (stop || nextToClaim >= files.size()) return;
        index = nextToClaim++;
      }
      PreparedRun prepared = prepareFile(files[index], options.name);
      {
        std::lock_guard lock(mutex);
        slots[index] = std::move(prepared);
      }
      readyCv.notify_all();
    }
  };
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t)
    workers.emplace_back(parser);

  bool cancelled = false;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (cancelled) {
      ImportOutcome outcome;
      outcome.file = files[i].string();
      outcome.message = files[i].string() + ": cancelled";
      outcomes.push_back(std::move(outcome));
      continue;
    }
    PreparedRun prepared;
    {
      std::unique_lock lock(mutex);
      readyCv.wait(lock, [&] { return slots[i].has_value(); });
      prepared = std::move(*slots[i]);
      slots[i].reset();
    }
    outcomes.push_back(writePrepared(*impl_, prepared, options.failAfterSteps));
    {
      std::lock_guard lock(mutex);
      written = i + 1;
    }
    spaceCv.notify_all();
    if (progress && !progress(i + 1, files.size())) {
      cancelled = true;
      std::lock_guard lock(mutex);
      stop = true;
      spaceCv.notify_all();
    }
  }
  {
    std::lock_guard lock(mutex);
    stop = true;
  }
  spaceCv.notify_all();
  for (auto& worker : workers)
    worker.join();
  return outcomes;
}

}  // namespace tactile::storage
