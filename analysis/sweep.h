// Sweep engine: train and score one classifier per cell of a grid
// group x method x order x covariance form x variance floor x features x seed, on all cores.
//
// Shared work is done once: each (group, features) data set is extracted from the runs once and
// split into per-class training matrices once, then read by every cell of that group. Cells run
// on a pool of std::threads (each fit single-threaded); every cell's result depends only on its
// own settings and seed, so the result is identical whatever the thread count. Cancellable through
// the progress callback.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/classifier.h"
#include "analysis/features.h"
#include "analysis/gmm.h"
#include "analysis/metrics.h"
#include "analysis/temporal.h"
#include "base/error.h"
#include "base/progress.h"

namespace tactile::analysis {

struct SweepGrid {
  std::vector<SensorGroup> groups;  // empty = all eight
  std::vector<ClassifierMethod> methods{ClassifierMethod::Gmm};
  std::vector<int> orders{1, 2, 4, 8, 16, 32, 64};
  std::vector<CovarianceForm> forms{CovarianceForm::NodalFull, CovarianceForm::NodalDiag,
                                    CovarianceForm::GrandFull, CovarianceForm::GrandDiag};
  std::vector<double> varianceFloors{0.01, 0.03, 0.1};
  // Tree settings (method Gbt, analysis/gbt.h): every combination is a cell.
  std::vector<int> treeCounts{100};
  std::vector<int> depths{6};
  std::vector<double> learningRates{0.1};
  std::vector<double> minChildWeights{1.0};
  std::vector<FeatureKind> features{FeatureKind::Normal};
  std::vector<std::uint64_t> seeds{1};
  // Decision modes scored (temporal.h): cells that differ only in the decision share one fit;
  // online and offline use the class chain estimated from the training rows.
  std::vector<DecisionMode> decisions{DecisionMode::Step};
  // Settings shared by every cell.
  Regularization regularization = Regularization::Floor;
  GmmInit init = GmmInit::KMeansPlusPlus;
  int restarts = 1;
  int maxIterations = 100;
  double tolerance = 1e-3;
  PriorMode priors = PriorMode::Equal;
};

// One cell's settings. The Gaussian method has no order or form: its cells carry order 1 and
// nodal-full and appear once per (group, variance floor, features, seed, decision). Boosted trees
// have neither order, form nor floor (order 1, nodal-full, floor 0) but the tree settings, which
// are 0 in the cells of the other methods.
struct SweepCell {
  SensorGroup group = SensorGroup::Front;
  ClassifierMethod method = ClassifierMethod::Gmm;
  int order = 1;
  CovarianceForm form = CovarianceForm::NodalDiag;
  double varianceFloor = 0.0;
  FeatureKind features = FeatureKind::Normal;
  std::uint64_t seed = 1;
  DecisionMode decision = DecisionMode::Step;
  int trees = 0;
  int depth = 0;
  double learningRate = 0.0;
  double minChildWeight = 0.0;

  // Same cell (every setting equal).
  bool operator==(const SweepCell&) const = default;
};

// The classifier settings of one cell: its own settings with the grid's shared ones, one thread
// (results do not depend on it). A model trained with them reproduces the cell.
ClassifierOptions cellClassifierOptions(const SweepGrid& grid, const SweepCell& cell);

// The tree settings of a Gbt cell.
GbtSettings cellTreeSettings(const SweepCell& cell);

// Cells of a grid in a fixed order (group, features, method, form, order, variance floor, seed,
// decision; for trees: trees, depth, learning rate, min child weight, seed, decision).
std::vector<SweepCell> expandGrid(const SweepGrid& grid);
// The fit jobs of expanded cells: the grid positions of cells equal but for the decision mode
// (adjacent in grid order), which share one fit.
std::vector<std::vector<std::size_t>> fitJobs(const std::vector<SweepCell>& cells);
// The cost model of a sweep, for the order its jobs are handed out in (most expensive first, so
// that no worker is left alone with a long fit at the end) and the workbench's time estimate: every
// EM iteration visits each training row once per component (a Gaussian is one) at a cost per row
// of the feature dimension D (diagonal forms) or D^2 (full forms); prediction visits the test rows
// the same way. Boosted trees visit each training row once per feature and round (the histogram
// of every class's tree) and each test row once per tree level and round. In units of that work,
// +1 so that an empty cell costs something. No result depends on it.
double sweepCellUnits(const SweepCell& cell, std::size_t trainRows, std::size_t testRows);

struct SweepCellResult {
  SweepCell cell;
  bool ok = false;
  std::string reason;                    // why the cell has no model (ok == false)
  std::vector<ContactClass> classes;     // modelled classes
  std::vector<ContactClass> unmodelled;  // present in training data with too few samples
  std::size_t trainRows = 0;
  std::size_t testRows = 0;
  double fitSeconds = 0.0;
  double predictSeconds = 0.0;  // per-step evaluation, plus the filter for online / offline
  int iterations = 0;           // sum over the classes' fits
  int maxIterations = 0;        // largest single class fit
  bool converged = false;       // every class fit converged
  ConfusionMatrix confusion;
  Metrics metrics;                          // on the test rows
  std::optional<double> meanLogLikelihood;  // held-out, nats (heldOutLogLikelihood, classifier.h)
  std::size_t negInfRows = 0;               // test rows left out of it: log-likelihood -inf
  int droppedComponents = 0;                // sum over the classes' fits
  std::vector<std::string> warnings;        // ClassifierFit::warnings
  // Test rows by on/off pattern of the group's sensors, true and predicted class (thesis table
  // 4.39).
  ContactPatternTable patterns;
  // By-scene sweeps: each held-out scene's confusion (scored by the cell's settings trained
  // without that scene); `confusion` is their sum.
  std::vector<std::pair<std::string, ConfusionMatrix>> scenes;
};

// Per (group, features): how much data the cells saw.
struct SweepDataSummary {
  SensorGroup group = SensorGroup::Front;
  FeatureKind features = FeatureKind::Normal;
  std::size_t trainRows = 0;
  std::size_t testRows = 0;
  std::array<std::size_t, kContactClassCount> trainCounts{};
  std::array<std::size_t, kContactClassCount> testCounts{};
  std::size_t trainZeroRows = 0;
  std::size_t testZeroRows = 0;
};

struct SweepResult {
  std::vector<SweepCellResult> cells;  // in expandGrid order; only finished cells when cancelled
  std::vector<SweepDataSummary> data;
  bool cancelled = false;
  int threads = 1;
  double wallSeconds = 0.0;
  double extractSeconds = 0.0;  // the shared data extraction
  SweepGrid grid;
};

struct SweepOptions {
  int threads = 0;  // 0 = all cores
  // Called as each cell finishes, in finish order (serialised), with its result; not called for
  // a cell whose fit was stopped by cancellation.
  std::function<void(const SweepCellResult&)> onCell;
};

// Runs every cell: trains on `train`, scores on `test`. Progress: (cells done, cells), called
// after each finished cell and also after every EM iteration of every running fit (serialised);
// returning false cancels: running fits stop within one EM iteration, and the result has
// cancelled = true and only the cells that finished.
SweepResult runSweep(const std::vector<LabelledRun>& train, const std::vector<LabelledRun>& test,
                     const SweepGrid& grid, const SweepOptions& options = {},
                     const ProgressFn& progress = {});

// Leave-one-scene-out: for each scene, every cell is trained on the runs of the other scenes and
// scored on that scene's runs (sceneOfRun[i] names run i's scene); each cell's confusion is the
// sum over held-out scenes, its fit and predict times the sums, and `scenes` lists each scene's
// confusion. onCell sees each cell once, after its last scene. Needs two scenes or more.
SweepResult runSweepByScene(const std::vector<LabelledRun>& runs,
                            const std::vector<std::string>& sceneOfRun, const SweepGrid& grid,
                            const SweepOptions& options = {}, const ProgressFn& progress = {});

// The one check of a grid, used by every way a sweep is asked for (CLI, workbench, Python,
// stored plans): every list has a value, every order is a whole number from 1 to kMaxModelOrder,
// every floor is 0 or at least kMinVarianceFloor, every tree setting passes checkGbtSettings
// (when trees are swept), restarts and the iteration limit are at least
// 1, the tolerance is finite and not negative. The message names the first bad value.
Status checkSweepGrid(const SweepGrid& grid);

// The data of a sweep extracted once (per (group, features), and per held-out scene for a
// by-scene sweep) and its fit jobs: what runSweep runs on its threads, and what a worker of a
// distributed sweep (workspace/sweep_job.h) runs one claimed job at a time. A job is the cells
// equal but for the decision mode (they share one fit). runJob may be called from several threads
// at once; a job's result depends only on its cells' settings and seeds, so it is the same
// whichever process or thread computes it.
class SweepSession {
 public:
  // Train on `train`, score on `test`.
  SweepSession(const std::vector<LabelledRun>& train, const std::vector<LabelledRun>& test,
               const SweepGrid& grid);
  // Leave-one-scene-out over `runs` (sceneOfRun[i] names run i's scene), as runSweepByScene.
  SweepSession(const std::vector<LabelledRun>& runs, const std::vector<std::string>& sceneOfRun,
               const SweepGrid& grid);
  ~SweepSession();
  SweepSession(const SweepSession&) = delete;
  SweepSession& operator=(const SweepSession&) = delete;

  const SweepGrid& grid() const;
  const std::vector<SweepCell>& cells() const;  // expandGrid(grid)
  // Each job's grid positions (into cells()), in grid order.
  const std::vector<std::vector<std::size_t>>& jobs() const;
  const std::vector<SweepDataSummary>& data() const;
  double extractSeconds() const;
  // Rough relative cost of a job (expensive jobs first spreads the work best).
  double jobCost(std::size_t job) const;
  // The results of one job's cells, in its order; nullopt when `keepGoing` returned false and
  // the fit stopped before it was done.
  std::optional<std::vector<SweepCellResult>> runJob(std::size_t job,
                                                     const ProgressFn& keepGoing = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Runs every job of a session on options.threads threads, as runSweep does (which is this on a
// new session).
SweepResult runSweepSession(const SweepSession& session, const SweepOptions& options = {},
                            const ProgressFn& progress = {});

// The "grid" object of SWEEP.json (and of a stored sweep's configuration), and back.
nlohmann::json sweepGridToJson(const SweepGrid& grid);
Result<SweepGrid> sweepGridFromJson(const nlohmann::json& value);

// SWEEP.json: {"format":"tactile-sweep","version":1,"grid":{...},"data":[...],"threads",
// "wall_s","cancelled","cells":[{...}]}.
nlohmann::json sweepToJson(const SweepResult& result);
// All of it but "cells": what a database stores as a sweep's configuration beside its cells.
nlohmann::json sweepHeaderToJson(const SweepResult& result);
// One cell as written in SWEEP.json's "cells" (and stored per cell in a database), and its
// settings alone (group, method, order, covariance, floor, features, seed, decision; for trees
// also trees, depth, learning_rate and min_child_weight).
nlohmann::json sweepCellToJson(const SweepCellResult& cell);
nlohmann::json sweepCellSettingsToJson(const SweepCell& cell);
// {"Wall": 12, "Corner": 3, ...}: the classes with a non-zero count.
nlohmann::json classCountsToJson(const std::array<std::size_t, kContactClassCount>& counts);
// Reads everything sweepToJson wrote (grid, data, run settings, cells; metrics are recomputed
// from each cell's confusion matrix).
Result<SweepResult> sweepFromJson(const nlohmann::json& value);

}  // namespace tactile::analysis
