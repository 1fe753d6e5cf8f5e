#include "analysis/sweep.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "analysis/training.h"
#include "base/parallel.h"
#include "base/text_rules.h"
#include "run/json_text.h"

namespace tactile::analysis {

using nlohmann::json;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Data shared by every cell of one (group, features): extracted once, read-only afterwards.
struct SharedGroupData {
  GroupDataSet train;
  GroupDataSet test;
  std::vector<std::string> testPatterns;  // on/off pattern of every test row
  ClassSelection selection;
  std::vector<Eigen::MatrixXd> perClass;  // training rows of each modelled class
  std::vector<std::string> names;
  TransitionModel chain;  // from the training rows' label sequences
};

std::vector<SensorGroup> groupsOf(const SweepGrid& grid) {
  if (!grid.groups.empty()) return grid.groups;
  std::vector<SensorGroup> all;
  for (const GroupInfo& info : kSensorGroups)
    all.push_back(info.group);
  return all;
}

int dataKey(SensorGroup g, FeatureKind f) {
  return groupIndex(g) * 8 + static_cast<int>(f);
}

// Fits the classifier of `cells` (cells equal but for the decision) once and scores each decision.
std::vector<SweepCellResult> runCells(const std::vector<SweepCell>& cells, const SweepGrid& grid,
                                      const SharedGroupData& data, const ProgressFn& keepGoing) {
  SweepCellResult r;
  r.cell = cells.front();
  r.trainRows = data.train.size();
  r.testRows = data.test.size();
  r.classes = data.selection.modelled;
  r.unmodelled = data.selection.unmodelled;
  auto each = [&cells](const SweepCellResult& base) {
    std::vector<SweepCellResult> out;
    for (const SweepCell& c : cells) {
      out.push_back(base);
      out.back().cell = c;
    }
    return out;
  };
  if (data.train.size() == 0) {
    r.reason = "no labelled contact samples";
    return each(r);
  }
  if (data.perClass.empty()) {
    r.reason = "no class has enough samples (at least max(2, D))";
    return each(r);
  }
  const ClassifierOptions options = cellClassifierOptions(grid, cells.front());
  const ClassifierFit fit = trainClassifier(data.perClass, data.names, options, keepGoing);
  r.fitSeconds = fit.fitSeconds;
  r.warnings = fit.warnings;
  if (!fit.ok) {
    r.reason = fit.reason;
    return each(r);
  }
  r.converged = true;
  for (std::size_t c = 0; c < fit.iterations.size(); ++c) {
    r.iterations += fit.iterations[c];
    r.maxIterations = std::max(r.maxIterations, fit.iterations[c]);
    if (c < fit.converged.size() && !fit.converged[c]) r.converged = false;
    if (c < fit.droppedComponents.size()) r.droppedComponents += fit.droppedComponents[c];
  }
  bool temporal = false;
  for (const SweepCell& c : cells)
    temporal = temporal || c.decision != DecisionMode::Step;
  TransitionModel chain = data.chain;
  chain.emissionWeight = defaultEmissionWeight(r.cell.group, r.cell.method);
  const GroupEvaluation ev = evaluateClassifier(fit.model, data.selection.modelled, data.test,
                                                &data.testPatterns, temporal ? &chain : nullptr);
  r.patterns = ev.patterns;
  r.meanLogLikelihood = ev.meanLogLikelihood;
  r.negInfRows = ev.negInfRows;
  r.ok = true;
  std::vector<SweepCellResult> out = each(r);
  for (SweepCellResult& o : out) {
    const DecisionMode mode = o.cell.decision;
    o.confusion = ev.byDecision[decisionIndex(mode)];
    o.metrics = computeMetrics(o.confusion);
    // The per-step evaluation, plus (for online and offline) the time of both filters.
    o.predictSeconds = ev.predictSeconds + (mode == DecisionMode::Step ? 0.0 : ev.decideSeconds);
    if (mode != DecisionMode::Step) o.patterns = ContactPatternTable{r.cell.group, {}};
  }
  return out;
}

}  // namespace

ClassifierOptions cellClassifierOptions(const SweepGrid& grid, const SweepCell& cell) {
  ClassifierOptions options;
  options.method = cell.method;
  options.priors = grid.priors;
  options.oneVsRest = false;
  options.threads = 1;
  options.gmm.components = cell.method == ClassifierMethod::Gaussian ? 1 : cell.order;
  options.gmm.form = cell.form;
  options.gmm.varianceFloor = cell.varianceFloor;
  options.gmm.reg = grid.regularization;
  options.gmm.init = grid.init;
  options.gmm.seed = cell.seed;
  options.gmm.restarts = grid.restarts;
  options.gmm.maxIterations = grid.maxIterations;
  options.gmm.tolerance = grid.tolerance;
  options.gmm.threads = 1;
  if (cell.method == ClassifierMethod::Gbt) options.gbt = cellTreeSettings(cell);
  return options;
}

GbtSettings cellTreeSettings(const SweepCell& cell) {
  GbtSettings s;
  s.trees = cell.trees;
  s.depth = cell.depth;
  s.learningRate = cell.learningRate;
  s.minChildWeight = cell.minChildWeight;
  s.seed = cell.seed;
  return s;
}

namespace {
std::vector<DecisionMode> decisionsOf(const SweepGrid& grid) {
  if (grid.decisions.empty()) return {DecisionMode::Step};
  return grid.decisions;
}
}  // namespace

std::vector<SweepCell> expandGrid(const SweepGrid& grid) {
  std::vector<SweepCell> cells;
  for (SensorGroup g : groupsOf(grid)) {
    for (FeatureKind f : grid.features) {
      for (ClassifierMethod m : grid.methods) {
        if (m == ClassifierMethod::Gaussian) {
          for (double floor : grid.varianceFloors) {
            for (std::uint64_t seed : grid.seeds) {
              for (DecisionMode d : decisionsOf(grid))
                cells.push_back({g, m, 1, CovarianceForm::NodalFull, floor, f, seed, d});
            }
          }
          continue;
        }
        if (m == ClassifierMethod::Gbt) {
          for (int trees : grid.treeCounts) {
            for (int depth : grid.depths) {
              for (double rate : grid.learningRates) {
                for (double weight : grid.minChildWeights) {
                  for (std::uint64_t seed : grid.seeds) {
                    for (DecisionMode d : decisionsOf(grid)) {
                      cells.push_back({g, m, 1, CovarianceForm::NodalFull, 0.0, f, seed, d, trees,
                                       depth, rate, weight});
                    }
                  }
                }
              }
            }
          }
          continue;
        }
        for (CovarianceForm form : grid.forms) {
          for (int order : grid.orders) {
            for (double floor : grid.varianceFloors) {
              for (std::uint64_t seed : grid.seeds) {
                for (DecisionMode d : decisionsOf(grid))
                  cells.push_back({g, m, order, form, floor, f, seed, d});
              }
            }
          }
        }
      }
    }
  }
  return cells;
}

namespace {
// The shortest text that reads back as v: -0.1, not -0.10000000000000001.
std::string numberText(double v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}
}  // namespace

Status checkSweepGrid(const SweepGrid& grid) {
  if (grid.methods.empty()) return Status::failure("a sweep needs at least one method");
  if (grid.features.empty()) return Status::failure("a sweep needs at least one feature kind");
  const auto uses = [&grid](ClassifierMethod m) {
    return std::find(grid.methods.begin(), grid.methods.end(), m) != grid.methods.end();
  };
  const bool mixtures = uses(ClassifierMethod::Gmm) || uses(ClassifierMethod::Gaussian);
  if (mixtures && grid.varianceFloors.empty())
    return Status::failure("a sweep needs at least one variance floor");
  if (uses(ClassifierMethod::Gbt)) {
    if (grid.treeCounts.empty() || grid.depths.empty() || grid.learningRates.empty() ||
        grid.minChildWeights.empty()) {
      return Status::failure(
          "a sweep of boosted trees needs at least one tree count, depth, learning rate and "
          "minimum child weight");
    }
    for (int trees : grid.treeCounts) {
      for (int depth : grid.depths) {
        for (double rate : grid.learningRates) {
          for (double weight : grid.minChildWeights) {
            const std::string bad = checkGbtSettings({trees, depth, rate, weight});
            if (!bad.empty()) return Status::failure(bad);
          }
        }
      }
    }
  }
  if (grid.seeds.empty()) return Status::failure("a sweep needs at least one seed");
  const bool gmm = std::find(grid.methods.begin(), grid.methods.end(), ClassifierMethod::Gmm) !=
                   grid.methods.end();
  if (gmm && grid.orders.empty()) return Status::failure("a sweep needs at least one model order");
  if (gmm && grid.forms.empty())
    return Status::failure("a sweep needs at least one covariance form");
  for (int order : grid.orders) {
    if (order < 1 || order > kMaxModelOrder) {
      return Status::failure("model order " + std::to_string(order) +
                             " is out of range: an order is a whole number from 1 to " +
                             std::to_string(kMaxModelOrder));
    }
  }
  for (double floor : grid.varianceFloors) {
    if (!(floor == 0.0 || (floor >= kMinVarianceFloor && std::isfinite(floor)))) {
      return Status::failure("variance floor " + numberText(floor) +
                             " is out of range: a floor is 0 (none) or a finite number of at "
                             "least " +
                             numberText(kMinVarianceFloor));
    }
  }
  if (grid.restarts < 1) return Status::failure("restarts must be at least 1");
  if (grid.maxIterations < 1) return Status::failure("the iteration limit must be at least 1");
  if (!(grid.tolerance >= 0.0 && std::isfinite(grid.tolerance)))
    return Status::failure("the tolerance must be a finite number of at least 0");
  return Status::success();
}

namespace {

// One split of the data: the shared data of every (group, features) of the grid, with what each
// held (SweepDataSummary).
struct Fold {
  std::string scene;  // the held-out scene (by-scene), empty otherwise
  std::map<int, SharedGroupData> shared;
  std::vector<SweepDataSummary> data;
};

void prepareFold(Fold& fold, const std::vector<LabelledRun>& train,
                 const std::vector<LabelledRun>& test, const std::vector<SweepCell>& cells) {
  for (const SweepCell& cell : cells) {
    const int key = dataKey(cell.group, cell.features);
    if (fold.shared.count(key) != 0) continue;
    SharedGroupData& d = fold.shared[key];
    d.train = buildGroupDataSet(train, cell.group, cell.features);
    d.test = buildGroupDataSet(test, cell.group, cell.features);
    d.testPatterns = rowPatterns(d.test, test);
    d.selection = selectClasses(d.train);
    for (ContactClass c : d.selection.modelled) {
      d.perClass.push_back(d.train.rowsOf(c));
      d.names.emplace_back(contactClassName(c));
    }
    d.chain = estimateTransitions(classSequences(d.train, d.selection.modelled),
                                  static_cast<int>(d.selection.modelled.size()));
    // The chain weighs the evidence as the group's trained mixtures do by default (runCells sets
    // each method's own default), so that the online and offline scores of a cell are those of
    // the model trained with its settings.
    d.chain.emissionWeight = defaultEmissionWeight(cell.group, ClassifierMethod::Gmm);
    SweepDataSummary s;
    s.group = cell.group;
    s.features = cell.features;
    s.trainRows = d.train.size();
    s.testRows = d.test.size();
    s.trainCounts = d.train.classCounts();
    s.testCounts = d.test.classCounts();
    s.trainZeroRows = d.train.zeroRows;
    s.testZeroRows = d.test.zeroRows;
    fold.data.push_back(s);
  }
}

// Leave-one-scene-out: one cell's results of every fold, in scene order, as one result: the
// confusions summed, each scene's kept, fit and predict times summed.
SweepCellResult mergeSceneFolds(const std::vector<SweepCellResult>& folds,
                                const std::vector<std::string>& scenes) {
  SweepCellResult c = folds.front();
  c.scenes = {{scenes.front(), c.confusion}};
  for (std::size_t f = 1; f < folds.size(); ++f) {
    const SweepCellResult& it = folds[f];
    if (!it.ok) {
      c.scenes.emplace_back(scenes[f], ConfusionMatrix());
      continue;
    }
    if (!c.ok) {
      // The first scenes gave no model; this one does: keep its settings' outcome.
      const auto previous = c.scenes;
      c = it;
      c.scenes = previous;
      c.confusion = ConfusionMatrix();
    } else {
      c.fitSeconds += it.fitSeconds;
      c.predictSeconds += it.predictSeconds;
      c.iterations += it.iterations;
      c.maxIterations = std::max(c.maxIterations, it.maxIterations);
      c.converged = c.converged && it.converged;
      c.testRows += it.testRows;
      c.negInfRows += it.negInfRows;
      c.droppedComponents += it.droppedComponents;
    }
    c.confusion.merge(it.confusion);
    c.scenes.emplace_back(scenes[f], it.confusion);
  }
  c.metrics = computeMetrics(c.confusion);
  // A pooled mean log-likelihood over scenes is not kept (each fold has its own models).
  if (scenes.size() > 1) c.meanLogLikelihood.reset();
  c.patterns = ContactPatternTable{c.cell.group, {}};
  return c;
}

}  // namespace

struct SweepSession::Impl {
  SweepGrid grid;
  bool byScene = false;
  std::vector<SweepCell> cells;
  std::vector<std::vector<std::size_t>> jobs;
  std::vector<double> cost;
  std::vector<Fold> folds;
  std::vector<SweepDataSummary> data;
  double extractSeconds = 0.0;

  void planJobs() {
    jobs = fitJobs(cells);
    for (const std::vector<std::size_t>& job : jobs) {
      const SweepCell& c = cells[job.front()];
      const SharedGroupData& d = folds.front().shared.at(dataKey(c.group, c.features));
      cost.push_back(sweepCellUnits(c, d.train.size(), d.test.size()));
    }
    // The data summary: the first fold's, with every fold's test rows (by-scene).
    data = folds.front().data;
    for (std::size_t f = 1; f < folds.size(); ++f) {
      for (std::size_t d = 0; d < data.size() && d < folds[f].data.size(); ++d) {
        data[d].testRows += folds[f].data[d].testRows;
        for (std::size_t k = 0; k < kContactClassCount; ++k)
          data[d].testCounts[k] += folds[f].data[d].testCounts[k];
      }
    }
  }
};

SweepSession::SweepSession(const std::vector<LabelledRun>& train,
                           const std::vector<LabelledRun>& test, const SweepGrid& grid)
    : impl_(std::make_unique<Impl>()) {
  const auto start = Clock::now();
  if (Status ok = checkSweepGrid(grid); !ok) throw std::invalid_argument(ok.errorText());
  impl_->grid = grid;
  impl_->cells = expandGrid(grid);
  impl_->folds.resize(1);
  prepareFold(impl_->folds.front(), train, test, impl_->cells);
  impl_->planJobs();
  impl_->extractSeconds = secondsSince(start);
}

SweepSession::SweepSession(const std::vector<LabelledRun>& runs,
                           const std::vector<std::string>& sceneOfRun, const SweepGrid& grid)
    : impl_(std::make_unique<Impl>()) {
  const auto start = Clock::now();
  if (Status ok = checkSweepGrid(grid); !ok) throw std::invalid_argument(ok.errorText());
  impl_->grid = grid;
  impl_->byScene = true;
  impl_->cells = expandGrid(grid);
  std::vector<std::string> scenes;
  for (const std::string& s : sceneOfRun)
    if (std::find(scenes.begin(), scenes.end(), s) == scenes.end()) scenes.push_back(s);
  if (scenes.empty()) scenes.emplace_back();
  impl_->folds.resize(scenes.size());
  for (std::size_t f = 0; f < scenes.size(); ++f) {
    std::vector<LabelledRun> train, test;
    for (std::size_t r = 0; r < runs.size() && r < sceneOfRun.size(); ++r)
      (sceneOfRun[r] == scenes[f] ? test : train).push_back(runs[r]);
    impl_->folds[f].scene = scenes[f];
    prepareFold(impl_->folds[f], train, test, impl_->cells);
  }
  impl_->planJobs();
  impl_->extractSeconds = secondsSince(start);
}

SweepSession::~SweepSession() = default;

const SweepGrid& SweepSession::grid() const {
  return impl_->grid;
}
const std::vector<SweepCell>& SweepSession::cells() const {
  return impl_->cells;
}
const std::vector<std::vector<std::size_t>>& SweepSession::jobs() const {
  return impl_->jobs;
}
const std::vector<SweepDataSummary>& SweepSession::data() const {
  return impl_->data;
}
double SweepSession::extractSeconds() const {
  return impl_->extractSeconds;
}
double SweepSession::jobCost(std::size_t job) const {
  return impl_->cost.at(job);
}

std::optional<std::vector<SweepCellResult>> SweepSession::runJob(
    std::size_t job, const ProgressFn& keepGoing) const {
  std::vector<SweepCell> jobCells;
  for (std::size_t i : impl_->jobs.at(job))
    jobCells.push_back(impl_->cells[i]);
  const SweepCell& first = jobCells.front();
  const int key = dataKey(first.group, first.features);
  bool stopped = false;
  const ProgressFn watched = [&](std::size_t done, std::size_t total) {
    const bool go = !keepGoing || keepGoing(done, total);
    stopped = stopped || !go;
    return go;
  };
  if (!impl_->byScene) {
    std::vector<SweepCellResult> rs =
        runCells(jobCells, impl_->grid, impl_->folds.front().shared.at(key), watched);
    // A fit stopped by cancellation is not a result.
    if (stopped && !rs.front().ok) return std::nullopt;
    return rs;
  }
  std::vector<std::string> scenes;
  std::vector<std::vector<SweepCellResult>> byFold;
  for (const Fold& fold : impl_->folds) {
    scenes.push_back(fold.scene);
    byFold.push_back(runCells(jobCells, impl_->grid, fold.shared.at(key), watched));
    if (stopped && !byFold.back().front().ok) return std::nullopt;
  }
  std::vector<SweepCellResult> out;
  for (std::size_t n = 0; n < jobCells.size(); ++n) {
    std::vector<SweepCellResult> folds;
    for (const std::vector<SweepCellResult>& rs : byFold)
      folds.push_back(rs[n]);
    out.push_back(mergeSceneFolds(folds, scenes));
  }
  return out;
}

namespace {

// Every job of a session on a pool of threads, expensive jobs first; the slot of each result is
// its grid position.
SweepResult runSession(const SweepSession& session, const SweepOptions& options,
                       const ProgressFn& progress, Clock::time_point wallStart) {
  SweepResult result;
  result.grid = session.grid();
  result.data = session.data();
  result.extractSeconds = session.extractSeconds();
  const std::vector<SweepCell>& cells = session.cells();
  const auto& jobs = session.jobs();
  std::vector<std::size_t> order(jobs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&session](std::size_t a, std::size_t b) {
    return session.jobCost(a) > session.jobCost(b);
  });

  const unsigned threads =
      workerThreadCount(static_cast<unsigned>(std::max(options.threads, 0)), jobs.size());
  result.threads = static_cast<int>(threads);

  std::vector<std::optional<SweepCellResult>> slots(cells.size());
  std::atomic<bool> cancel{false};
  std::mutex progressMutex;
  std::size_t done = 0;
  if (progress && !progress(0, cells.size())) cancel = true;
  // Consulted by every running fit after each EM iteration (through trainClassifier).
  const ProgressFn keepGoing = [&](std::size_t, std::size_t) {
    if (cancel.load()) return false;
    if (!progress) return true;
    std::lock_guard<std::mutex> lock(progressMutex);
    if (cancel.load()) return false;
    if (!progress(done, cells.size())) cancel = true;
    return !cancel.load();
  };

  // An exception in any job (out of memory) reaches the caller after every worker has stopped.
  parallelFor(order.size(), threads, [&](std::size_t k) {
    if (cancel.load()) return false;
    const std::vector<std::size_t>& job = jobs[order[k]];
    std::optional<std::vector<SweepCellResult>> rs = session.runJob(order[k], keepGoing);
    if (!rs) return false;
    std::lock_guard<std::mutex> lock(progressMutex);
    for (std::size_t n = 0; n < job.size(); ++n) {
      slots[job[n]] = (*rs)[n];
      ++done;
      if (options.onCell) options.onCell((*rs)[n]);
    }
    if (!cancel.load() && progress && !progress(done, cells.size())) cancel = true;
    return !cancel.load();
  });

  result.cancelled = cancel.load();
  for (std::optional<SweepCellResult>& s : slots) {
    if (s) result.cells.push_back(std::move(*s));
  }
  result.wallSeconds = secondsSince(wallStart);
  return result;
}

}  // namespace

std::vector<std::vector<std::size_t>> fitJobs(const std::vector<SweepCell>& cells) {
  std::vector<std::vector<std::size_t>> jobs;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    SweepCell key = cells[i];
    bool joined = false;
    if (!jobs.empty()) {
      SweepCell last = cells[jobs.back().front()];
      last.decision = key.decision;
      joined = last == key;
    }
    if (joined) {
      jobs.back().push_back(i);
    } else {
      jobs.push_back({i});
    }
  }
  return jobs;
}

double sweepCellUnits(const SweepCell& cell, std::size_t trainRows, std::size_t testRows) {
  const double d = featureDimension(cell.group, cell.features);
  if (cell.method == ClassifierMethod::Gbt) {
    const double rounds = static_cast<double>(std::max(cell.trees, 1));
    return static_cast<double>(trainRows) * d * rounds +
           static_cast<double>(testRows) * static_cast<double>(std::max(cell.depth, 1)) * rounds +
           1.0;
  }
  const double perRow = isDiagonal(cell.form) ? d : d * d;
  const double components =
      cell.method == ClassifierMethod::Gaussian ? 1.0 : static_cast<double>(cell.order);
  return static_cast<double>(trainRows + testRows) * components * perRow + 1.0;
}

SweepResult runSweepSession(const SweepSession& session, const SweepOptions& options,
                            const ProgressFn& progress) {
  return runSession(session, options, progress, Clock::now());
}

SweepResult runSweep(const std::vector<LabelledRun>& train, const std::vector<LabelledRun>& test,
                     const SweepGrid& grid, const SweepOptions& options,
                     const ProgressFn& progress) {
  const auto wallStart = Clock::now();
  const SweepSession session(train, test, grid);
  return runSession(session, options, progress, wallStart);
}

SweepResult runSweepByScene(const std::vector<LabelledRun>& runs,
                            const std::vector<std::string>& sceneOfRun, const SweepGrid& grid,
                            const SweepOptions& options, const ProgressFn& progress) {
  const auto wallStart = Clock::now();
  const SweepSession session(runs, sceneOfRun, grid);
  return runSession(session, options, progress, wallStart);
}

namespace {

json classList(const std::vector<ContactClass>& classes) {
  json out = json::array();
  for (ContactClass c : classes)
    out.push_back(contactClassName(c));
  return out;
}

}  // namespace

json classCountsToJson(const std::array<std::size_t, kContactClassCount>& counts) {
  json out = json::object();
  for (int c = 0; c < kContactClassCount; ++c) {
    if (counts[static_cast<std::size_t>(c)] > 0) {
      out[std::string(kContactClassNames[static_cast<std::size_t>(c)])] =
          counts[static_cast<std::size_t>(c)];
    }
  }
  return out;
}

json sweepCellSettingsToJson(const SweepCell& cell) {
  json c;
  c["group"] = groupInfo(cell.group).shortName;
  c["method"] = classifierMethodName(cell.method);
  c["order"] = cell.order;
  c["covariance"] = covarianceFormName(cell.form);
  c["floor"] = cell.varianceFloor;
  c["features"] = featureKindName(cell.features);
  c["seed"] = cell.seed;
  c["decision"] = decisionModeName(cell.decision);
  if (cell.method == ClassifierMethod::Gbt) {
    c["trees"] = cell.trees;
    c["depth"] = cell.depth;
    c["learning_rate"] = cell.learningRate;
    c["min_child_weight"] = cell.minChildWeight;
  }
  return c;
}

json sweepCellToJson(const SweepCellResult& r) {
  json c = sweepCellSettingsToJson(r.cell);
  c["ok"] = r.ok;
  if (!r.ok) c["reason"] = r.reason;
  c["classes"] = classList(r.classes);
  c["unmodelled"] = classList(r.unmodelled);
  c["train_rows"] = r.trainRows;
  c["test_rows"] = r.testRows;
  c["fit_s"] = r.fitSeconds;
  c["predict_s"] = r.predictSeconds;
  c["iterations"] = r.iterations;
  c["max_iterations"] = r.maxIterations;
  c["converged"] = r.converged;
  // No test rows: nothing was scored, which is not a rate of 0.
  const bool scored = r.confusion.total() > 0;
  c["scored"] = scored;
  c["accuracy"] = scored ? json(r.metrics.accuracy) : json(nullptr);
  c["balanced_accuracy"] = scored ? json(r.metrics.balancedAccuracy) : json(nullptr);
  c["macro_f1"] = scored ? json(r.metrics.macroF1) : json(nullptr);
  c["mean_loglik"] = r.meanLogLikelihood ? json(*r.meanLogLikelihood) : json(nullptr);
  c["neg_inf_rows"] = r.negInfRows;
  c["dropped_components"] = r.droppedComponents;
  c["warnings"] = r.warnings;
  json rates = json::object(), support = json::object();
  for (const ClassMetrics& m : r.metrics.perClass) {
    if (m.recall) rates[std::string(contactClassName(m.label))] = *m.recall;
    if (m.support > 0) support[std::string(contactClassName(m.label))] = m.support;
  }
  c["rates"] = std::move(rates);
  c["test_steps"] = std::move(support);
  c["confusion"] = confusionToJson(r.confusion);
  if (!r.patterns.rows.empty()) c["patterns"] = patternsToJson(r.patterns);
  if (!r.scenes.empty()) {
    json scenes = json::array();
    for (const auto& [scene, confusion] : r.scenes) {
      const bool any = confusion.total() > 0;
      scenes.push_back({{"scene", scene},
                        {"test_rows", confusion.total()},
                        {"balanced_accuracy",
                         any ? json(computeMetrics(confusion).balancedAccuracy) : json(nullptr)},
                        {"confusion", confusionToJson(confusion)}});
    }
    c["scenes"] = std::move(scenes);
  }
  return c;
}

json sweepGridToJson(const SweepGrid& g) {
  json grid;
  json groups = json::array();
  for (SensorGroup s : groupsOf(g))
    groups.push_back(groupInfo(s).shortName);
  grid["groups"] = std::move(groups);
  json methods = json::array();
  for (ClassifierMethod m : g.methods)
    methods.push_back(classifierMethodName(m));
  grid["methods"] = std::move(methods);
  grid["orders"] = g.orders;
  json forms = json::array();
  for (CovarianceForm f : g.forms)
    forms.push_back(covarianceFormName(f));
  grid["covariances"] = std::move(forms);
  grid["floors"] = g.varianceFloors;
  grid["trees"] = g.treeCounts;
  grid["depths"] = g.depths;
  grid["learning_rates"] = g.learningRates;
  grid["min_child_weights"] = g.minChildWeights;
  json features = json::array();
  for (FeatureKind f : g.features)
    features.push_back(featureKindName(f));
  grid["features"] = std::move(features);
  grid["seeds"] = g.seeds;
  json decisions = json::array();
  for (DecisionMode d : decisionsOf(g))
    decisions.push_back(decisionModeName(d));
  grid["decisions"] = std::move(decisions);
  grid["regularization"] = regularizationName(g.regularization);
  grid["init"] = gmmInitName(g.init);
  grid["restarts"] = g.restarts;
  grid["max_iterations"] = g.maxIterations;
  grid["tolerance"] = g.tolerance;
  grid["priors"] = priorModeName(g.priors);
  return grid;
}

json sweepToJson(const SweepResult& result) {
  json out = sweepHeaderToJson(result);
  json cells = json::array();
  for (const SweepCellResult& r : result.cells)
    cells.push_back(sweepCellToJson(r));
  out["cells"] = std::move(cells);
  return out;
}

json sweepHeaderToJson(const SweepResult& result) {
  json out;
  out["format"] = "tactile-sweep";
  out["version"] = 1;
  out["grid"] = sweepGridToJson(result.grid);
  json data = json::array();
  for (const SweepDataSummary& s : result.data) {
    data.push_back({{"group", groupInfo(s.group).shortName},
                    {"features", featureKindName(s.features)},
                    {"train_rows", s.trainRows},
                    {"test_rows", s.testRows},
                    {"train_classes", classCountsToJson(s.trainCounts)},
                    {"test_classes", classCountsToJson(s.testCounts)},
                    {"train_zero_rows", s.trainZeroRows},
                    {"test_zero_rows", s.testZeroRows}});
  }
  out["data"] = std::move(data);
  out["threads"] = result.threads;
  out["wall_s"] = result.wallSeconds;
  out["extract_s"] = result.extractSeconds;
  out["cancelled"] = result.cancelled;
  return out;
}

namespace {

template <typename T, typename Parse>
bool parseList(const json& v, const char* key, std::vector<T>& out, Parse parse) {
  out.clear();
  if (!v.contains(key) || !v[key].is_array()) return false;
  for (const json& e : v[key]) {
    if (!e.is_string()) return false;
    auto p = parse(e.get<std::string>());
    if (!p) return false;
    out.push_back(*p);
  }
  return true;
}

}  // namespace

namespace {

// Fills `g` from a grid object; returns what is wrong, empty when nothing is.
std::string readGrid(const json& grid, SweepGrid& g) {
  try {
    if (!parseList(grid, "groups", g.groups, parseSensorGroup)) return "grid: bad 'groups'";
    if (!parseList(grid, "methods", g.methods, parseClassifierMethod)) return "grid: bad 'methods'";
    if (!parseList(grid, "covariances", g.forms, parseCovarianceForm))
      return "grid: bad 'covariances'";
    if (!parseList(grid, "features", g.features, parseFeatureKind)) return "grid: bad 'features'";
    g.orders = grid.value("orders", std::vector<int>{});
    g.varianceFloors = grid.value("floors", std::vector<double>{});
    g.seeds = grid.value("seeds", std::vector<std::uint64_t>{});
    // Sweeps from before boosted trees have no tree settings: the defaults.
    const SweepGrid treeDefaults;
    g.treeCounts = grid.value("trees", treeDefaults.treeCounts);
    g.depths = grid.value("depths", treeDefaults.depths);
    g.learningRates = grid.value("learning_rates", treeDefaults.learningRates);
    g.minChildWeights = grid.value("min_child_weights", treeDefaults.minChildWeights);
    // Sweeps from before decision modes scored the per-step decision only.
    if (grid.contains("decisions")) {
      if (!parseList(grid, "decisions", g.decisions, parseDecisionMode))
        return "grid: bad 'decisions'";
    } else {
      g.decisions = {DecisionMode::Step};
    }
    const SweepGrid defaults;
    const auto reg = parseRegularization(
        grid.value("regularization", std::string(regularizationName(defaults.regularization))));
    const auto init = parseGmmInit(grid.value("init", std::string(gmmInitName(defaults.init))));
    const auto priors =
        parsePriorMode(grid.value("priors", std::string(priorModeName(defaults.priors))));
    if (!reg || !init || !priors) return "grid: unknown regularization, init or priors";
    g.regularization = *reg;
    g.init = *init;
    g.priors = *priors;
    g.restarts = grid.value("restarts", defaults.restarts);
    g.maxIterations = grid.value("max_iterations", defaults.maxIterations);
    g.tolerance = grid.value("tolerance", defaults.tolerance);
  } catch (const json::exception& e) {
    return "grid: " + plainJsonError(e);
  }
  return {};
}

// Fills `out`; returns what is wrong, empty when nothing is.
std::string readSweep(const json& value, SweepResult& out) {
  out = SweepResult();
  try {
    if (!value.is_object() || value.value("format", "") != "tactile-sweep") {
      return "not a sweep file (expected \"format\": \"tactile-sweep\")";
    }
    if (value.value("version", 0) != 1) return "unsupported sweep file version";
    if (std::string error = readGrid(value.at("grid"), out.grid); !error.empty()) return error;
    for (const json& d : value.value("data", json::array())) {
      SweepDataSummary s;
      const auto group = parseSensorGroup(d.at("group").get<std::string>());
      const auto features = parseFeatureKind(d.at("features").get<std::string>());
      if (!group || !features) return "data: unknown group or features";
      s.group = *group;
      s.features = *features;
      s.trainRows = d.value("train_rows", std::size_t{0});
      s.testRows = d.value("test_rows", std::size_t{0});
      for (const auto& [key, counts] :
           {std::pair{"train_classes", &s.trainCounts}, std::pair{"test_classes", &s.testCounts}}) {
        const json classes = d.value(key, json::object());
        for (const auto& [name, count] : classes.items()) {
          const auto c = parseContactClass(name);
          if (!c) return "data: unknown class " + quotedInput(name);
          (*counts)[static_cast<std::size_t>(*c)] = count.get<std::size_t>();
        }
      }
      s.trainZeroRows = d.value("train_zero_rows", std::size_t{0});
      s.testZeroRows = d.value("test_zero_rows", std::size_t{0});
      out.data.push_back(s);
    }
    out.threads = value.value("threads", 1);
    out.wallSeconds = value.value("wall_s", 0.0);
    out.extractSeconds = value.value("extract_s", 0.0);
    out.cancelled = value.value("cancelled", false);
    const json& cells = value.at("cells");
    if (!cells.is_array()) return "'cells' is not an array";
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const json& c = cells[i];
      const std::string where = "cells[" + std::to_string(i) + "]: ";
      SweepCellResult r;
      const auto group = parseSensorGroup(c.at("group").get<std::string>());
      const auto method = parseClassifierMethod(c.at("method").get<std::string>());
      const auto form = parseCovarianceForm(c.at("covariance").get<std::string>());
      const auto features = parseFeatureKind(c.at("features").get<std::string>());
      if (!group || !method || !form || !features) return where + "unknown group/method/form";
      r.cell = {*group,
                *method,
                c.at("order").get<int>(),
                *form,
                c.at("floor").get<double>(),
                *features,
                c.value("seed", std::uint64_t{1}),
                DecisionMode::Step};
      if (c.contains("decision")) {
        const auto d = parseDecisionMode(c.value("decision", std::string()));
        if (!d) return where + "unknown decision";
        r.cell.decision = *d;
      }
      if (r.cell.method == ClassifierMethod::Gbt) {
        r.cell.trees = c.at("trees").get<int>();
        r.cell.depth = c.at("depth").get<int>();
        r.cell.learningRate = c.at("learning_rate").get<double>();
        r.cell.minChildWeight = c.at("min_child_weight").get<double>();
      }
      r.ok = c.at("ok").get<bool>();
      r.reason = c.value("reason", "");
      for (const auto& [key, list] :
           {std::pair{"classes", &r.classes}, std::pair{"unmodelled", &r.unmodelled}}) {
        for (const json& n : c.value(key, json::array())) {
          const auto cls = parseContactClass(n.get<std::string>());
          if (!cls) return where + "unknown class " + quotedInput(n.get<std::string>());
          list->push_back(*cls);
        }
      }
      r.trainRows = c.value("train_rows", std::size_t{0});
      r.testRows = c.value("test_rows", std::size_t{0});
      r.fitSeconds = c.value("fit_s", 0.0);
      r.predictSeconds = c.value("predict_s", 0.0);
      r.iterations = c.value("iterations", 0);
      r.maxIterations = c.value("max_iterations", 0);
      r.converged = c.value("converged", false);
      if (c.contains("mean_loglik") && c["mean_loglik"].is_number()) {
        r.meanLogLikelihood = c["mean_loglik"].get<double>();
      }
      r.negInfRows = c.value("neg_inf_rows", std::size_t{0});
      r.droppedComponents = c.value("dropped_components", 0);
      r.warnings = c.value("warnings", std::vector<std::string>{});
      if (!confusionFromJson(c.at("confusion"), r.confusion)) return where + "bad confusion";
      // Sweeps stored before contact patterns were kept have none.
      r.patterns.group = r.cell.group;
      if (c.contains("patterns") && !patternsFromJson(c["patterns"], r.cell.group, r.patterns))
        return where + "bad patterns";
      for (const json& sc : c.value("scenes", json::array())) {
        ConfusionMatrix m;
        if (!confusionFromJson(sc.value("confusion", json::object()), m))
          return where + "bad scene confusion";
        r.scenes.emplace_back(sc.value("scene", std::string()), m);
      }
      r.metrics = computeMetrics(r.confusion);
      out.cells.push_back(std::move(r));
    }
  } catch (const json::exception& e) {
    return "malformed sweep file: " + plainJsonError(e);
  }
  return {};
}

}  // namespace

Result<SweepGrid> sweepGridFromJson(const json& value) {
  SweepGrid grid;
  if (!value.is_object()) return Error("grid: not an object");
  if (std::string error = readGrid(value, grid); !error.empty()) return Error(std::move(error));
  return grid;
}

Result<SweepResult> sweepFromJson(const json& value) {
  SweepResult out;
  if (std::string error = readSweep(value, out); !error.empty()) return Error(std::move(error));
  return out;
}

}  // namespace tactile::analysis
