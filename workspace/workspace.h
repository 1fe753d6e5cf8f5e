// The workspace: one run database seen as the workbench and the CLI work with it. It lists runs,
// label sets, models and sweeps; loads runs and windows; edits labels so that every edit can be
// undone; trains, sweeps and classifies from stored runs and label sets, and keeps the models and
// sweep cells it makes (docs/workflow.md). No Qt: the GUI and the `tactile` verbs call the same
// functions, so they share one code path.
//
// One Workspace is one database connection: use it from one thread at a time.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/classify_run.h"
#include "analysis/model_file.h"
#include "analysis/sweep.h"
#include "analysis/training.h"
#include "base/error.h"
#include "base/progress.h"
#include "run/run.h"
#include "storage/run_database.h"

namespace tactile::workspace {

// How runs are split into training and test runs. Whole runs are held out, never steps of one
// run: neighbouring steps are nearly identical, so a step split would score on copies of the
// training data.
enum class SplitMode {
  ByRun,           // the given test runs; without any, every fourth run (by name) is held out
  LeaveOneRunOut,  // each run is scored by a model trained on all the others
  ByScene,         // each scene's runs are scored by a model trained without that scene
};
// "by-run", "leave-one-run-out", "by-scene".
std::optional<SplitMode> parseSplitMode(std::string_view name);
std::string_view splitModeName(SplitMode mode);

// Runs as a stored model's or sweep's provenance records them: [{"name","steps","checksum"}].
nlohmann::json runsJson(const std::vector<storage::RunInfo>& infos);

// The default hold-out: every fourth run by name is a test run, and at least one when there are
// two or more runs.
struct RunSplit {
  std::vector<std::string> train;
  std::vector<std::string> test;
};
RunSplit holdOutEveryFourth(std::vector<std::string> runs);

struct TrainRequest {
  std::string labelSet;
  std::vector<std::string> trainRuns;  // empty: every run the set labels, minus the test runs
  std::vector<std::string> testRuns;
  SplitMode split = SplitMode::ByRun;
  std::vector<SensorGroup> groups;                                      // empty: all eight
  analysis::GroupSettings settings = analysis::defaultGroupSettings();  // each group's own
  std::string modelName;  // empty: "<label set>-<n>", the first free n
  // A group with fewer labelled contact rows than this for training, or with fewer than two
  // classes that can be modelled, is skipped with a warning; the other groups train.
  std::size_t minRowsPerGroup = 20;
  // false: train and score only; storeTrained() stores the outcome afterwards (the workbench asks
  // first when a group scored 0 or had no test data).
  bool store = true;
};

// One group's outcome.
struct GroupTrainReport {
  SensorGroup group = SensorGroup::Front;
  bool trained = false;
  std::string skippedBecause;  // when not trained
  std::size_t samplesTrain = 0;
  std::size_t samplesTest = 0;
  // By the model's default decision; nullopt when nothing was scored (no test data), never 0.
  analysis::DecisionMode decision = analysis::DecisionMode::Online;
  std::optional<double> accuracy;
  std::optional<double> balancedAccuracy;
  std::array<std::optional<double>, analysis::kDecisionModeCount> balancedAccuracyByDecision{};
  std::optional<double> sceneMean;  // by-scene: mean over held-out scenes
  double fitSeconds = 0.0;
  std::vector<std::string> warnings;
  // True when a trained group had no test rows or scored 0 (worth a question before storing).
  bool doubtful() const { return trained && (!balancedAccuracy || *balancedAccuracy <= 0.0); }
};

struct TrainOutcome {
  std::string modelName;
  std::int64_t modelId = 0;
  analysis::ModelBundle bundle;
  std::vector<GroupTrainReport> groups;  // in the requested group order
  std::vector<std::string> trainRuns;
  std::vector<std::string> testRuns;  // empty for leave-one-run-out
  std::string evaluatedOn;            // "test runs", "leave-one-run-out", "training runs"
  nlohmann::json provenance;          // as stored with the model
};

// The summary `tactile train --db ... --json` prints and the Python module's `train(...).report`:
// {"model","id","label_set","train_runs","test_runs","split","evaluated_on","groups":[...]} with
// one analysis::groupReportJson entry per requested group.
nlohmann::json trainReportJson(const TrainOutcome& outcome, const TrainRequest& request);

// ---- sweeps (workspace/sweep_job.cpp, docs/cluster.md) ----------------------------------------

// Where a sweep's runs come from: stored runs of a database, or run files (`tactile sweep --runs`).
enum class SweepSource { Database, Files };

// One sweep as asked for, by the CLI (files and database), the workbench and the Python module
// alike; checked by checkSweepRequest, run by one function (a session over the selected data), and
// turned into JSON only where it is written to a file or a database.
struct SweepRequest {
  // Data selection. Database: a stored label set and stored run names. Run files: run-file paths,
  // labelled by `labelsFile` (empty: the runs' truth columns).
  std::string labelSet;
  std::vector<std::string> trainRuns;
  std::vector<std::string> testRuns;
  std::string labelsFile;
  // Run files without test runs: the last fraction of each run's steps is held out.
  double holdout = 0.3;
  // ByRun: train on trainRuns, score on testRuns. ByScene: no test runs; every scene of the
  // training runs is scored by cells trained without it. (LeaveOneRunOut is not offered.)
  SplitMode split = SplitMode::ByRun;
  analysis::SweepGrid grid;  // grid, decision modes, seeds and the settings shared by every cell
  std::string name;          // empty: defaultSweepName(labelSet, grid)
  int threads = 0;           // 0 = all cores
};

// A sweep's name from what it sweeps: the label set, then each setting with more than one value
// ("truth: order 1-16 x floor 0.01-0.1 x covariance nodal-full/nodal-diag"), or the one cell's
// settings when nothing varies; groups are named when not all eight.
std::string defaultSweepName(const std::string& labelSet, const analysis::SweepGrid& grid);

// The one check of a sweep request: the grid (analysis::checkSweepGrid), the split and the run
// selection, the name rule. The same bad request gets the same words from every front end.
Status checkSweepRequest(const SweepRequest& request, SweepSource source = SweepSource::Database);

// A sweep request as the CLI's options and the Python module's arguments spell it (names and
// numbers), parsed and checked in one place: unknown names and bad values are errors in the same
// words for both.
struct SweepRequestText {
  std::string labelSet;
  std::vector<std::string> trainRuns;
  std::vector<std::string> testRuns;
  std::string labelsFile;
  double holdout = 0.3;
  std::string split = "by-run";
  std::vector<std::string> groups;  // empty: all eight
  std::vector<std::string> methods{"gmm"};
  std::vector<int> orders{1, 2, 4, 8, 16, 32, 64};
  std::vector<std::string> covariances{"nodal-full", "nodal-diag", "grand-full", "grand-diag"};
  std::vector<double> floors{0.01, 0.03, 0.1};
  std::vector<int> trees{100};  // boosted trees' settings (method gbt)
  std::vector<int> depths{6};
  std::vector<double> learningRates{0.1};
  std::vector<double> minChildWeights{1.0};
  std::vector<std::string> features{"normal"};
  std::vector<std::uint64_t> seeds{1};
  std::vector<std::string> decisions{"step"};
  std::string reg = "floor";
  std::string init = "kmeans++";
  int restarts = 1;
  int maxIterations = 100;
  double tolerance = 1e-3;
  std::string name;
  int threads = 0;
};
Result<SweepRequest> parseSweepRequest(const SweepRequestText& text,
                                       SweepSource source = SweepSource::Database);

// The selected data of a sweep, however it was read: labelled training and test runs, and the
// scene of each training run (by-scene).
struct SweepData {
  std::vector<analysis::LabelledRun> train;
  std::vector<analysis::LabelledRun> test;
  std::vector<std::string> sceneOfTrain;
};
// The session (data extracted once, fit jobs) of a request over its data, after the split's checks
// (by-scene: at least two scenes). Every way of running a sweep starts here.
Result<std::unique_ptr<analysis::SweepSession>> makeSweepSession(const SweepRequest& request,
                                                                 const SweepData& data);

// A sweep stored for workers (Workspace::planSweep).
struct PlannedSweep {
  std::int64_t sweepId = 0;
  std::size_t cells = 0;
  std::size_t jobs = 0;
};

// What a worker does (Workspace::workSweep).
struct WorkOptions {
  int threads = 1;           // claims in flight at once (each fit single-threaded); 0 = all cores
  std::size_t maxCells = 0;  // stop after storing at least this many cells (0: until none is left)
  std::string worker;        // the name claims carry (empty: host:pid)
  double leaseSeconds = 120.0;
  // A read-only copy of the database (an SQLite snapshot on node-local disk) to read the runs
  // and labels from; empty: this database.
  std::filesystem::path data;
};
struct WorkReport {
  std::size_t jobs = 0;       // jobs this worker stored
  std::size_t cells = 0;      // their cells
  std::size_t failed = 0;     // jobs that failed here
  std::size_t overtaken = 0;  // jobs another worker finished first (after this one's lease ran out)
  bool cancelled = false;
  double seconds = 0.0;
  double extractSeconds = 0.0;
  // Time spent claiming jobs and storing their cells (the database's share of the work).
  double claimStoreSeconds = 0.0;
};

// Where a planned sweep stands (Workspace::sweepStatus): counts in cells, the claims that run or
// failed, and an estimate of the time left.
struct SweepStatus {
  std::int64_t sweepId = 0;
  std::string name;
  std::string state;  // "planned", "running", "finished", "failed", "cancelled"
  std::size_t cells = 0, done = 0, pending = 0, running = 0, failed = 0;
  std::vector<storage::SweepClaim> runningClaims;
  std::vector<storage::SweepClaim> failedClaims;
  std::optional<double> secondsLeft;  // from the done jobs' times and the workers running
  bool planned = true;                // false: an older sweep run in one process (no claims)
};
nlohmann::json sweepStatusJson(const SweepStatus& status, double now);

// Single quotes for a POSIX shell.
std::string shellQuoted(const std::string& text);
// The commands that fill planned sweep `sweepId` of `database` (a file, made absolute, or a server
// address shown without its password), as `tactile sweep plan` prints them and the workbench shows
// them to copy: one worker process of one thread, and a Slurm job array of `workers` such tasks.
std::string sweepWorkCommand(const std::string& database, std::int64_t sweepId);
std::string sweepSubmitCommand(const std::string& database, std::int64_t sweepId, int workers);

struct SweepOutcome {
  std::int64_t sweepId = 0;
  analysis::SweepResult result;
};

// An applied label edit: the segments of the touched (set, run, group) before and after it. Undo
// puts `before` back exactly (ranges, classes and annotators; segment ids may change).
struct LabelEdit {
  std::int64_t setId = 0;
  std::int64_t runId = 0;
  SensorGroup group = SensorGroup::Front;
  std::vector<storage::LabelSegment> before;
  std::vector<storage::LabelSegment> after;
  std::int64_t segmentId = 0;  // the added or changed segment (0 for a removal)
  // The revision its last application (the edit, an undo or a redo) made.
  std::int64_t revision = 0;
};

// How far a run's labels agree with its truth in one group, over the steps the labels cover.
struct GroupAgreement {
  SensorGroup group = SensorGroup::Front;
  std::int64_t comparedSteps = 0;  // labelled steps (the truth covers every step)
  std::int64_t agreeingSteps = 0;
  std::optional<double> percent;  // 100 * agreeing / compared; nullopt with nothing compared
  std::optional<double> kappa;    // Cohen's kappa (analysis::cohensKappa)
  // The agreement expected by chance from the two raters' class shares, in percent:
  // 100 * sum over classes of (share in one) * (share in the other). Kappa is
  // (agree - chance) / (100 - chance): a high agreement with a chance near it gives a kappa near
  // 0, and a chance of 100 (one class throughout on both sides) leaves kappa undefined.
  std::optional<double> chancePercent;
};
// Per group in group order; `segments` are one run's label segments of any groups (not
// overlapping within a group). Empty when the track has no truth.
std::vector<GroupAgreement> truthAgreement(const storage::RunTrack& track,
                                           const std::vector<storage::LabelSegment>& segments);
// Two label sets of one run against each other (annotator against annotator), per group in group
// order, over the steps of [0, stepCount) that both label.
std::vector<GroupAgreement> labelAgreement(std::int64_t stepCount,
                                           const std::vector<storage::LabelSegment>& first,
                                           const std::vector<storage::LabelSegment>& second);

// ---- labels from a model (workspace/label_from_model.cpp, docs/workflow.md#labels-from-a-model)
// -- The annotator a model's labels carry in the segments and the history: "model:NAME".
std::string modelAnnotator(std::string_view modelName);
// The segments one group's classification gives steps [first, last] by its chosen decision:
// maximal stretches of one class; steps no model could say stay unlabelled.
std::vector<storage::LabelSegment> decisionSegments(const analysis::GroupClassification& group,
                                                    SensorGroup sensorGroup, std::int64_t first,
                                                    std::int64_t last,
                                                    const std::string& annotator);

struct ModelLabelling {
  std::int64_t runs = 0;
  std::int64_t groups = 0;    // (run, group) pairs labelled
  std::int64_t segments = 0;  // segments written
  std::vector<std::string> warnings;
};

class Workspace {
 public:
  // Opens a database (OpenOptions choose create / existing / read-only).
  static Result<std::unique_ptr<Workspace>> open(const std::filesystem::path& path,
                                                 const storage::OpenOptions& options = {});
  explicit Workspace(std::unique_ptr<storage::RunDatabase> database);

  // The database's stores (storage/run_database.h); what the workbench and the CLI edit or read
  // beside the jobs below goes through these.
  storage::RunStore runStore() { return db_->runs(); }
  storage::LabelStore labelStore() { return db_->labels(); }
  storage::ModelStore modelStore() { return db_->models(); }
  storage::SweepStore sweepStore() { return db_->sweeps(); }
  // Where the database is (a file, or a server address without password) and how it was opened.
  const std::filesystem::path& databasePath() const { return db_->path(); }
  bool readOnly() const { return db_->readOnly(); }
  storage::RunDatabase::Rights rights() { return db_->rights(); }
  storage::IntegrityReport check() { return db_->check(); }

  // ---- listing ----
  Result<std::vector<storage::RunCatalogEntry>> runs() { return db_->runs().catalog(); }
  Result<std::vector<storage::LabelSetCatalogEntry>> labelSets() { return db_->labels().catalog(); }
  Result<std::vector<storage::ModelInfo>> models() { return db_->models().list(); }
  Result<std::vector<storage::SweepInfo>> sweeps() { return db_->sweeps().list(); }

  // ---- runs ----
  Result<RunData> loadRun(std::string_view name);
  Result<storage::RunWindow> loadWindow(std::string_view name, std::int64_t firstStep,
                                        std::int64_t count);
  // Pose, command, blocked flag and truth of every step, without the sensor values.
  Result<storage::RunTrack> loadTrack(std::string_view name);
  // Percent of each run's group-steps (steps x 8) that the set's segments cover, by run id.
  Result<std::vector<std::pair<std::int64_t, double>>> labelCoverage(std::int64_t setId);
  // The same for the part a model labelled (annotator "model:NAME"; the rest is people's).
  Result<std::vector<std::pair<std::int64_t, double>>> modelLabelCoverage(std::int64_t setId);

  // ---- label edits, each one transaction, each returning what it replaced ----
  // `options` name the annotator and the revision the edit is based on (a conflict stores
  // nothing: storage::isLabelConflict).
  Result<LabelEdit> addSegment(std::int64_t setId, const storage::LabelSegment& segment,
                               const storage::EditOptions& options = {});
  Result<LabelEdit> changeSegment(std::int64_t setId, std::int64_t segmentId,
                                  const storage::LabelSegment& segment,
                                  const storage::EditOptions& options = {});
  Result<LabelEdit> removeSegment(std::int64_t setId, std::int64_t segmentId,
                                  const storage::EditOptions& options = {});
  // Steps [first, last] of one group of a run take `segments` (within the range; labels outside
  // it stay as they are), as one edit (action "model" unless options say otherwise).
  Result<LabelEdit> replaceLabels(std::int64_t setId, std::int64_t runId, SensorGroup group,
                                  std::int64_t first, std::int64_t last,
                                  std::vector<storage::LabelSegment> segments,
                                  const storage::EditOptions& options = {});
  // Every named run (empty: every stored run) takes a stored model's offline decision in the
  // named groups (empty: every group the model covers) over the whole run, in the set (created
  // when absent), one edit per run and group with the annotator "model:NAME".
  Result<ModelLabelling> labelFromModel(const std::string& setName, const std::string& modelName,
                                        const std::vector<std::string>& runs,
                                        const std::vector<SensorGroup>& groups,
                                        const ProgressFn& progress = {});
  // Puts the touched range of the edit back as it was before the edit (undo), or as it was after
  // it (redo); edit.revision becomes the revision this made.
  Status undo(LabelEdit& edit, const storage::EditOptions& options = {});
  Status redo(LabelEdit& edit, const storage::EditOptions& options = {});

  // ---- learning ----
  // Trains one model per group on the label set's segments of the stored runs, scores it as the
  // split says, stores the bundle with its provenance under a free name and returns it.
  Result<TrainOutcome> train(const TrainRequest& request, const ProgressFn& progress = {});
  // Stores an outcome of train() with request.store == false under request.modelName (or the
  // first free "<label set>-<n>").
  Result<TrainOutcome> storeTrained(TrainOutcome outcome, const TrainRequest& request);
  // Stores a sweep with every fit job pending, for workers (`tactile sweep plan`): the request is
  // checked and its label set, runs and scenes looked up first; nothing is fitted. Each job carries
  // its cost (analysis::sweepCellUnits of its group's labelled contact rows): the workers claim the
  // most expensive first.
  Result<PlannedSweep> planSweep(const SweepRequest& request);
  // Claims pending jobs of a planned sweep one at a time (options.threads at once) and stores
  // each job's cells once (`tactile sweep work`); onCell sees each stored cell, progress gets
  // (cells done, cells) and stops the work when it returns false (running claims go back to
  // pending). When no job is left it records the sweep's final state.
  Result<WorkReport> workSweep(
      std::int64_t sweepId, const WorkOptions& options,
      const std::function<void(const analysis::SweepCellResult&)>& onCell = {},
      const ProgressFn& progress = {});
  Result<SweepStatus> sweepStatus(std::int64_t sweepId);
  // A stored sweep's request (grid, label set, runs, split, name), read back from its
  // configuration; `configuration` gets the configuration itself.
  Result<SweepRequest> plannedRequest(std::int64_t sweepId,
                                      nlohmann::json* configuration = nullptr);
  // A sweep in one process: planSweep, then workSweep with request.threads (a cancelled sweep
  // keeps its finished cells; its other jobs stay pending for `tactile sweep work`). onCell sees
  // each stored cell.
  Result<SweepOutcome> sweep(
      const SweepRequest& request,
      const std::function<void(const analysis::SweepCellResult&)>& onCell = {},
      const ProgressFn& progress = {});
  // A stored sweep read back into a SweepResult (for reports).
  Result<analysis::SweepResult> loadSweep(std::int64_t sweepId);
  // Per group (in group order), the steps of the named runs that the label set labels and where
  // the group touches something: the rows a model of that group trains on or is scored on.
  Result<std::array<std::size_t, kGroupCount>> labelledContactSteps(
      std::string_view labelSet, const std::vector<std::string>& runs);
  // A stored model bundle.
  Result<analysis::ModelBundle> loadModel(std::string_view name);

  // ---- model files (workspace_models.cpp) ----
  // Writes a stored model to a model file through the one model reader and writer, so the file
  // is exactly what training writes. Nothing is left at `out` on failure.
  Status exportModel(std::string_view name, const std::filesystem::path& out);
  // Stores a model file (checked by the model reader) under `name`, or the file's stem when empty;
  // returns the stored name. A taken name is an error.
  Result<std::string> importModel(const std::filesystem::path& file, std::string name = {});
  // Trains the model of one sweep cell (index into loadSweep(sweepId).cells): the cell's group and
  // settings with the sweep's shared settings, on the sweep's label set and training runs, scored
  // on its test runs, and stored under `modelName` (empty: "sweep<id>-<group>-cell<index>", made
  // unique; short and within the name rule). Its test confusion equals the cell's: same data,
  // settings and seed. With `store` false the model is trained and scored only (modelId 0), for a
  // model file that is not to become a stored model.
  Result<TrainOutcome> trainSweepCell(std::int64_t sweepId, std::size_t cellIndex,
                                      std::string modelName = {}, const ProgressFn& progress = {},
                                      bool store = true);
  // Classifies a stored run with a stored model; the bundle is returned beside the result, which
  // points into it.
  struct Classified {
    std::unique_ptr<analysis::ModelBundle> bundle;
    RunData run;
    analysis::RunClassification result;
  };
  Result<Classified> classify(std::string_view modelName, std::string_view runName,
                              const analysis::ClassifyOptions& options = {});

 private:
  // A stored sweep's configuration (its grid, data selection and state), parsed.
  static Result<nlohmann::json> sweepConfigurationOf(const storage::SweepInfo& info);
  // Loads the named runs and the set's labels for them; every name must be a stored run.
  struct Labelled {
    std::vector<std::unique_ptr<RunData>> runs;
    std::vector<analysis::LabelledRun> labelled;
    std::vector<storage::RunInfo> infos;
  };
  Result<Labelled> loadLabelled(std::int64_t setId, const std::vector<std::string>& names);

  std::unique_ptr<storage::RunDatabase> db_;
};

// The program's version, stored with every model.
std::string_view programVersion();

}  // namespace tactile::workspace
