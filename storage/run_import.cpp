// Run import, the scheduler: worker threads prepare files chunk by chunk (import_prepare.cpp);
// the calling thread writes each file in its own transaction as its chunks arrive
// (run_writer.cpp).
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <new>
#include <optional>
#include <thread>
#include <unordered_set>

#include "base/file_text.h"
#include "base/parallel.h"
#include "run/run_csv.h"
#include "storage/import_pieces.h"

namespace tactile::storage {

using namespace importing;

namespace {

// importRun encodes the steps in blocks of this many, at most this many blocks ahead of the
// writer: a block's blobs (a few MB) reuse the memory of the ones before instead of fresh pages.
constexpr std::size_t kRunBlockSteps = 16384;
constexpr std::size_t kRunBlocksAhead = 3;

}  // namespace

ImportOutcome RunStore::importText(std::string_view text, const std::string& fileName,
                                   const ImportOptions& options) {
  const ResetStatements reset{*impl_};
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
  ImportOutcome outcome = writeRun(
      *impl_, head, [&](std::size_t i) { return parseChunk(*chunks, i, fileName); },
      options.failAfterSteps);
  if (outcome.status == ImportStatus::Imported) impl_->refreshStepStatistics(outcome.steps);
  return outcome;
}

ImportOutcome RunStore::importRun(const RunData& run, const std::string& name,
                                  const std::string& sourceFile,
                                  const SceneResolver& sceneResolver) {
  return importRun(run.clone(), name, sourceFile, sceneResolver);
}

ImportOutcome RunStore::importRun(RunData&& run, const std::string& name,
                                  const std::string& sourceFile,
                                  const SceneResolver& sceneResolver) {
  const ResetStatements reset{*impl_};
  FileHead head;
  head.file = sourceFile.empty() ? name : sourceFile;
  head.name = name;
  if (std::string problem = validateRun(run); !problem.empty()) {
    head.error = head.file + ": " + problem;
  } else {
    try {
      head.header.metadata = run.metadata;
      head.header.extraColumns = run.extraColumns;
      head.hasTruth = run.hasTruth();
      describeHead(head, std::filesystem::path(sourceFile).parent_path(), sceneResolver);
    } catch (const std::exception& e) {
      head.error = head.file + ": " + e.what();
    }
  }
  if (!head.error.empty()) return writeRun(*impl_, head, {}, -1);

  // Side by side: this thread writes the rows (SQLite's work, the longest part), one helper
  // encodes the steps a block at a time just ahead of it (with the rows' checksums, once the run's
  // row is written and its id known), and one takes the checksum of the run's file form (formatted
  // on itself and one more thread), which the writer needs only once the steps are in. The run is
  // read by the helpers and changed by none.
  const std::size_t steps = run.stepCount();
  const std::size_t blocks =
      std::max<std::size_t>(1, (steps + kRunBlockSteps - 1) / kRunBlockSteps);
  head.chunkCount = blocks;
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<StepChunk> encoded;  // blocks ready, in order, from block `taken`
  std::size_t taken = 0;
  bool stop = false;
  std::optional<std::string> checksum;
  std::string checksumError;
  std::optional<std::int64_t> runId;  // once the writer has written the run's row
  struct Stopped {};

  SummaryBuilder wholeSummary;  // the encoding thread's
  auto encodeAll = [&] {
    for (std::size_t b = 0; b < blocks; ++b) {
      {
        std::unique_lock lock(mutex);
        changed.wait(lock, [&] { return stop || b < taken + kRunBlocksAhead; });
        if (stop) return;
      }
      const std::size_t first = b * kRunBlockSteps;
      StepChunk chunk;
      try {
        chunk = encodeSteps(run, first, std::min(steps, first + kRunBlockSteps) - first);
        // The rows' checksums too, once the writer has the run's id (they include it).
        std::int64_t id = 0;
        {
          std::unique_lock lock(mutex);
          changed.wait(lock, [&] { return stop || runId.has_value(); });
          if (stop) return;
          id = *runId;
        }
        checksumSteps(chunk, id, head.hasTruth);
        // The run's summary rows too, with the last block (the writer then has only to write
        // them).
        if (chunk.rows.stepCount() > 0) wholeSummary.merge(chunk.summary);
        chunk.summary = PartialSummary{};
        if (b + 1 == blocks) chunk.wholeSummary = summaryRows(std::move(wholeSummary).finish(), id);
      } catch (const std::exception& e) {
        chunk = StepChunk{};
        chunk.error = head.file + ": " + e.what();
      }
      {
        std::lock_guard lock(mutex);
        encoded.push_back(std::move(chunk));
      }
      changed.notify_all();
    }
  };
  auto hashAll = [&] {
    std::string hex;
    std::string error;
    try {
      RunningChecksum sum;
      // On two threads: on two cores the writer at times gets ahead of one.
      formatRunCsvPieces(run, 2, [&](std::string_view piece) {
        {
          std::lock_guard lock(mutex);
          if (stop) throw Stopped{};
        }
        sum.update(piece);
      });
      hex = sum.hex();
    } catch (const Stopped&) {
      return;
    } catch (const std::exception& e) {
      error = head.file + ": " + e.what();
    }
    {
      std::lock_guard lock(mutex);
      checksum = std::move(hex);
      checksumError = std::move(error);
    }
    changed.notify_all();
  };
  std::atomic<int> nextJob{0};
  FirstException failure;
  auto stopHelpers = [&] {
    {
      std::lock_guard lock(mutex);
      stop = true;
    }
    changed.notify_all();
  };
  auto work = [&] {
    const int job = nextJob.fetch_add(1);
    if (!failure.capture([&] { job == 0 ? hashAll() : encodeAll(); })) stopHelpers();
  };
  ImportOutcome outcome;
  {
    BackgroundWorkers helpers(2, work, failure);
    struct Joiner {
      BackgroundWorkers& helpers;
      const std::function<void()> stop;
      ~Joiner() {
        stop();
        helpers.join();
      }
    } joiner{helpers, stopHelpers};
    head.runStarted = [&](std::int64_t id) {
      {
        std::lock_guard lock(mutex);
        runId = id;
      }
      changed.notify_all();
    };
    head.lateChecksum = [&](std::string& out, std::string& error) {
      std::unique_lock lock(mutex);
      changed.wait(lock, [&] { return checksum.has_value() || failure.failed(); });
      if (!checksum) {
        error = head.file + ": the checksum could not be taken";
        return false;
      }
      out = *checksum;
      error = checksumError;
      return error.empty();
    };
    outcome = writeRun(
        *impl_, head,
        [&](std::size_t) {
          std::unique_lock lock(mutex);
          changed.wait(lock, [&] { return !encoded.empty() || failure.failed(); });
          StepChunk chunk;
          if (encoded.empty()) {
            chunk.error = head.file + ": the steps could not be encoded";
            try {
              failure.rethrow();
            } catch (const std::exception& e) {
              chunk.error = head.file + ": " + e.what();
            } catch (...) {
            }
          } else {
            chunk = std::move(encoded.front());
            encoded.pop_front();
          }
          ++taken;
          lock.unlock();
          changed.notify_all();
          return chunk;
        },
        -1);
  }
  if (outcome.status == ImportStatus::Imported) impl_->refreshStepStatistics(outcome.steps);
  return outcome;
}

std::vector<ImportOutcome> RunStore::importFiles(const std::vector<std::filesystem::path>& files,
                                                 const ImportOptions& options,
                                                 const ProgressFn& progress) {
  const ResetStatements reset{*impl_};
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
      if (Status loaded = source->text.load(files[j]); !loaded) {
        head.error = loaded.errorText();
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

  // An exception that escapes a task (out of memory outside a file's own parsing) stops the
  // workers; the writer then throws it on this thread once they are joined.
  FirstException workerFailure;
  auto workerLoop = [&] {
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
        StepChunk chunk;
        try {
          chunk = parseChunk(*source->chunks, c, file);
        } catch (const std::bad_alloc&) {
          chunk = StepChunk{};
          chunk.error = file + ": out of memory: the file is too large for this machine's memory";
        } catch (const std::exception& e) {
          chunk = StepChunk{};
          chunk.error = file + ": " + e.what();
        }
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
  // The exception is kept before the others (and the writer) are woken, so they see failed().
  auto worker = [&] {
    if (!workerFailure.capture(workerLoop)) stopWorkers();
  };
  BackgroundWorkers workers(threads, worker, workerFailure);
  // Stops and joins the workers on every way out, exceptions included.
  struct Joiner {
    BackgroundWorkers& workers;
    const std::function<void()> stop;
    void join() {
      stop();
      workers.join();
    }
    ~Joiner() { join(); }
  } joiner{workers, stopWorkers};
  // After a wait woken by a failed worker: join them all, then throw its exception here.
  auto throwWorkerFailure = [&] {
    joiner.join();
    workerFailure.rethrow();
  };
  // A thread that could not be started: the ones that did are stopped and joined first.
  if (workerFailure.failed()) throwWorkerFailure();

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
      changed.wait(lock, [&] { return job.headReady || workerFailure.failed(); });
    }
    if (workerFailure.failed()) throwWorkerFailure();
    auto take = [&](std::size_t c) {
      std::unique_lock lock(mutex);
      changed.wait(lock, [&] { return job.parsed[c].has_value() || workerFailure.failed(); });
      if (!job.parsed[c].has_value()) {
        lock.unlock();
        throwWorkerFailure();
      }
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
  // A worker's exception that the writer met inside a file's write (reported there as that
  // file's failure) is thrown here all the same.
  if (workerFailure.failed()) throwWorkerFailure();
  std::int64_t added = 0;
  for (const ImportOutcome& outcome : outcomes) {
    if (outcome.status == ImportStatus::Imported) added += outcome.steps;
  }
  impl_->refreshStepStatistics(added);
  return outcomes;
}

}  // namespace tactile::storage
