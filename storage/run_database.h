// The run database: one SQLite file holding recorded runs, their scenes, ground truth, label sets,
// models and sweep results (design notes in docs/storage.md).
//
// This is the API the CLI and the workbench use. Every call returns a result with a message
// instead of throwing. One RunDatabase is one connection: use it from one thread at a time (open a
// second RunDatabase on the same file for a reader thread; WAL lets readers run beside a writer).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "base/error.h"
#include "base/progress.h"
#include "run/contact_class.h"
#include "run/run.h"
#include "run/sensor_layout.h"

namespace tactile::storage {

using tactile::Error;
using tactile::Result;
using tactile::Status;

// One stored run, without its steps.
struct RunInfo {
  std::int64_t id = 0;
  std::string name;
  std::string sourceFile;
  std::string checksum;  // of the imported file's bytes (see docs/storage.md)
  std::string scene;     // the run's `scene` metadata value, empty if none
  bool sceneStored = false;
  std::string subject;
  std::string outcome;  // "success", "gave-up", "unreachable", "timeout" or "unknown"
  std::optional<double> dtSeconds;
  std::int64_t stepCount = 0;
  bool hasTruth = false;
  std::string importedAt;  // UTC, ISO 8601
};

// Consecutive steps of a run: `data` holds the run's metadata and steps [firstStep, firstStep +
// data.stepCount()).
struct RunWindow {
  std::int64_t firstStep = 0;
  RunData data;
};

// Min and max of every sensor value over the steps [firstStep, lastStep].
struct SummaryBucket {
  std::int64_t firstStep = 0;
  std::int64_t lastStep = 0;
  std::array<double, kValuesPerStep> min{};
  std::array<double, kValuesPerStep> max{};
};

// A decimated view of a step range for plotting (min/max per bucket; docs/storage.md#reading).
struct RunSummary {
  std::int64_t firstStep = 0;
  std::int64_t lastStep = -1;
  // Steps per stored block the buckets were built from; 1 when computed from the steps
  // themselves. Bucket boundaries fall on multiples of it (see docs/storage.md).
  std::int64_t blockSteps = 1;
  std::vector<SummaryBucket> buckets;
};

// The per-step columns a view draws, without the sensor values: pose, command, blocked flag and
// truth. About 49 bytes a step, so the track of a million-step run takes about 50 MB where the
// whole run would take over 750 MB.
struct RunTrack {
  std::vector<double> x, y, theta, v, omega;
  std::vector<std::uint8_t> blocked;
  std::vector<ContactClass> truth;  // empty, or stepCount() * kGroupCount in group order

  std::size_t stepCount() const { return x.size(); }
  bool hasTruth() const { return !truth.empty(); }
  ContactClass truthAt(std::size_t step, SensorGroup g) const {
    return truth[step * kGroupCount + static_cast<std::size_t>(groupIndex(g))];
  }
};

// ---- import ----------------------------------------------------------------------------------

enum class ImportStatus { Imported, Skipped, Failed };

struct ImportOutcome {
  std::string file;
  ImportStatus status = ImportStatus::Failed;
  std::string runName;
  std::int64_t runId = 0;  // the new run, or for Skipped the run already holding this file
  std::int64_t steps = 0;
  std::string message;                // why it failed or was skipped (file:line: ... for errors)
  std::vector<std::string> warnings;  // e.g. a scene that could not be resolved
};

// Scene JSON for a run's `scene` value that is not a built-in scene name, or nullopt to fall back
// to reading it as a file path. Lets a caller that links the simulator store procedural scenes
// (`random:N:SEED`) without storage depending on it. Called from worker threads.
using SceneResolver = std::function<std::optional<std::string>(const std::string& scene)>;

struct ImportOptions {
  // The run's name; only for a single file. Empty: the file's stem.
  std::string name;
  // Parser threads; 0 = one per hardware thread. Writing is always one thread (the caller's).
  unsigned threads = 0;
  // Files are parsed in chunks of about this many bytes, so that one big file is parsed on
  // several threads while its first steps are written; 0 = the default (4 MiB).
  std::size_t chunkBytes = 0;
  // Put before every run name taken from a file's stem, joined by '_': runs `P_<stem>`
  // (docs/storage.md#import); not applied to `name`. Lets several batches with the same file names
  // (run_0000.csv, ...) be stored side by side.
  std::string namePrefix;
  // Tried after the built-in scenes and before file paths; may be empty.
  SceneResolver sceneResolver;
  // Test hook: throw after writing this many steps of a run (checks that nothing is kept).
  std::int64_t failAfterSteps = -1;
};

// ---- labels ----------------------------------------------------------------------------------

struct LabelSetInfo {
  std::int64_t id = 0;
  std::string name;
  std::string annotator;
  std::string createdAt;
  std::int64_t segmentCount = 0;
};

// An inclusive step range of one sensor group of one run with one class.
struct LabelSegment {
  std::int64_t id = 0;  // assigned by the database
  std::string run;      // run name (filled on read; on write, used when runId is 0)
  std::int64_t runId = 0;
  SensorGroup group = SensorGroup::Front;
  std::int64_t firstStep = 0;
  std::int64_t lastStep = 0;
  ContactClass cls = ContactClass::NoContact;
  std::string annotator;
};

// One label edit as the history keeps it (storage/label_history.cpp, docs/team.md#history).
struct LabelRevision {
  // Increases through the database: an edit made later has a larger revision.
  std::int64_t revision = 0;
  std::int64_t setId = 0;
  std::string run;
  std::int64_t runId = 0;
  SensorGroup group = SensorGroup::Front;
  // The steps the edit changed.
  std::int64_t firstStep = 0;
  std::int64_t lastStep = 0;
  // The class it gave those steps; none when it cleared them or wrote several classes.
  std::optional<ContactClass> cls;
  // "set", "change", "delete", "undo", "redo", "import", "truth", "copy" or "model".
  std::string action;
  std::string annotator;
  std::string time;  // UTC, ISO 8601
  // What those steps held before, clipped to them (empty: they were unlabelled).
  std::vector<LabelSegment> replaced;
};

// How one label edit is made and recorded.
struct EditOptions {
  // Who makes the edit, as the history shows it. Empty: the annotator of the segment written.
  std::string annotator;
  // The revision the edit was based on: when a later revision changed any step it touches, in
  // any of its groups, nothing is stored and the error names who changed them and when
  // (isLabelConflict). nullopt: newest wins without a check.
  std::optional<std::int64_t> expectRevision;
  // The history's word for the edit; empty: the call's own ("set", "change", ...).
  std::string action;
  // Only revisions by annotators other than `annotator` count against `expectRevision` (an undo:
  // based on the edit it takes back, whatever the same annotator did since).
  bool othersOnly = false;
};

// Whether a failed label edit was refused because someone changed its steps since its revision.
bool isLabelConflict(const Error& error);

// An assignment of a run, or of one group of it, to an annotator (docs/team.md#assignments).
enum class AssignmentState { Todo, Labelled, Reviewed };
std::string_view assignmentStateName(AssignmentState state);  // "todo", "labelled", "reviewed"
std::optional<AssignmentState> parseAssignmentState(std::string_view text);

struct Assignment {
  std::int64_t id = 0;
  std::string run;
  std::int64_t runId = 0;
  std::optional<SensorGroup> group;  // none: the whole run
  std::string annotator;
  std::string labelSet;  // the set to label in; empty when not said
  AssignmentState state = AssignmentState::Todo;
  std::string updatedBy;
  std::string updatedAt;
};

// ---- catalog (storage/catalog.cpp, docs/storage.md#catalog) -------------------------------

// A stored run and the label sets that have segments on it (by name, sorted).
struct RunCatalogEntry {
  RunInfo run;
  std::vector<std::string> labelSets;
};

// A label set and the runs it has segments on (by name, sorted).
struct LabelSetCatalogEntry {
  LabelSetInfo set;
  std::vector<std::string> runs;
};

// ---- models and sweeps (storage/models.cpp) ----------------------------------------------------

// A stored model bundle without its parameters.
struct ModelInfo {
  std::int64_t id = 0;
  std::string name;
  std::string createdAt;      // UTC, ISO 8601
  std::string trainedOnJson;  // provenance: label set, runs, settings, program version
  std::string metricsJson;
};

// A stored sweep without its cells.
struct SweepInfo {
  std::int64_t id = 0;
  std::string name;
  std::string createdAt;
  std::string configurationJson;  // grid, runs, label set, state ("running", "finished", ...)
  std::int64_t cellCount = 0;
};

// One fit job of a sweep planned for workers (docs/cluster.md): pending until a worker claims
// it, running under a lease the worker renews, then done (its cells stored) or failed.
struct SweepClaim {
  std::int64_t job = 0;     // the job's index in the sweep's plan
  std::int64_t cells = 0;   // grid cells it covers (those differing only in the decision mode)
  std::string state;        // "pending", "running", "done", "failed"
  std::string worker;       // who holds or last held it
  double leaseUntil = 0.0;  // Unix seconds; a running claim past it may be taken over
  std::int64_t attempts = 0;
  std::string error;     // failed
  double seconds = 0.0;  // done: the worker's time on it
  std::string finishedAt;
};

// A job's claim is taken over at most this many times (its workers died mid-job each time):
// then it is failed rather than handed to the next worker to kill.
inline constexpr std::int64_t kSweepClaimAttempts = 3;

struct SweepCellRecord {
  std::int64_t id = 0;
  std::string configurationJson;
  std::string metricsJson;
};

// Problems of one kind found by RunDatabase::check: how many, and the first few in full.
struct IntegrityProblemKind {
  std::string kind;  // e.g. "integrity", "foreign key steps -> runs", "step count"
  std::int64_t count = 0;
  std::vector<std::string> cases;  // the first kIntegrityCasesKept, in the order found
};
inline constexpr std::size_t kIntegrityCasesKept = 10;

struct IntegrityReport {
  bool ok = false;
  int schemaVersion = 0;
  // integrity_check, foreign_key_check and checksum findings: the first kIntegrityCasesKept of
  // each kind
  // (`kinds` has every count).
  std::vector<std::string> problems;
  std::vector<IntegrityProblemKind> kinds;
  std::int64_t runs = 0;
  std::int64_t steps = 0;
  std::int64_t labelSets = 0;
};

// ---- copies between databases (storage/copy.cpp, docs/team.md#copies) -------------------------

struct CopyOptions {
  std::vector<std::string> runs;  // run names; empty: every run
  std::vector<std::string> sets;  // label set names; empty: every set
  bool models = true;
  bool sweeps = true;
};

struct CopyReport {
  std::int64_t runsCopied = 0;
  std::int64_t runsPresent = 0;  // already in the target with the same checksum
  std::int64_t stepsCopied = 0;
  std::int64_t setsCreated = 0;
  std::int64_t segmentsCopied = 0;
  std::int64_t segmentsWithoutRun = 0;  // on runs the target does not hold
  std::int64_t revisionsCopied = 0;     // label history entries
  std::int64_t modelsCopied = 0;
  std::int64_t sweepsCopied = 0;
  std::vector<std::string> warnings;
};

// How RunDatabase::open treats the file (docs/storage.md#opening).
enum class OpenMode {
  // Makes the file (and its schema) when absent or empty; migrates an older one.
  Create,
  // An existing Tactile database only (an absent or empty file is an error); migrates an older one.
  ReadWrite,
  // An existing, current Tactile database, never written: works on a read-only file in a
  // read-only folder (then opened `immutable`, see docs/storage.md#read-only-opening).
  ReadOnly,
};

struct OpenOptions {
  OpenMode mode = OpenMode::Create;
  // Older spelling of the mode: false turns OpenMode::Create into OpenMode::ReadWrite.
  bool create = true;
  // Page cache per connection in KiB (PRAGMA cache_size = -cacheKiB).
  int cacheKiB = 256 * 1024;
  // Bytes of the file SQLite may map into memory (PRAGMA mmap_size). Mapped pages count towards
  // the process's resident memory while they are read, so a program that keeps running (the
  // workbench) may choose 0 and read through the page cache alone.
  std::int64_t mmapBytes = std::int64_t{1} << 30;
  // A writable open runs check() first and refuses a database it finds damaged, so nothing is
  // written into one (docs/storage.md#checksums). Costs one pass over the file.
  bool refuseDamaged = true;
};

class RunStore;
class LabelStore;
class ModelStore;
class SweepStore;

class RunDatabase {
 public:
  // Opens or creates a database file (":memory:" for a private in-memory one): WAL journal,
  // synchronous=NORMAL, foreign keys on, schema migrated to the newest version (an older file is
  // first copied to "<file>.v<N>.bak"); a file from a newer program is an error.
  // Before anything is written, a file that is not a Tactile database (not SQLite, another
  // application's SQLite file, SQLite without the Tactile schema, or empty unless mode is Create)
  // is refused and left byte for byte as it was. Every error names the file in Error::file.
  static Result<std::unique_ptr<RunDatabase>> open(const std::filesystem::path& path,
                                                   const OpenOptions& options = {});
  static Result<std::unique_ptr<RunDatabase>> open(const std::filesystem::path& path,
                                                   OpenMode mode);
  ~RunDatabase();
  RunDatabase(const RunDatabase&) = delete;
  RunDatabase& operator=(const RunDatabase&) = delete;

  const std::filesystem::path& path() const;
  // True when opened with OpenMode::ReadOnly.
  bool readOnly() const;
  // True when this open made the database (a new file, or the schema in an empty server database).
  bool created() const;
  // True for a PostgreSQL server, false for an SQLite file.
  bool onServer() const;
  // The backup written when opening migrated an older file (empty otherwise).
  const std::filesystem::path& migrationBackup() const;

  // The database's parts, one store each (below). A store is a light view of this database: take
  // one when needed (`db.runs().list()`); it is valid while the database is open.
  RunStore runs();
  LabelStore labels();
  ModelStore models();
  SweepStore sweeps();

  IntegrityReport check();

  // ---- rights of a team (docs/team.md#roles) ----
  // What this connection may do: on a server, what its role was granted; on a file, everything
  // unless opened read-only.
  struct Rights {
    bool editLabels = true;
    bool keepModels = true;  // store models and sweeps
    bool manageRuns = true;  // import, rename and delete runs
  };
  Rights rights();
  // On a server: makes the login role `role` when absent and gives it exactly `right`
  // ("annotator", "researcher" or "admin"); the server enforces it. An error on a file.
  Status grant(const std::string& role, const std::string& right);

  // Copies runs (row by row with their stored bytes: the copy exports byte for byte as the source
  // does), label sets, models and sweeps from `source` into this database; either may be SQLite or
  // PostgreSQL. Each run is one transaction, checked against its checksums when read and again in
  // this database before it commits; a run already here with the same checksum is left as it is,
  // one with the same name and other content is an error. A label set's segments go onto the runs
  // of the same name here, newest wins, segments already here are not added again; models are
  // copied by name (another model of that name here is a warning), sweeps when not already here.
  // So a second copy adds nothing. `progress` gets (runs done, runs total).
  Result<CopyReport> copyFrom(RunDatabase& source, const CopyOptions& options = {},
                              const ProgressFn& progress = {});

  struct Impl;

 private:
  explicit RunDatabase(std::unique_ptr<Impl> impl);
  // open() of a PostgreSQL server address (docs/team.md).
  static Result<std::unique_ptr<RunDatabase>> openServer(const std::string& address, OpenMode mode);
  // open() without the clean-up of a failed creation.
  static Result<std::unique_ptr<RunDatabase>> openFile(const std::filesystem::path& path,
                                                       const OpenOptions& options, OpenMode mode,
                                                       const std::string& name);
  std::unique_ptr<Impl> impl_;
};

// Runs (storage/run_import.cpp, run_recording.cpp, run_read.cpp, run_columns.cpp, catalog.cpp).
class RunStore {
 public:
  explicit RunStore(RunDatabase::Impl& impl) : impl_(&impl) {}

  // Imports run files. Each file is one transaction: it is stored completely or not at all. A
  // file whose checksum is already stored is skipped. Files are parsed on `options.threads`
  // threads and written by the calling thread, in the given order. `progress` gets (files done,
  // files total); returning false stops after the file being written (the rest are reported as
  // Failed with "cancelled"). Outcomes are in input order.
  std::vector<ImportOutcome> importFiles(const std::vector<std::filesystem::path>& files,
                                         const ImportOptions& options = {},
                                         const ProgressFn& progress = {});
  // Imports run-file text (as if read from `fileName`; a relative scene path resolves against
  // `fileName`'s folder).
  ImportOutcome importText(std::string_view text, const std::string& fileName,
                           const ImportOptions& options = {});
  // Stores a run built in memory (e.g. just recorded). The checksum is that of its CSV text.
  ImportOutcome importRun(const RunData& run, const std::string& name,
                          const std::string& sourceFile = {},
                          const SceneResolver& sceneResolver = {});
  // The same, taking the run's memory instead of copying it (a run of a million steps is 700 MB).
  ImportOutcome importRun(RunData&& run, const std::string& name,
                          const std::string& sourceFile = {},
                          const SceneResolver& sceneResolver = {});

  // ---- runs stored while they are recorded (storage/run_recording.cpp, docs/storage.md#recording)
  // Every call is one committed transaction, so a recorder that dies keeps a readable run with the
  // steps appended so far (outcome as in its header, usually `unknown`).
  // Creates the run `name` with no steps: metadata and x_ column names from `header` (its steps are
  // ignored), the scene resolved as on import; `withTruth`: its steps will carry truth. The name
  // must be free, non-empty and hold no comma or line break. Returns the run id.
  Result<std::int64_t> beginRun(const std::string& name, const RunData& header, bool withTruth,
                                const SceneResolver& sceneResolver = {});
  // Appends steps [firstStep, run.stepCount()) of `run`; firstStep must be the number of steps
  // stored so far. Writes them through the import's step writer with their summary blocks (the
  // run reads back by window and summary at once) and the new step count.
  Status appendSteps(std::int64_t runId, const RunData& run, std::size_t firstStep);
  // Completes the run: `run` holds every step (those not stored yet are appended). Its metadata
  // replaces the stored one (outcome and subject columns too), stored truth that differs from
  // `run`'s (e.g. smoothed at the end) is replaced, and the checksum becomes that of its CSV text,
  // as importRun would store it.
  Status finishRun(std::int64_t runId, const RunData& run);

  Result<std::vector<RunInfo>> list();
  Result<RunInfo> find(std::string_view name);
  Result<RunInfo> info(std::int64_t runId);
  Status remove(std::int64_t runId);  // with its steps, truth and label segments

  // The whole run, equal value for value to what was imported.
  Result<RunData> load(std::int64_t runId);
  // Steps [firstStep, firstStep + count) clipped to the run; reads only those rows.
  Result<RunWindow> loadWindow(std::int64_t runId, std::int64_t firstStep, std::int64_t count);
  // Every step's pose, command, blocked flag and truth, without reading a sensor value.
  Result<RunTrack> loadTrack(std::int64_t runId);
  // Min/max per bucket of about (lastStep - firstStep + 1) / buckets steps over the range (clipped
  // to the run; lastStep < 0 means the last step), read from stored block summaries when the
  // buckets are wide, so a whole huge run is summarised without loading it.
  Result<RunSummary> loadSummary(std::int64_t runId, std::int64_t firstStep, std::int64_t lastStep,
                                 int buckets);
  // The JSON text of the scene the run was recorded in, if it could be resolved at import.
  Result<std::optional<std::string>> sceneJson(std::int64_t runId);
  // Writes the run as a run CSV file (atomically).
  Status exportRun(std::int64_t runId, const std::filesystem::path& file);

  // By name (docs/storage.md#catalog); every change is one transaction, and an unknown name is an
  // error naming it that changes nothing.
  // Every run (sorted by name) with the label sets that have segments on it.
  Result<std::vector<RunCatalogEntry>> catalog();
  // Renames a run; the new name must be free, non-empty and hold no comma or line break.
  Status rename(std::string_view name, const std::string& newName);
  // Deletes the named runs with their steps, truth, block summaries and label segments (and
  // scenes no other run uses), all in one transaction: all or nothing.
  Status remove(const std::vector<std::string>& names);

 private:
  RunDatabase::Impl* impl_;
};

// Label sets and their segments (storage/labels.cpp, label_scope.cpp, catalog.cpp).
class LabelStore {
 public:
  explicit LabelStore(RunDatabase::Impl& impl) : impl_(&impl) {}

  // Every label set (sorted by name) with the runs it has segments on.
  Result<std::vector<LabelSetCatalogEntry>> catalog();
  Status rename(std::string_view name, const std::string& newName);
  // Deletes the named sets with their segments in one transaction: all or nothing.
  Status remove(const std::vector<std::string>& names);

  // Every call below that changes something is one committed transaction.
  Result<std::vector<LabelSetInfo>> list();
  Result<LabelSetInfo> find(std::string_view name);
  Result<std::int64_t> create(const std::string& name, const std::string& annotator = {});
  Result<std::int64_t> copy(std::int64_t setId, const std::string& newName);

  // Every edit below is one revision per group it touches (history()), made by
  // `options.annotator` (else the segment's), and refused as a whole, storing nothing, when
  // `options.expectRevision` is older than a revision over its steps.
  // Adds a segment. Newest wins: any older segment of the same set, run and group overlapping
  // [firstStep, lastStep] is trimmed, split or removed so that only the new one covers that range.
  // The range must lie within the run. Returns the new segment's id.
  Result<std::int64_t> addSegment(std::int64_t setId, const LabelSegment& segment,
                                  const EditOptions& options = {});
  // Replaces a segment's range, group and class (it keeps its id and wins over the range it now
  // covers, as if newly added).
  Status changeSegment(std::int64_t segmentId, const LabelSegment& segment,
                       const EditOptions& options = {});
  Status removeSegment(std::int64_t segmentId, const EditOptions& options = {});
  // Gives steps [firstStep, lastStep] of each of `groups` of a run the class `cls` (newest wins),
  // in one transaction. Returns the last revision made.
  Result<std::int64_t> setRange(std::int64_t setId, std::int64_t runId,
                                const std::vector<SensorGroup>& groups, std::int64_t firstStep,
                                std::int64_t lastStep, ContactClass cls,
                                const EditOptions& options);

  // The history of a set's labels on one run, oldest first: the revisions after
  // `afterRevision`.
  Result<std::vector<LabelRevision>> history(std::int64_t setId, std::int64_t runId,
                                             std::int64_t afterRevision = 0);
  // The newest revision of a set's labels on one run (0 when none).
  Result<std::int64_t> latestRevision(std::int64_t setId, std::int64_t runId);
  // The revision the last successful edit through this database made (0 before any).
  std::int64_t lastRevision() const;
  // True when another connection may have changed labels since the last call (the first call
  // starts watching and returns false). Cheap enough for a timer: SQLite's data_version, a
  // PostgreSQL notification read without a round trip.
  Result<bool> pollChanges();

  // Assignments (docs/team.md#assignments). assign() gives each named run (one group of it, or the
  // whole run) to `annotator` in state todo, or moves an existing one to `state`; one transaction.
  Status assign(const std::vector<std::string>& runs, std::optional<SensorGroup> group,
                const std::string& annotator, const std::string& labelSet, AssignmentState state,
                const std::string& by);
  Status unassign(const std::vector<std::string>& runs, std::optional<SensorGroup> group,
                  const std::string& annotator);
  // Every assignment (of one annotator when not empty), by run name, group, annotator.
  Result<std::vector<Assignment>> assignments(const std::string& annotator = {});
  // One segment of a set; the segments of one run and group overlapping [firstStep, lastStep]
  // (by first step); and a replacement of those with `with` in one transaction (the segments given
  // must not overlap each other). The undo of label edits is built on these.
  Result<LabelSegment> segment(std::int64_t setId, std::int64_t segmentId);
  Result<std::vector<LabelSegment>> segmentsInRange(std::int64_t setId, std::int64_t runId,
                                                    SensorGroup group, std::int64_t firstStep,
                                                    std::int64_t lastStep);
  Status replaceSegmentsInRange(std::int64_t setId, std::int64_t runId, SensorGroup group,
                                std::int64_t firstStep, std::int64_t lastStep,
                                const std::vector<LabelSegment>& with,
                                const EditOptions& options = {});
  // Steps covered by the set's segments per run (summed over the eight groups), for the runs it
  // has segments on: (run id, covered group-steps).
  Result<std::vector<std::pair<std::int64_t, std::int64_t>>> labelledSteps(std::int64_t setId);
  // The same for the segments a model wrote (annotator "model:NAME").
  Result<std::vector<std::pair<std::int64_t, std::int64_t>>> modelLabelledSteps(std::int64_t setId);
  // Segments of a set (of one run when runId != 0), ordered by run, group, first step.
  Result<std::vector<LabelSegment>> segments(std::int64_t setId, std::int64_t runId = 0);

  // Label files (docs/file-formats.md#label-file): CSV
  // `run,group,first_step,last_step,class[,annotator]` or JSON, chosen by the extension (.json,
  // otherwise CSV). Import adds the file's segments in file order (later rows win where they
  // overlap) to the set, creating it when absent, in one transaction: a file with any error changes
  // nothing. A provenance entry for a stored run whose step count or checksum differs from the
  // stored one is an error naming the file, the run and both values. Export writes a provenance
  // entry for every run of the set. Returns the number of segments read.
  Result<std::int64_t> importFile(const std::string& setName, const std::filesystem::path& file);
  Status exportFile(const std::string& setName, const std::filesystem::path& file);

  // Turns a run's truth columns into segments of the set (created when absent): maximal ranges of
  // one class per group, NoContact included, replacing the set's segments of that run. One
  // transaction per run. Returns the number of segments written; an error if the run has no truth.
  Result<std::int64_t> autolabel(std::int64_t runId, const std::string& setName);

 private:
  RunDatabase::Impl* impl_;
};

class ModelStore {
 public:
  explicit ModelStore(RunDatabase::Impl& impl) : impl_(&impl) {}
  // Stores a new model; a name already in use is an error naming it.
  Result<std::int64_t> add(const std::string& name, const std::string& json,
                           const std::string& trainedOnJson, const std::string& metricsJson);
  // One model's JSON.
  Result<std::string> load(const std::string& name);
  // Models by name (sorted), one model's record, deletes (all named or none, in one transaction;
  // an unknown name is an error naming it).
  Result<std::vector<ModelInfo>> list();
  Result<ModelInfo> info(std::string_view name);
  Status remove(const std::vector<std::string>& names);

 private:
  RunDatabase::Impl* impl_;
};

// Sweeps (storage/models.cpp): stored cell by cell as they run: create one, add each cell in its
// own transaction (a stopped sweep keeps the cells it finished), then record its final
// configuration and state.
class SweepStore {
 public:
  explicit SweepStore(RunDatabase::Impl& impl) : impl_(&impl) {}
  Result<std::int64_t> create(const std::string& name, const std::string& configurationJson);
  Result<std::int64_t> addCell(std::int64_t sweepId, const std::string& configurationJson,
                               const std::string& metricsJson);

  // ---- sweeps planned for workers (storage/sweep_claims.cpp, docs/cluster.md) ----
  // Creates a sweep with one pending claim per job (cellsPerJob[i] cells of job i, costing
  // costPerJob[i] in the sweep's cost model; empty: all alike), at once.
  Result<std::int64_t> plan(const std::string& name, const std::string& configurationJson,
                            const std::vector<std::int64_t>& cellsPerJob,
                            const std::vector<double>& costPerJob = {});
  // Claims one job for `worker` until `now + leaseSeconds` (Unix seconds): the most expensive
  // pending one (the first by job of equal cost), or a running one whose lease ran out (its worker
  // died); nullopt when none is left. PostgreSQL
  // locks the row (FOR UPDATE SKIP LOCKED), so workers claim side by side; SQLite claims in an
  // immediate transaction. A running claim taken over kSweepClaimAttempts times is failed.
  Result<std::optional<SweepClaim>> claim(std::int64_t sweepId, const std::string& worker,
                                          double now, double leaseSeconds);
  // Moves the lease of the worker's running claim to `leaseUntil`; false when the claim is no
  // longer the worker's (taken over, or done).
  Result<bool> renew(std::int64_t sweepId, std::int64_t job, const std::string& worker,
                     double leaseUntil);
  // Stores a job's cells ((settings, result) JSON pairs) and marks it done, in one transaction;
  // false, storing nothing, when the job is already done or failed (another worker took it over
  // and finished first), so every job's cells are stored once.
  Result<bool> complete(std::int64_t sweepId, std::int64_t job, const std::string& worker,
                        double seconds,
                        const std::vector<std::pair<std::string, std::string>>& cells);
  // Marks the worker's running claim failed with `error`.
  Status fail(std::int64_t sweepId, std::int64_t job, const std::string& worker,
              const std::string& error);
  // Gives the worker's running claim back (pending again): a worker that was stopped.
  Status release(std::int64_t sweepId, std::int64_t job, const std::string& worker);
  // Every claim of a sweep by job; empty for a sweep that was not planned for workers.
  Result<std::vector<SweepClaim>> claims(std::int64_t sweepId);
  Status update(std::int64_t sweepId, const std::string& configurationJson);
  Result<std::vector<SweepInfo>> list();
  Result<SweepInfo> info(std::int64_t sweepId);
  Result<std::vector<SweepCellRecord>> cells(std::int64_t sweepId);
  Status remove(const std::vector<std::int64_t>& sweepIds);

 private:
  RunDatabase::Impl* impl_;
};

// Whether `address` names a PostgreSQL server (a postgresql:// or postgres:// URI, or a libpq
// key=value string such as "host=/run/pg dbname=lab") rather than a file (docs/team.md#addresses).
bool isServerAddress(std::string_view address);
// `address` as it may be shown in messages and output: a password in it replaced by "***".
std::string shownAddress(std::string_view address);

// Fast 64-bit checksum of bytes as 16 hex digits (not cryptographic; detects re-imports).
std::string checksumHex(std::string_view bytes);
// The same checksum over bytes given in pieces: update() with each in order, then hex().
class RunningChecksum {
 public:
  void update(std::string_view bytes);
  std::string hex() const;

 private:
  void addBlock(const char* p);
  std::uint64_t a_ = 0x243F6A8885A308D3ull;
  std::uint64_t b_ = 0x13198A2E03707344ull;
  std::size_t total_ = 0;
  char block_[16] = {};
  std::size_t pending_ = 0;
};
// checksumHex of the run's file form (formatRunCsv), formatted in pieces on every core and never
// held whole: the checksum importRun and a finished recording store.
std::string runFileChecksumHex(const RunData& run);

// Block sizes (steps) of the stored min/max summaries, finest first.
inline constexpr std::array<std::int64_t, 4> kSummaryBlockSteps{16, 128, 1024, 8192};

}  // namespace tactile::storage
