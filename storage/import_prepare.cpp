// Preparing run files for the writer: reading, hashing, parsing and encoding, off the writer
// thread (see import_pieces.h).
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
#include <type_traits>
#include <unordered_set>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include "base/file_text.h"
#include "base/text_rules.h"
#include "run/builtin_scenes.h"
#include "run/run_csv.h"
#include "storage/import_pieces.h"

namespace tactile::storage {

static_assert(std::endian::native == std::endian::little,
              "the sensors BLOB is little-endian float64; add byte swapping for this platform");

namespace {

constexpr std::uint64_t kMul1 = 0x9E3779B97F4A7C15ull;
constexpr std::uint64_t kMul2 = 0xC2B2AE3D27D4EB4Full;

std::uint64_t mixWord(std::uint64_t h, std::uint64_t w, std::uint64_t mul) {
  w *= mul;
  w ^= w >> 29;
  return (h ^ w) * kMul2 + 0x165667B19E3779F9ull;
}

}  // namespace

// Two independent multiply-xorshift lanes over 8-byte words (for instruction-level parallelism),
// then the tail and the length, then a final avalanche. Bytes may come in pieces of any size: up to
// 15 wait for the rest of their 16-byte block.
void RunningChecksum::update(std::string_view bytes) {
  const char* p = bytes.data();
  std::size_t n = bytes.size();
  total_ += n;
  if (pending_ > 0) {
    const std::size_t take = std::min(n, sizeof block_ - pending_);
    std::memcpy(block_ + pending_, p, take);
    pending_ += take;
    p += take;
    n -= take;
    if (pending_ < sizeof block_) return;
    addBlock(block_);
    pending_ = 0;
  }
  while (n >= 16) {
    addBlock(p);
    p += 16;
    n -= 16;
  }
  std::memcpy(block_, p, n);
  pending_ = n;
}

void RunningChecksum::addBlock(const char* p) {
  std::uint64_t w1 = 0;
  std::uint64_t w2 = 0;
  std::memcpy(&w1, p, 8);
  std::memcpy(&w2, p + 8, 8);
  a_ = mixWord(a_, w1, kMul1);
  b_ = mixWord(b_, w2, kMul2);
}

std::string RunningChecksum::hex() const {
  std::uint64_t a = a_;
  std::uint64_t b = b_;
  const std::size_t n = pending_;
  std::uint64_t tail = 0;
  std::memcpy(&tail, block_, std::min<std::size_t>(n, 8));
  a = mixWord(a, tail, kMul1);
  if (n > 8) {
    tail = 0;
    std::memcpy(&tail, block_ + 8, n - 8);
    b = mixWord(b, tail, kMul2);
  }
  std::uint64_t h = mixWord(a ^ std::rotl(b, 31), total_, kMul1);
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

std::string checksumHex(std::string_view bytes) {
  RunningChecksum sum;
  sum.update(bytes);
  return sum.hex();
}

std::string runFileChecksumHex(const RunData& run) {
  RunningChecksum sum;
  formatRunCsvPieces(run, 0, [&sum](std::string_view piece) { sum.update(piece); });
  return sum.hex();
}

namespace importing {

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

namespace {

// A run file's `scene` value that is not a built-in name must be the name of a plain file in the
// run file's own folder (docs/file-formats.md#run-file): no folder part (so no absolute path and
// no `..`), not a symbolic link, a regular file (never a FIFO or a device, which could hang or
// never end), at most kMaxSceneFileBytes. The file is opened without following links and without
// blocking, and checked on the open descriptor, so it cannot be swapped in between.
std::optional<std::string> readSceneBeside(const std::string& value,
                                           const std::filesystem::path& baseDir,
                                           std::string& problem) {
  if (value == "." || value == ".." || value.find_first_of("/\\") != std::string::npos ||
      value.find('\0') != std::string::npos) {
    problem =
        "is neither a built-in scene nor a file name in the run file's folder (a path "
        "with a folder part, absolute or with '..', is not read)";
    return std::nullopt;
  }
  const std::filesystem::path path = baseDir / value;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    problem = error == ELOOP ? "names a symbolic link (" + path.string() + "), which is not read"
                             : "is neither a built-in scene nor a readable file (" + path.string() +
                                   ": " + std::strerror(error) + ")";
    return std::nullopt;
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    problem = "names " + path.string() + ", which is not a regular file";
    return std::nullopt;
  }
  if (static_cast<std::uint64_t>(info.st_size) > kMaxSceneFileBytes) {
    problem = "names " + path.string() + " of " + std::to_string(info.st_size) +
              " bytes, more than the " + std::to_string(kMaxSceneFileBytes) +
              " a scene file may have";
    return std::nullopt;
  }
  std::string text;
  text.resize(static_cast<std::size_t>(info.st_size));
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t n = ::read(fd, text.data() + got, text.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got != text.size()) {
    problem = "names " + path.string() + ", which could not be read whole";
    return std::nullopt;
  }
  return text;
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
    std::string problem;
    std::optional<std::string> text = readSceneBeside(*scene, baseDir, problem);
    if (!text) {
      head.warnings.push_back("scene '" + *scene + "' " + problem +
                              "; the run is stored without its scene");
      return;
    }
    json = std::move(*text);
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

}  // namespace

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

namespace {

// Truth and x_ columns of a chunk whose sensors are encoded, then the rows moved in.
void encodeRest(StepChunk& chunk, RunData& rows, std::size_t extraColumns) {
  const std::size_t n = rows.stepCount();
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
}

}  // namespace

StepChunk encodeChunk(RunData rows, std::size_t firstStep, std::size_t extraColumns) {
  StepChunk chunk;
  chunk.firstStep = firstStep;
  const std::size_t n = rows.stepCount();
  chunk.sensors = encodeStepSensors(rows.sensors.data(), n);
  chunk.summary = summarizeSteps(rows.sensors.data(), firstStep, n);
  encodeRest(chunk, rows, extraColumns);
  return chunk;
}

StepChunk encodeSteps(const RunData& run, std::size_t first, std::size_t count) {
  StepChunk chunk;
  chunk.firstStep = first;
  const double* sensors = run.sensors.data() + first * kValuesPerStep;
  chunk.sensors = encodeStepSensors(sensors, count);
  chunk.summary = summarizeSteps(sensors, first, count);
  RunData rows;
  const auto slice = [&](const auto& column, std::size_t width) {
    using Column = std::decay_t<decltype(column)>;
    const auto from = column.begin() + static_cast<std::ptrdiff_t>(first * width);
    return Column(from, from + static_cast<std::ptrdiff_t>(count * width));
  };
  rows.x = slice(run.x, 1);
  rows.y = slice(run.y, 1);
  rows.theta = slice(run.theta, 1);
  rows.v = slice(run.v, 1);
  rows.omega = slice(run.omega, 1);
  rows.blocked = slice(run.blocked, 1);
  if (run.hasTruth()) rows.truth = slice(run.truth, kGroupCount);
  const std::size_t extras = run.extraColumns.size();
  if (extras > 0) rows.extraValues = slice(run.extraValues, extras);
  encodeRest(chunk, rows, extras);
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

// The given name, else `PREFIX_<stem>` (or the stem without a prefix); docs/storage.md#import.
std::string runName(const ImportOptions& options, const std::filesystem::path& file) {
  if (!options.name.empty()) return options.name;
  // A stem's commas and control characters become '_' (the name rule, base/text_rules.h); the
  // rule itself is checked when the run is written.
  const std::string stem = nameFromFileStem(file.stem().string());
  if (options.namePrefix.empty()) return stem;
  return options.namePrefix + "_" + stem;
}

ImportOutcome cancelledOutcome(const std::filesystem::path& file) {
  ImportOutcome outcome;
  outcome.file = file.string();
  outcome.message = file.string() + ": cancelled";
  return outcome;
}

}  // namespace importing
}  // namespace tactile::storage
