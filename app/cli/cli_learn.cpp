// Learning verbs on labelled runs: train, sweep, report, classify.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "analysis/classify_run.h"
#include "analysis/features.h"
#include "analysis/model_file.h"
#include "analysis/report.h"
#include "analysis/sweep.h"
#include "analysis/temporal.h"
#include "analysis/training.h"
#include "app/cli/cli_classifier_options.h"
#include "app/cli/cli_common.h"
#include "app/cli/cli_labels.h"
#include "app/cli/cli_sweep.h"
#include "base/file_text.h"
#include "base/text_rules.h"
#include "run/json_text.h"
#include "run/label_file.h"
#include "run/run_csv.h"
#include "storage/run_database.h"  // storage::checksumHex, the run-file checksum of label files
#include "workspace/workspace.h"

namespace tactile::cli {

workspace::SweepRequest sweepRequestOrUsage(const workspace::SweepRequestText& text,
                                            workspace::SweepSource source) {
  auto request = workspace::parseSweepRequest(text, source);
  if (!request) throw UsageError(request.errorText());
  return request.value();
}

void addSweepRequestOptions(CLI::App* cmd, workspace::SweepRequestText& r) {
  cmd->add_option("--set", r.labelSet, "Label set (with --db)");
  cmd->add_option("--train-runs", r.trainRuns, "Stored runs to train on (with --db)")
      ->delimiter(',');
  cmd->add_option("--name", r.name, "Name of the stored sweep (with --db)");
  cmd->add_option("--test-runs", r.testRuns,
                  "Score on these runs (stored run names with --db, A B or A,B; run files "
                  "otherwise, A B, instead of a holdout)");
  cmd->add_option("--groups", r.groups, "Groups (default all)")->delimiter(',');
  cmd->add_option("--methods", r.methods, "gmm, gaussian and/or gbt (boosted trees)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--orders", r.orders, "Model orders")->delimiter(',')->capture_default_str();
  cmd->add_option("--covs", r.covariances, "Covariance forms")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--floors", r.floors, "Variance floors")->delimiter(',')->capture_default_str();
  cmd->add_option("--trees", r.trees, "Boosting rounds (gbt)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--depths", r.depths, "Largest tree depths (gbt)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--learning-rates", r.learningRates, "Learning rates (gbt)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--min-child-weights", r.minChildWeights, "Least leaf weights (gbt)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--features", r.features, "Feature kinds")->delimiter(',')->capture_default_str();
  cmd->add_option("--seeds", r.seeds, "Seeds")->delimiter(',')->capture_default_str();
  cmd->add_option("--decisions", r.decisions,
                  "Decision modes scored: step, online (HMM forward filter), offline "
                  "(forward-backward); cells differing only here share one fit")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--split", r.split,
                  "by-run (--test-runs, else the --holdout of each run) or by-scene (each "
                  "scene's runs scored by cells trained without it)")
      ->capture_default_str();
  cmd->add_option("--reg", r.reg, "floor or add")->capture_default_str();
  cmd->add_option("--init", r.init, "kmeans++ or random-from-data")->capture_default_str();
  cmd->add_option("--restarts", r.restarts, "EM restarts per fit")->capture_default_str();
  cmd->add_option("--max-iter", r.maxIterations, "EM iteration limit")->capture_default_str();
  cmd->add_option("--tol", r.tolerance, "Relative convergence tolerance")->capture_default_str();
  cmd->add_option("--threads", r.threads, "Worker threads (0 = all cores)")->capture_default_str();
}

namespace {

using analysis::ClassifierMethod;
using analysis::CovarianceForm;
using analysis::FeatureKind;
using analysis::LabelledRun;
using analysis::parseClassifierMethod;
using analysis::parseCovarianceForm;
using analysis::parseGmmInit;
using analysis::parseRegularization;
using nlohmann::json;

// Labels of each loaded run: from the label file when given (matched by matchLabelRuns), else
// from the run's truth columns.
void attachLabels(LoadedRuns& loaded, const std::string& labelsPath) {
  LabelFile file;
  std::vector<std::string> nameOf(loaded.runs.size());
  if (!labelsPath.empty()) {
    file = readLabels(labelsPath);
    nameOf = matchLabelRuns(loaded, labelsPath, file);
  }
  const std::vector<LabelRecord>& segments = file.records;
  for (std::size_t i = 0; i < loaded.runs.size(); ++i) {
    const RunData& run = loaded.runs[i];
    const std::string& path = loaded.paths[i];
    LabelledRun lr{&run, {}};
    if (labelsPath.empty()) {
      if (!run.hasTruth()) {
        throw std::runtime_error(path + ": the run has no truth_* columns; give --labels");
      }
      lr.labels = analysis::labelsFromTruth(run);
    } else {
      const std::filesystem::path p(path);
      const std::string& name = nameOf[i];
      if (name.empty()) {
        printWarning(labelsPath + ": no label segments for run '" + p.stem().string() + "' (" +
                     path + ")");
      }
      auto labels = analysis::labelsFromSegments(run, name, segments);
      if (!labels) throw std::runtime_error(labelsPath + ": " + labels.errorText());
      lr.labels = std::move(labels.value());
    }
    loaded.labelled.push_back(std::move(lr));
  }
}

std::vector<SensorGroup> parseGroups(const std::vector<std::string>& names) {
  std::vector<SensorGroup> out;
  for (const std::string& n : names) {
    const auto g = parseSensorGroup(n);
    if (!g)
      throw UsageError("unknown group " + quotedInput(n) +
                       " (expected F, FLC, L, RLC, B, RRC, R, FRC)");
    out.push_back(*g);
  }
  return out;
}

template <typename T, typename Parse>
std::vector<T> parseNames(const std::vector<std::string>& names, Parse parse, const char* what) {
  std::vector<T> out;
  for (const std::string& n : names) {
    const auto v = parse(n);
    if (!v) throw UsageError(std::string("unknown ") + what + " " + quotedInput(n));
    out.push_back(*v);
  }
  return out;
}

FeatureKind parseFeatures(const std::string& name) {
  const auto f = analysis::parseFeatureKind(name);
  if (!f)
    throw UsageError("unknown --features '" + name +
                     "' (normal, magnitude, normal+shear, normal+shear+touch, "
                     "normal+shear+touch+context, normal+shear+touch+context+neighbours, "
                     "normal+shear+touch+motion, normal+shear+touch+motion+neighbours)");
  return *f;
}

void writeText(const std::string& path, const std::string& text) {
  if (path.empty() || path == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return;
  }
  const Status written = writeFileAtomically(path, text);
  if (!written) throw std::runtime_error(written.errorText());
}

// ---------------------------------------------------------------------------------------------
// train

struct TrainArgs {
  std::string db;  // database form: --db DB --set SET
  std::string set;
  std::vector<std::string> trainRuns;
  std::string split = "by-run";
  std::string name;
  std::size_t minRows = 20;
  std::vector<std::string> runs;
  std::vector<std::string> testRuns;
  std::string labels;
  // Unless given, --method, --order, --cov, --floor, --restarts, --trees, --depth, --learning-rate,
  // --min-child-weight and --features are each group's default (analysis::defaultGroupSettings(),
  // the workbench's too).
  ClassifierArgs classifier;
  std::string features;
  std::string decision = "online";
  std::optional<double> emissionWeight;  // unless given, each group's own
  struct Given {
    bool method = false, order = false, cov = false, floor = false, restarts = false;
    bool trees = false, depth = false, learningRate = false, minChildWeight = false;
    bool anyTrees() const { return trees || depth || learningRate || minChildWeight; }
  } given;
  std::vector<std::string> groups;
  double holdout = 0.0;
  std::string out;
  bool json = false;
};

// The workspace of a verb's --db: training and sweeping may create the database, reading verbs
// (report, classify) open it read-only.
std::unique_ptr<workspace::Workspace> openWorkspace(const std::string& path, bool create) {
  return std::make_unique<workspace::Workspace>(create ? openDatabaseOrCreate(path)
                                                       : openDatabaseForRead(path));
}

// Before any long work: the output can be written and is none of the verb's inputs
// (docs/cli.md#output-files).
void checkOutput(const std::string& path, const std::vector<std::string>& inputs) {
  if (path.empty() || path == "-") return;
  const Status writable = checkWritable(path);
  if (!writable) throw std::runtime_error(writable.errorText());
  const Status distinct =
      checkNotAnInput(path, std::vector<std::filesystem::path>(inputs.begin(), inputs.end()));
  if (!distinct) throw std::runtime_error(distinct.errorText());
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b,
                                const std::string& c = {}) {
  a.insert(a.end(), b.begin(), b.end());
  if (!c.empty()) a.push_back(c);
  return a;
}

std::string percentText(const std::optional<double>& v) {
  if (!v) return "  n/a ";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%5.1f%%", 100.0 * *v);
  return buffer;
}

// Warnings (skipped groups, fit warnings) on stderr, then the summary: one JSON object, or text.
void printTrainSummary(const std::vector<analysis::GroupJobReport>& reports,
                       const analysis::ModelBundle& bundle, const std::string& evaluatedOn,
                       bool asJson, json doc, const std::string& headline) {
  json groupsJson = json::array();
  for (const analysis::GroupJobReport& r : reports) {
    const std::string g(groupInfo(r.group).shortName);
    if (!r.trained) {
      std::string keep;
      for (const analysis::GroupJobReport& q : reports)
        if (q.trained && q.group != r.group)
          keep += (keep.empty() ? "" : ",") + std::string(groupInfo(q.group).shortName);
      printWarning("group " + g + " skipped: " + r.skippedBecause +
                   (keep.empty() ? std::string() : "; leave it out with --groups " + keep));
    }
    for (const std::string& w : r.warnings)
      printWarning("group " + g + ": " + w);
    groupsJson.push_back(analysis::groupReportJson(r, bundle.find(r.group)));
  }
  if (asJson) {
    doc["evaluated_on"] = evaluatedOn;
    if (!doc.contains("groups")) doc["groups"] = std::move(groupsJson);
    std::cout << dumpJson(doc) << "\n";
    return;
  }
  std::printf("%s\n", headline.c_str());
  std::printf("  %-4s %7s %7s  %-7s %8s %8s %8s %8s\n", "", "train", "test", "default", "balanced",
              "step", "online", "offline");
  for (const analysis::GroupJobReport& r : reports) {
    const analysis::GroupModel* m = bundle.find(r.group);
    if (!r.trained || m == nullptr) continue;
    const analysis::ModelEvaluation& e = m->evaluation;
    if (!e.scored()) {
      std::printf("  %-4s %7zu %7d  (no test data: not scored)\n",
                  std::string(groupInfo(r.group).shortName).c_str(), r.samplesTrain, 0);
      continue;
    }
    std::printf("  %-4s %7zu %7zu  %-7s %8s %8s %8s %8s\n",
                std::string(groupInfo(r.group).shortName).c_str(), r.samplesTrain, e.samplesTest(),
                std::string(analysis::decisionModeName(m->decision)).c_str(),
                percentText(e.balancedAccuracy(m->decision)).c_str(),
                percentText(e.balancedAccuracy(analysis::DecisionMode::Step)).c_str(),
                percentText(e.balancedAccuracy(analysis::DecisionMode::Online)).c_str(),
                percentText(e.balancedAccuracy(analysis::DecisionMode::Offline)).c_str());
    for (const analysis::SceneScore& sc : e.scenes) {
      const analysis::ConfusionMatrix& c = sc.byDecision[analysis::decisionIndex(m->decision)];
      std::printf("         held-out scene %-28s %7zu test  %s\n", sc.scene.c_str(), c.total(),
                  c.total() > 0 ? percentText(analysis::computeMetrics(c).balancedAccuracy).c_str()
                                : "no test data");
    }
    if (!e.scenes.empty()) {
      std::printf("         mean over held-out scenes %s\n",
                  percentText(analysis::meanSceneBalancedAccuracy(e.scenes, m->decision)).c_str());
    }
  }
}

analysis::EvaluationSplit parseFileSplit(const std::string& name) {
  if (name == "by-run") return analysis::EvaluationSplit::TestRuns;
  if (name == "leave-one-run-out") return analysis::EvaluationSplit::LeaveOneRunOut;
  if (name == "by-scene") return analysis::EvaluationSplit::ByScene;
  throw UsageError("unknown --split " + quotedInput(name) +
                   " (by-run, leave-one-run-out, by-scene)");
}

int runTrainDb(const TrainArgs& a, const analysis::GroupSettings& settings,
               const std::vector<SensorGroup>& groups) {
  if (a.set.empty()) throw UsageError("--db needs --set SET (the label set to train on)");
  if (!a.name.empty()) requireValidName(a.name, "--name", "model");
  if (!a.runs.empty() || !a.labels.empty() || a.holdout > 0.0) {
    throw UsageError(
        "--runs, --labels and --holdout are for run files; with --db use "
        "--train-runs, --test-runs and --split");
  }
  const auto split = workspace::parseSplitMode(a.split);
  if (!split) {
    throw UsageError("unknown --split " + quotedInput(a.split) +
                     " (by-run, leave-one-run-out, by-scene)");
  }
  checkOutput(a.out, {a.db});
  auto ws = openWorkspace(a.db, true);
  workspace::TrainRequest request;
  request.labelSet = a.set;
  request.trainRuns = a.trainRuns;
  request.testRuns = splitNames(a.testRuns);
  request.split = *split;
  request.groups = groups;
  request.settings = settings;
  request.modelName = a.name;
  request.minRowsPerGroup = a.minRows;
  auto outcome = ws->train(request);
  if (!outcome) throw std::runtime_error(a.db + ": " + outcome.errorText());
  const workspace::TrainOutcome& o = outcome.value();
  if (!a.out.empty()) {
    const Status written = analysis::writeModelBundleFile(a.out, o.bundle);
    if (!written) throw std::runtime_error(written.errorText());
  }
  std::vector<analysis::GroupJobReport> reports;
  for (const workspace::GroupTrainReport& r : o.groups)
    reports.push_back({r.group, r.trained, r.skippedBecause, r.samplesTrain, r.warnings});
  // The same summary as the Python module's train(...).report.
  json doc = workspace::trainReportJson(o, request);
  if (!a.out.empty()) doc["out"] = a.out;
  std::string headline = "stored model '" + o.modelName + "' (" +
                         std::to_string(o.bundle.models.size()) + " group model(s)) in " + a.db +
                         "; scored on " + o.evaluatedOn;
  if (!a.out.empty()) headline += "; wrote " + a.out;
  printTrainSummary(reports, o.bundle, o.evaluatedOn, a.json, std::move(doc), headline);
  return kExitOk;
}

// Each group's default settings, with what the command line gave applied to every group.
analysis::GroupSettings trainSettings(const TrainArgs& a) {
  const analysis::ClassifierOptions typed = toClassifierOptions(a.classifier);
  analysis::GroupSettings out = analysis::defaultGroupSettings();
  for (const GroupInfo& info : kSensorGroups) {
    const SensorGroup g = info.group;
    analysis::TrainSettings& s = out.of(g);
    analysis::ClassifierOptions o = typed;
    // Options of one family without --method train that family (--order 16 means mixtures).
    const auto method =
        analysis::impliedMethod(a.given.method ? std::optional(typed.method) : std::nullopt,
                                a.given.order || a.given.cov || a.given.floor || a.given.restarts,
                                a.given.anyTrees(), s.classifier.method);
    if (!method) throw UsageError(method.errorText());
    o.method = method.value();
    if (!a.given.order) o.gmm.components = s.classifier.gmm.components;
    if (!a.given.cov) o.gmm.form = s.classifier.gmm.form;
    if (!a.given.floor) o.gmm.varianceFloor = s.classifier.gmm.varianceFloor;
    if (!a.given.restarts) o.gmm.restarts = s.classifier.gmm.restarts;
    if (!a.given.trees) o.gbt.trees = s.classifier.gbt.trees;
    if (!a.given.depth) o.gbt.depth = s.classifier.gbt.depth;
    if (!a.given.learningRate) o.gbt.learningRate = s.classifier.gbt.learningRate;
    if (!a.given.minChildWeight) o.gbt.minChildWeight = s.classifier.gbt.minChildWeight;
    s.classifier = o;
    // The method brings its own default features and weight of the chain's evidence.
    s.features =
        a.features.empty() ? analysis::defaultFeatures(g, o.method) : parseFeatures(a.features);
    const auto decision = analysis::parseDecisionMode(a.decision);
    if (!decision || !analysis::isCausal(*decision)) {
      throw UsageError("--decision must be online or step (a model's default decision is causal)");
    }
    s.decision = *decision;
    s.emissionWeight = analysis::defaultEmissionWeight(g, o.method);
    if (a.emissionWeight) {
      checkNumberOption("--emission-weight", *a.emissionWeight, 0.0, RangeEnd::Open, HUGE_VAL,
                        RangeEnd::Open);
      s.emissionWeight = *a.emissionWeight;
    }
  }
  return out;
}

int runTrain(const TrainArgs& a) {
  const analysis::GroupSettings settings = trainSettings(a);
  if (!a.db.empty()) {
    std::vector<SensorGroup> groups = parseGroups(a.groups);
    return runTrainDb(a, settings, groups);
  }
  if (a.runs.empty()) throw UsageError("give --runs FILES (run files) or --db DB --set SET");
  if (a.out.empty()) throw UsageError("--runs needs --out MODEL.json");
  if (!a.set.empty() || !a.trainRuns.empty() || !a.name.empty()) {
    throw UsageError("--set, --train-runs and --name need --db (run files: --out names the file)");
  }
  checkOutput(a.out, joined(a.runs, a.testRuns, a.labels));
  checkNumberOption("--holdout", a.holdout, 0.0, RangeEnd::Closed, 1.0, RangeEnd::Open);
  if (!a.testRuns.empty() && a.holdout > 0.0) {
    throw UsageError("give either --test-runs or --holdout, not both");
  }
  const analysis::EvaluationSplit fileSplit = parseFileSplit(a.split);
  if (fileSplit != analysis::EvaluationSplit::TestRuns &&
      (a.holdout > 0.0 || !a.testRuns.empty())) {
    throw UsageError("--split " + a.split +
                     " scores the training runs in turn; give no "
                     "--test-runs or --holdout");
  }
  std::vector<SensorGroup> groups = parseGroups(a.groups);

  LoadedRuns loaded, loadedTest;
  readRuns(a.runs, loaded);
  attachLabels(loaded, a.labels);
  analysis::TrainJob job;
  job.runs = loaded.labelled;
  auto refsOf = [](const LoadedRuns& l) {
    std::vector<analysis::RunReference> out;
    for (std::size_t i = 0; i < l.runs.size(); ++i) {
      const auto scene = l.runs[i].meta("scene");
      out.push_back({l.paths[i], static_cast<std::int64_t>(l.runs[i].stepCount()), "",
                     scene ? std::string(*scene) : std::string()});
    }
    return out;
  };
  job.runRefs = refsOf(loaded);
  job.split = fileSplit;
  if (!a.testRuns.empty()) {
    readRuns(a.testRuns, loadedTest);
    attachLabels(loadedTest, a.labels);
    job.testRuns = loadedTest.labelled;
    job.testRunRefs = refsOf(loadedTest);
  } else if (a.holdout > 0.0) {
    job.split = analysis::EvaluationSplit::Holdout;
    job.holdout = a.holdout;
  }
  job.groups = groups;
  job.settings = settings;
  job.minRowsPerGroup = a.minRows;
  job.provenance.labels = a.labels.empty() ? "truth columns" : a.labels;
  job.provenance.programVersion = std::string(workspace::programVersion());
  auto trained = analysis::trainAndEvaluate(job);
  if (!trained) throw std::runtime_error(trained.errorText());
  const Status written = analysis::writeModelBundleFile(a.out, trained->bundle);
  if (!written) throw std::runtime_error(written.errorText());
  json doc{{"out", a.out}, {"split", std::string(analysis::evaluationSplitName(job.split))}};
  printTrainSummary(trained->groups, trained->bundle, trained->evaluatedOn, a.json, std::move(doc),
                    "wrote " + std::to_string(trained->bundle.models.size()) +
                        " group model(s) to " + a.out + " (scores on " + trained->evaluatedOn +
                        ")");
  return kExitOk;
}

// ---------------------------------------------------------------------------------------------
// sweep

struct SweepArgs {
  std::string db;                 // database form
  std::vector<std::string> runs;  // run-file form: the run files (request.trainRuns)
  workspace::SweepRequestText request;
  bool progress = false;
  std::string out;
  bool json = false;
};

ProgressFn sweepProgress(bool show) {
  if (!show) return {};
  // Also called after every EM iteration of the running fits: print only when a cell finishes.
  return [line = ProgressLine("sweep", "cells")](std::size_t done, std::size_t total) mutable {
    line.show(done, total);
    return true;
  };
}

int runSweepDb(const SweepArgs& a) {
  if (!a.runs.empty() || !a.request.labelsFile.empty()) {
    throw UsageError(
        "--runs and --labels are for run files; with --db use --train-runs and "
        "--test-runs");
  }
  workspace::SweepRequestText text = a.request;
  text.testRuns = splitNames(text.testRuns);
  const workspace::SweepRequest request =
      sweepRequestOrUsage(text, workspace::SweepSource::Database);
  checkOutput(a.out, {a.db});
  auto ws = openWorkspace(a.db, true);
  auto outcome = ws->sweep(request, {}, sweepProgress(a.progress));
  if (!outcome) throw std::runtime_error(a.db + ": " + outcome.errorText());
  const analysis::SweepResult& result = outcome->result;
  json doc = analysis::sweepToJson(result);
  if (!a.out.empty()) writeText(a.out, dumpJson(doc, 1) + "\n");
  std::size_t ok = 0;
  for (const auto& c : result.cells)
    ok += c.ok ? 1 : 0;
  if (a.json) {
    std::cout << dumpJson(json{{"sweep", outcome->sweepId},
                               {"cells", doc["cells"]},
                               {"fitted", ok},
                               {"threads", result.threads},
                               {"wall_s", result.wallSeconds}})
              << "\n";
  } else {
    std::printf("sweep %lld: %zu cells (%zu fitted) in %.2f s on %d threads, stored in %s\n",
                static_cast<long long>(outcome->sweepId), result.cells.size(), ok,
                result.wallSeconds, result.threads, a.db.c_str());
  }
  return kExitOk;
}

int runSweepVerb(const SweepArgs& a) {
  if (!a.db.empty()) return runSweepDb(a);
  if (a.runs.empty()) throw UsageError("give --runs FILES (run files) or --db DB --set SET");
  if (a.out.empty()) throw UsageError("--runs needs --out SWEEP.json");
  if (!a.request.labelSet.empty() || !a.request.trainRuns.empty() || !a.request.name.empty()) {
    throw UsageError("--set, --train-runs and --name need --db (run files: --out names the file)");
  }
  workspace::SweepRequestText text = a.request;
  text.trainRuns = a.runs;
  const workspace::SweepRequest request = sweepRequestOrUsage(text, workspace::SweepSource::Files);
  const bool byScene = request.split == workspace::SplitMode::ByScene;
  checkOutput(a.out, joined(a.runs, request.testRuns, request.labelsFile));

  LoadedRuns loaded, loadedTest;
  readRuns(a.runs, loaded);
  attachLabels(loaded, request.labelsFile);
  workspace::SweepData data;
  for (std::size_t i = 0; i < loaded.runs.size(); ++i) {
    const std::string* scene = loaded.runs[i].meta("scene");
    data.sceneOfTrain.push_back(scene != nullptr && !scene->empty() ? *scene : loaded.paths[i]);
  }
  if (byScene) {
    data.train = loaded.labelled;
  } else if (!request.testRuns.empty()) {
    readRuns(request.testRuns, loadedTest);
    attachLabels(loadedTest, request.labelsFile);
    data.train = loaded.labelled;
    data.test = loadedTest.labelled;
  } else {
    analysis::splitLabelledRuns(loaded.labelled, request.holdout, data.train, data.test);
  }
  auto session = workspace::makeSweepSession(request, data);
  if (!session) throw std::runtime_error(session.errorText());
  analysis::SweepOptions options;
  options.threads = request.threads;
  const analysis::SweepResult result =
      analysis::runSweepSession(*session.value(), options, sweepProgress(a.progress));
  // Each distinct warning once (cells of one group and variance floor share them).
  std::vector<std::string> warnings;
  for (const auto& c : result.cells) {
    for (const std::string& w : c.warnings) {
      const std::string line = "group " + std::string(groupInfo(c.cell.group).shortName) + ": " + w;
      if (std::find(warnings.begin(), warnings.end(), line) == warnings.end())
        warnings.push_back(line);
    }
  }
  for (const std::string& w : warnings)
    printWarning(w);
  json doc = analysis::sweepToJson(result);
  doc["runs"] = loaded.paths;
  doc["test_runs"] = loadedTest.paths;
  doc["labels"] = request.labelsFile.empty() ? "truth columns" : request.labelsFile;
  doc["holdout"] = request.testRuns.empty() && !byScene ? request.holdout : 0.0;
  doc["split"] = std::string(workspace::splitModeName(request.split));
  writeText(a.out, dumpJson(doc, 1) + "\n");
  std::size_t ok = 0;
  for (const auto& c : result.cells)
    ok += c.ok ? 1 : 0;
  if (a.json) {
    std::cout << dumpJson(json{{"out", a.out},
                               {"cells", result.cells.size()},
                               {"fitted", ok},
                               {"threads", result.threads},
                               {"wall_s", result.wallSeconds},
                               {"warnings", warnings}})
              << "\n";
  } else {
    std::printf("sweep: %zu cells (%zu fitted) in %.2f s on %d threads -> %s\n",
                result.cells.size(), ok, result.wallSeconds, result.threads, a.out.c_str());
  }
  return kExitOk;
}

// ---------------------------------------------------------------------------------------------
// report

struct ReportArgs {
  std::size_t minTestSteps = analysis::kMinTestSteps;
  std::string path;
  bool csv = false;
  bool json = false;
  std::string db;
  std::int64_t sweep = 0;
  std::string format;
  std::string out;
};

// With --json the report goes to --out and stdout gets one summary object.
void checkReportJson(const ReportArgs& a) {
  if (a.json && (a.out.empty() || a.out == "-")) {
    throw UsageError("--json prints a summary; give --out FILE for the report itself");
  }
}

int runReportDb(const ReportArgs& a) {
  if (a.sweep <= 0) throw UsageError("--db needs --sweep ID (see tactile sweeps list)");
  checkReportJson(a);
  const std::string format = a.format.empty() ? "text" : a.format;
  const auto style = analysis::parseTableStyle(format);
  if (!style)
    throw UsageError("unknown --format " + quotedInput(format) + " (md, csv, html, text)");
  checkOutput(a.out, {a.db});
  auto ws = openWorkspace(a.db, false);
  auto sweep = ws->loadSweep(a.sweep);
  if (!sweep) throw std::runtime_error(a.db + ": " + sweep.errorText());
  auto info = ws->sweepStore().info(a.sweep);
  json configuration = json::object();
  if (info) configuration = json::parse(info->configurationJson, nullptr, false);
  if (a.out.empty() || a.out == "-") {
    analysis::SweepReportOptions options;
    if (!configuration.is_discarded()) options.configuration = configuration;
    writeText(a.out, analysis::sweepReport(sweep.value(), *style, options));
  } else {
    // The same writer as the workbench's Export Report (Markdown: figures beside the file).
    const Status written =
        analysis::writeSweepReport(sweep.value(), *style, a.out,
                                   configuration.is_discarded() ? json::object() : configuration);
    if (!written) throw std::runtime_error(written.errorText());
  }
  if (a.json) {
    std::cout << dumpJson(json{{"sweep", a.sweep},
                               {"cells", sweep->cells.size()},
                               {"format", format},
                               {"out", a.out}})
              << "\n";
  }
  return kExitOk;
}

// What a SWEEP.json written by `tactile sweep --runs` says of its data, in the shape of a stored
// sweep's configuration: labels, run files (as run names) and the held-out share.
json sweepFileConfiguration(const json& doc) {
  json out = json::object();
  if (doc.contains("labels") && doc["labels"].is_string()) out["label_set"] = doc["labels"];
  auto runs = [&doc](const char* key) {
    json list = json::array();
    if (doc.contains(key) && doc[key].is_array())
      for (const json& p : doc[key])
        if (p.is_string()) list.push_back(json{{"name", p}});
    return list;
  };
  if (doc.contains("runs")) out["train_runs"] = runs("runs");
  if (doc.contains("test_runs") && !doc["test_runs"].empty()) out["test_runs"] = runs("test_runs");
  if (doc.contains("holdout") && doc["holdout"].is_number()) out["holdout"] = doc["holdout"];
  return out;
}

int runReport(const ReportArgs& r) {
  if (!r.db.empty()) return runReportDb(r);
  if (r.path.empty())
    throw UsageError("give FILE (SWEEP.json or MODEL.json) or --db DB --sweep ID");
  checkReportJson(r);
  const std::string& path = r.path;
  const bool csv = r.csv || r.format == "csv";
  const Result<std::string> read = readFileText(path);
  if (!read) throw std::runtime_error(read.errorText());
  const std::string& text = read.value();
  // The one JSON reader: syntax errors as FILE:LINE: column C: ..., in plain words.
  Result<json> parsed = parseJsonText(text, path);
  if (!parsed) {
    Error error = parsed.error();
    error.message = "invalid JSON: " + error.message;
    throw std::runtime_error(error.text());
  }
  const json& value = parsed.value();
  analysis::TableStyle style = csv ? analysis::TableStyle::Csv : analysis::TableStyle::Text;
  if (!r.format.empty()) {
    const auto parsed = analysis::parseTableStyle(r.format);
    if (!parsed)
      throw UsageError("unknown --format " + quotedInput(r.format) + " (md, csv, html, text)");
    style = *parsed;
  }
  checkOutput(r.out, {r.path});
  const std::string format =
      value.is_object() && value.contains("format") && value["format"].is_string()
          ? value["format"].get<std::string>()
          : "";
  if (format == "tactile-sweep") {
    const Result<analysis::SweepResult> sweep = analysis::sweepFromJson(value);
    if (!sweep) throw std::runtime_error(path + ": " + sweep.errorText());
    const json configuration = sweepFileConfiguration(value);
    if (r.out.empty() || r.out == "-") {
      analysis::SweepReportOptions options;
      options.configuration = configuration;
      writeText(r.out, analysis::sweepReport(sweep.value(), style, options));
    } else {
      const Status written = analysis::writeSweepReport(sweep.value(), style, r.out, configuration);
      if (!written) throw std::runtime_error(written.errorText());
    }
    if (r.json)
      std::cout << dumpJson(json{{"file", path}, {"kind", "sweep"}, {"out", r.out}}) << "\n";
    return kExitOk;
  }
  if (format == analysis::kModelFormat || format == analysis::kModelBundleFormat) {
    // Validate through the one model reader before reporting.
    const Result<analysis::ModelBundle> models = analysis::modelsFromJson(value, path);
    if (!models) throw std::runtime_error(models.errorText());
    writeText(r.out, analysis::modelReport(models.value(), style, r.minTestSteps));
    if (r.json)
      std::cout << dumpJson(json{{"file", path}, {"kind", "model"}, {"out", r.out}}) << "\n";
    return kExitOk;
  }
  throw std::runtime_error(path + ": not a sweep or model file (format " + quotedInput(format) +
                           ")");
}

// ---------------------------------------------------------------------------------------------
// classify

struct ClassifyArgs {
  std::string db;
  std::string model;
  std::string run;
  std::string out;
  bool json = false;
  std::string temporal = "none";
  std::string decision;  // empty: each model's default
  int count = 3;
  double threshold = 5.0;
  int window = 0;
  double stay = 0.9;
};

// Prints (or writes) a run's classification: JSON, or CSV with one line per step and group.
int printClassification(const ClassifyArgs& a, const analysis::RunClassification& result) {
  const std::size_t steps = result.steps;
  for (const GroupInfo& info : kSensorGroups) {
    if (result.groups[static_cast<std::size_t>(groupIndex(info.group))].model == nullptr) {
      printWarning(a.model + ": no model for group " + std::string(info.shortName) +
                   "; its contact steps are left unclassified");
    }
  }
  if (a.json) {
    json doc;
    doc["run"] = a.run;
    doc["model"] = a.model;
    doc["steps"] = steps;
    if (a.temporal != "none") doc["temporal"] = a.temporal;
    json gj = json::object();
    for (const GroupInfo& info : kSensorGroups) {
      const analysis::GroupClassification& go =
          result.groups[static_cast<std::size_t>(groupIndex(info.group))];
      json g;
      g["model"] = go.model != nullptr;
      if (go.model) g["decision"] = go.decisionName;
      json cls = json::array(), stepCls = json::array(), rule = json::array();
      for (std::size_t t = 0; t < steps; ++t) {
        const std::string c = go.className(t);
        cls.push_back(c.empty() ? json(nullptr) : json(c));
        const std::string p = go.stepClassName(t);
        stepCls.push_back(p.empty() ? json(nullptr) : json(p));
        rule.push_back(go.noContactRule[t] != 0);
      }
      // `class` is the chosen decision; `step_class` the per-step argmax.
      g["class"] = std::move(cls);
      g["step_class"] = std::move(stepCls);
      g["no_contact_rule"] = std::move(rule);
      if (go.model) {
        json ll = json::object();
        for (int c = 0; c < go.model->classifier.classCount(); ++c) {
          json col = json::array();
          Eigen::Index row = 0;  // the contact steps' rows, in step order
          for (std::size_t t = 0; t < steps; ++t) {
            col.push_back(go.noContactRule[t] ? json(nullptr) : json(go.logLikelihoods(row++, c)));
          }
          ll[go.model->classifier.classNames()[static_cast<std::size_t>(c)]] = std::move(col);
        }
        g["loglik"] = std::move(ll);
      }
      gj[std::string(info.shortName)] = std::move(g);
    }
    doc["groups"] = std::move(gj);
    const std::string text = dumpJson(doc) + "\n";
    if (a.out.empty()) {
      std::fwrite(text.data(), 1, text.size(), stdout);
    } else {
      writeText(a.out, text);
      std::cout << dumpJson(json{{"out", a.out}, {"steps", steps}}) << "\n";
    }
    return kExitOk;
  }

  // CSV, long form: one line per step and group. `class` is the chosen decision (the model's
  // default, --decision or --temporal), `step_class` the per-step argmax.
  std::string csv = "step,group,class,no_contact_rule";
  for (std::string_view n : kContactClassNames)
    csv += ",loglik_" + std::string(n);
  csv += ",decision,step_class\n";
  std::array<Eigen::Index, kGroupCount> rows{};  // each group's next contact row
  for (std::size_t t = 0; t < steps; ++t) {
    for (const GroupInfo& info : kSensorGroups) {
      const auto g = static_cast<std::size_t>(groupIndex(info.group));
      const analysis::GroupClassification& go = result.groups[g];
      csv += std::to_string(t) + "," + std::string(info.shortName) + "," + go.className(t) + "," +
             (go.noContactRule[t] ? "1" : "0");
      const bool scored = go.model != nullptr && !go.noContactRule[t];
      for (int c = 0; c < kContactClassCount; ++c) {
        csv += ",";
        if (!scored) continue;
        for (std::size_t k = 0; k < go.model->classes.size(); ++k) {
          if (static_cast<int>(go.model->classes[k]) == c)
            csv += dumpJson(json(go.logLikelihoods(rows[g], static_cast<Eigen::Index>(k))));
        }
      }
      if (scored) ++rows[g];
      csv += "," + go.decisionName + "," + go.stepClassName(t) + "\n";
    }
  }
  writeText(a.out, csv);
  return kExitOk;
}

int runClassify(const ClassifyArgs& a) {
  const auto rule = analysis::parseTemporalRule(a.temporal);
  if (!rule)
    throw UsageError("unknown --temporal " + quotedInput(a.temporal) + " (none, count, sum, hmm)");
  if (a.count < 1) throw UsageError("--count must be >= 1");
  checkNumberOption("--stay", a.stay, 0.0, RangeEnd::Closed, 1.0, RangeEnd::Closed);
  checkNumberOption("--threshold", a.threshold, 0.0, RangeEnd::Closed, HUGE_VAL, RangeEnd::Open);
  analysis::ClassifyOptions options;
  if (!a.decision.empty()) {
    const auto decision = analysis::parseDecisionMode(a.decision);
    if (!decision)
      throw UsageError("unknown --decision " + quotedInput(a.decision) +
                       " (step, online, offline)");
    if (*rule != analysis::TemporalRule::None)
      throw UsageError("give either --decision or --temporal, not both");
    options.decision = *decision;
  }
  options.temporal = *rule;
  options.count = a.count;
  options.threshold = a.threshold;
  options.window = a.window;
  options.stay = a.stay;
  checkOutput(a.out, {a.db, a.model, a.run});
  if (!a.db.empty()) {
    // --model and --run name a stored model and a stored run.
    auto ws = openWorkspace(a.db, false);
    auto classified = ws->classify(a.model, a.run, options);
    if (!classified) throw std::runtime_error(a.db + ": " + classified.errorText());
    return printClassification(a, classified->result);
  }
  const Result<analysis::ModelBundle> models = analysis::readModelFile(a.model);
  if (!models) throw std::runtime_error(models.errorText());
  RunCsvResult read = readRunCsv(a.run);
  if (!read.ok()) throw std::runtime_error(read.errorText());
  return printClassification(a, analysis::classifyRun(read.value(), models.value(), options));
}

}  // namespace

void registerLearnVerbs(CLI::App& app, CLI::App& /*bench*/) {
  // train
  {
    auto args = std::make_shared<TrainArgs>();
    CLI::App* cmd = app.add_subcommand(
        "train",
        "Train one classifier per sensor group on labelled runs.\n"
        "From a database: --db DB --set SET stores the model bundle in the database (and writes "
        "--out when given).\nFrom run files: --runs FILES --out MODEL.json; labels come from "
        "--labels, else from the runs' truth columns.");
    cmd->add_option("--db", args->db,
                    "Database holding the runs and label sets (default: TACTILE_DB when no "
                    "--runs are given)");
    cmd->add_option("--set", args->set, "Label set to train on (with --db)");
    cmd->add_option("--train-runs", args->trainRuns,
                    "Stored runs to train on (with --db; default: every run the set labels, "
                    "minus the test runs)")
        ->delimiter(',');
    cmd->add_option("--split", args->split,
                    "by-run (whole runs held out: --test-runs; with --db and no --test-runs every "
                    "4th run by name), leave-one-run-out, or by-scene (each scene's runs scored by "
                    "models trained without that scene)")
        ->capture_default_str();
    cmd->add_option("--name", args->name,
                    "Name of the stored model (with --db; default SET-N, the first free N)");
    cmd->add_option("--min-rows", args->minRows,
                    "Groups with fewer labelled contact rows for training are skipped")
        ->capture_default_str();
    cmd->add_option("--runs", args->runs,
                    "Run CSV files to train on (A B; a path is never split at a comma)");
    cmd->add_option("--labels", args->labels,
                    "Label CSV (run,group,first_step,last_step,class[,annotator]); its run column "
                    "matches a run's path, file name or stem");
    cmd->add_option("--test-runs", args->testRuns,
                    "Runs to score the models on (stored run names with --db, A B or A,B; else "
                    "run files, A B)");
    cmd->add_option("--holdout", args->holdout,
                    "Run files: score on the last fraction of each run's steps instead (0 = score "
                    "on the training data)")
        ->capture_default_str();
    addClassifierOptions(cmd, args->classifier, true);
    // These default to each group's own setting; given, they apply to every group.
    for (const char* name : {"--method", "--order", "--cov", "--floor", "--restarts", "--trees",
                             "--depth", "--learning-rate", "--min-child-weight"}) {
      CLI::Option* o = cmd->get_option(name);
      o->default_str("");
      o->description(o->get_description() + " (default: each group's own)");
    }
    cmd->add_option("--features", args->features,
                    "normal, magnitude, normal+shear, normal+shear+touch, "
                    "normal+shear+touch+context, normal+shear+touch+context+neighbours, "
                    "normal+shear+touch+motion or normal+shear+touch+motion+neighbours "
                    "(default: each group's own for the method: the mixtures and the trees have "
                    "kinds of their own)");
    cmd->add_option("--decision", args->decision,
                    "The models' default decision: online (HMM forward filter, causal) or step "
                    "(per-step argmax); scores are given for step, online and offline either way")
        ->capture_default_str();
    cmd->add_option("--emission-weight", args->emissionWeight,
                    "Weight w of each step's log-likelihoods in the online and offline deciders "
                    "(the class chain sees p(x | class)^w; 1 = plain HMM; default: each group's "
                    "own)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--groups", args->groups, "Groups to train (default all), e.g. R,L")
        ->delimiter(',');
    cmd->add_option("--out", args->out, "Model bundle JSON to write (checked before training)");
    cmd->add_flag("--json", args->json, "Print a JSON summary");
    setAction(cmd, [args, cmd] {
      args->given.method = cmd->get_option("--method")->count() > 0;
      args->given.order = cmd->get_option("--order")->count() > 0;
      args->given.cov = cmd->get_option("--cov")->count() > 0;
      args->given.floor = cmd->get_option("--floor")->count() > 0;
      args->given.restarts = cmd->get_option("--restarts")->count() > 0;
      args->given.trees = cmd->get_option("--trees")->count() > 0;
      args->given.depth = cmd->get_option("--depth")->count() > 0;
      args->given.learningRate = cmd->get_option("--learning-rate")->count() > 0;
      args->given.minChildWeight = cmd->get_option("--min-child-weight")->count() > 0;
      TrainArgs a = *args;
      if (a.db.empty() && a.runs.empty()) a.db = databaseFromEnvironment();
      return runTrain(a);
    });
  }
  // sweep
  {
    auto args = std::make_shared<SweepArgs>();
    CLI::App* cmd = app.add_subcommand(
        "sweep",
        "Train and score a grid of classifiers (group x method x order x covariance x floor x "
        "features x seed) on all cores.\nFrom a database: --db DB --set SET --train-runs ... "
        "--test-runs ... stores every cell as it finishes.\nFrom run files: --runs FILES --out "
        "SWEEP.json.");
    cmd->add_option("--db", args->db,
                    "Database holding the runs and label sets (default: TACTILE_DB when no "
                    "--runs are given)");
    cmd->add_option("--runs", args->runs, "Run CSV files (A B; a path is never split at a comma)");
    cmd->add_option("--labels", args->request.labelsFile,
                    "Label CSV (default: the runs' truth columns)");
    cmd->add_option("--holdout", args->request.holdout,
                    "Last fraction of each run's steps held out")
        ->capture_default_str();
    addSweepRequestOptions(cmd, args->request);
    cmd->add_flag("--progress", args->progress, "Print progress on stderr");
    cmd->add_option("--out", args->out, "SWEEP.json to write (optional with --db)");
    cmd->add_flag("--json", args->json, "Print a JSON summary");
    setAction(cmd, [args, cmd] {
      if (!cmd->get_subcommands().empty()) return lastExitCode();  // a sub-verb ran
      SweepArgs a = *args;
      if (a.db.empty() && a.runs.empty()) a.db = databaseFromEnvironment();
      return runSweepVerb(a);
    });
    registerSweepJobVerbs(*cmd);
  }
  // report
  {
    auto args = std::make_shared<ReportArgs>();
    CLI::App* cmd = app.add_subcommand(
        "report",
        "Print the tables of a sweep (best cells, rate against floor and order, confusion "
        "matrices) or of a model file (confusion, per-class rates, one-vs-rest rates, contact "
        "patterns)");
    cmd->add_option("FILE", args->path, "SWEEP.json or MODEL.json");
    cmd->add_option("--db", args->db,
                    "Database holding the sweep (default: TACTILE_DB without FILE)");
    cmd->add_option("--sweep", args->sweep, "Stored sweep id (with --db; see tactile sweeps list)");
    cmd->add_option("--format", args->format, "md, csv, html or text (default text)");
    cmd->add_option("--out", args->out, "Write here instead of stdout");
    cmd->add_option(
           "--min-test-steps", args->minTestSteps,
           "Classes with fewer test steps are marked \"only N test steps\" and never decide a "
           "best cell")
        ->capture_default_str();
    cmd->add_flag("--csv", args->csv, "CSV tables instead of aligned text (= --format csv)");
    cmd->add_flag(
        "--json", args->json,
        R"(With --out: print {"out","format"} and, for a stored sweep, "sweep" and "cells")");
    setAction(cmd, [args] {
      ReportArgs a = *args;
      if (a.db.empty() && a.path.empty()) a.db = databaseFromEnvironment();
      return runReport(a);
    });
  }
  // classify
  {
    auto args = std::make_shared<ClassifyArgs>();
    CLI::App* cmd = app.add_subcommand(
        "classify",
        "Classify every step and group of a run with a model (bundle): class and per-class "
        "log-likelihoods, as CSV (one line per step and group) or JSON.\nWith --db, --model and "
        "--run name a stored model and a stored run.");
    cmd->add_option("--db", args->db,
                    "Database holding the model and the run (default: TACTILE_DB when --model "
                    "and --run are not files)");
    cmd->add_option("--model", args->model, "Model or model bundle JSON, or a stored model's name")
        ->required();
    cmd->add_option("--run", args->run, "Run CSV, or a stored run's name")->required();
    cmd->add_option("--out", args->out, "Write here instead of stdout");
    cmd->add_flag("--json", args->json, "JSON instead of CSV");
    cmd->add_option("--decision", args->decision,
                    "The decision written as `class`: step (per-step argmax), online (HMM forward "
                    "filter with the model's transitions, causal) or offline (forward-backward); "
                    "default: each model's own (online for models with transitions)");
    cmd->add_option("--temporal", args->temporal,
                    "An older temporal rule as `class` instead (thesis 4.6): none, count, sum or "
                    "hmm (a fixed stay probability)")
        ->capture_default_str();
    cmd->add_option("--count", args->count, "count: consecutive steps required")
        ->capture_default_str();
    cmd->add_option("--threshold", args->threshold, "sum: log-probability margin, nats")
        ->capture_default_str();
    cmd->add_option("--window", args->window, "sum: sliding window in steps (0 = whole contact)")
        ->capture_default_str();
    cmd->add_option("--stay", args->stay, "hmm: self-transition probability")
        ->capture_default_str();
    setAction(cmd, [args] {
      ClassifyArgs a = *args;
      // Names that are not files name a stored model and run of TACTILE_DB.
      if (a.db.empty() && !std::filesystem::exists(a.model) && !std::filesystem::exists(a.run)) {
        a.db = databaseFromEnvironment();
      }
      return runClassify(a);
    });
  }
}

}  // namespace tactile::cli
