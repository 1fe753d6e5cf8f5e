// Training and evaluating one group's classifier on labelled run data: the glue between features,
// the classifier engine (classifier.h), metrics and model files, shared by `tactile train`, the
// sweep engine and the GUI.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "analysis/classifier.h"
#include "analysis/features.h"
#include "analysis/metrics.h"
#include "analysis/model_file.h"
#include "base/progress.h"

namespace tactile::analysis {

// Settings of one group's classifier.
struct TrainSettings {
  FeatureKind features = FeatureKind::Normal;
  ClassifierOptions classifier;  // method, GMM options (order, form, floor, ...), priors
  // The model's default decision (causal: step or online; offline is taken as online).
  DecisionMode decision = DecisionMode::Online;
  // The weight of each step's log-likelihoods in the class chain's deciders
  // (TransitionModel::emissionWeight): 1 is the plain HMM, smaller lets the chain act.
  double emissionWeight = 1.0;
};

// Settings of each group's classifier, indexed by groupIndex().
struct GroupSettings {
  std::array<TrainSettings, kGroupCount> byGroup{};

  // The same settings for every group.
  static GroupSettings same(const TrainSettings& settings);
  const TrainSettings& of(SensorGroup group) const { return byGroup[groupIndex(group)]; }
  TrainSettings& of(SensorGroup group) { return byGroup[groupIndex(group)]; }
};

// What `tactile train` and the workbench train with unless told otherwise: per group the family
// (GMM or boosted trees), the feature kind (mostly the context kinds), order and variance floor
// (clamp) with the best score on a selection corpus apart from the scenes scores are quoted on;
// the mixtures nodal-full, k-means++ with 3 restarts, the trees at their defaults; seed 1, the
// online decision (docs/learning.md#training-defaults).
GroupSettings defaultGroupSettings();
TrainSettings defaultTrainSettings(SensorGroup group);
// The default feature kind of a group's model of the given method: for either family, the kind
// chosen with its other settings of that family.
FeatureKind defaultFeatures(SensorGroup group, ClassifierMethod method);
// The default weight of each step's evidence in the class chain of a group's model of the given
// method: for either family, the group's weight chosen with its other settings of that family.
// The trees' weights are 1 or more: their scaled likelihoods (posterior over prior) span far
// fewer nats than the mixtures' densities, whose weights are 1 or less.
double defaultEmissionWeight(SensorGroup group, ClassifierMethod method);
// The family a group trains with when a front end (CLI, Python) applies options to every group:
// the method given, else the family the given options belong to (mixtureOptions: order,
// covariance, floor or restarts; treeOptions: trees, depth, learning rate or min child weight),
// else the group's default. Options of both families without a method are refused: which was
// meant cannot be told.
Result<ClassifierMethod> impliedMethod(std::optional<ClassifierMethod> given, bool mixtureOptions,
                                       bool treeOptions, ClassifierMethod groupDefault);

// Classes of a data set that get a model: present with at least max(2, D) samples (the engine
// rejects fewer samples than dimensions). The others are listed in `unmodelled`; their test rows
// count as errors.
struct ClassSelection {
  std::vector<ContactClass> modelled;
  std::vector<ContactClass> unmodelled;  // present but too few samples
};
ClassSelection selectClasses(const GroupDataSet& data);

struct GroupTrainResult {
  bool ok = false;
  std::string reason;
  GroupModel model;
  ClassifierFit fit;  // iterations, converged, fit time (model moved into `model`)
  ClassSelection classes;
};

// The label sequences of a data set for transition counting (estimateTransitions): rows that
// follow each other (same run, next step) continue a sequence; -1 separates sequences and stands
// for a row whose class is not among `classes`.
std::vector<std::vector<int>> classSequences(const GroupDataSet& data,
                                             const std::vector<ContactClass>& classes);

// Fits one model per modelled class of `data` (rows of that class), and the class chain from the
// data's label sequences (classSequences, estimateTransitions).
GroupTrainResult trainGroupModel(const GroupDataSet& data, const TrainSettings& settings,
                                 const ProgressFn& progress = {});

// A model scored on labelled contact rows (zero rows are NoContact by rule and not scored; their
// count is kept).
struct GroupEvaluation {
  ConfusionMatrix confusion;
  Metrics metrics;
  // heldOutLogLikelihood (classifier.h) over the rows of modelled classes: mean of log p(x | model
  // of the row's class) over rows where it is finite, nats (nullopt when no such row), and the
  // number of rows left out because it is -inf.
  std::optional<double> meanLogLikelihood;
  std::size_t negInfRows = 0;
  double predictSeconds = 0.0;
  std::size_t zeroRows = 0;
  // Thesis table 4.39 (filled when `runs` is given to evaluateGroupModel).
  ContactPatternTable patterns;
  // Thesis table 4.19 (Gaussian models with rest models only): one binary confusion per class.
  std::vector<BinaryConfusion> oneVsRest;
  // The confusion of each decision mode (step = `confusion`; online and offline with a chain,
  // else equal to step). Sequences are the data's runs of adjacent rows (classSequences).
  std::array<ConfusionMatrix, kDecisionModeCount> byDecision;
  double decideSeconds = 0.0;  // the online and offline decisions
};

// `runs` are the runs the data set was built from (for the contact patterns); may be null.
GroupEvaluation evaluateGroupModel(const GroupModel& model, const GroupDataSet& data,
                                   const std::vector<LabelledRun>* runs = nullptr);

// Same, from the classifier alone (sweep cells): per-row log-likelihoods computed once. With
// `rowPatterns` (one on/off pattern per data row, rowPatterns()) the contact patterns are filled.
GroupEvaluation evaluateClassifier(const ClassModelSet& classifier,
                                   const std::vector<ContactClass>& classes,
                                   const GroupDataSet& data,
                                   const std::vector<std::string>* rowPatterns = nullptr,
                                   const TransitionModel* chain = nullptr);

// The on/off pattern (contactPattern) of every row of a data set built from `runs`.
std::vector<std::string> rowPatterns(const GroupDataSet& data,
                                     const std::vector<LabelledRun>& runs);

// ---- the one training recipe: `tactile train` (run files and database) and the workbench ----

// How a model is scored.
enum class EvaluationSplit {
  TrainingData,    // on the rows it was trained on (says nothing about new data)
  TestRuns,        // on separate test runs
  Holdout,         // on the last `holdout` fraction of each run's steps
  LeaveOneRunOut,  // each run scored by a model trained on all the others
  ByScene,         // each scene's runs scored by a model trained without that scene
};
// "training-data", "by-run", "holdout", "leave-one-run-out", "by-scene".
std::string_view evaluationSplitName(EvaluationSplit split);
// What the scores are on, in words ("test runs", "leave-one-scene-out", ...).
std::string evaluatedOnText(EvaluationSplit split, double holdout);

struct TrainJob {
  // Runs to train on (for LeaveOneRunOut and ByScene: every run, each scored in turn) and, for
  // TestRuns, the runs to score on; the references name them (and give their scenes) in the
  // models' provenance. A run's scene is its reference's `scene`, or its name when empty.
  std::vector<LabelledRun> runs;
  std::vector<RunReference> runRefs;
  std::vector<LabelledRun> testRuns;
  std::vector<RunReference> testRunRefs;
  EvaluationSplit split = EvaluationSplit::TestRuns;
  double holdout = 0.0;             // Holdout: the fraction of each run's steps scored
  std::vector<SensorGroup> groups;  // empty: all eight
  GroupSettings settings = defaultGroupSettings();
  // A group with fewer labelled contact rows than this for training, or with fewer than two
  // classes that can be modelled, is skipped with a reason; the other groups train.
  std::size_t minRowsPerGroup = 20;
  // Provenance written into every model as is (label set / label file, program version);
  // runs, split, settings and sample counts are filled in by the job.
  ModelProvenance provenance;
};

struct GroupJobReport {
  SensorGroup group = SensorGroup::Front;
  bool trained = false;
  std::string skippedBecause;  // when not trained
  std::size_t samplesTrain = 0;
  std::vector<std::string> warnings;
};

struct TrainJobOutcome {
  ModelBundle bundle;                  // one model per trained group, evaluation and provenance
  std::vector<GroupJobReport> groups;  // in the requested group order
  std::string evaluatedOn;
};

// Trains every group on the job's runs and scores it as the split says (every decision mode),
// fills each model's provenance and evaluation. Cancelled (progress false) is an error; so is a job
// where no group could be trained (naming each group's reason).
Result<TrainJobOutcome> trainAndEvaluate(const TrainJob& job, const ProgressFn& progress = {});

// One group's entry of a training summary (`tactile train --json`, the Python module's
// `train(...).report`): group, trained, sample counts, the default decision's scores and every
// decision's balanced accuracy, classes, fit time, held-out log-likelihood, dropped components and
// per-scene scores; for a group not trained, why. `model` is the bundle's model of the group (null
// when not trained).
nlohmann::json groupReportJson(const GroupJobReport& report, const GroupModel* model);

// Splits each run's labelled steps in time: the first (1 - holdout) of its steps for training,
// the rest for testing (a random row split would leak neighbouring, nearly identical steps).
void splitLabelledRuns(const std::vector<LabelledRun>& runs, double holdoutFraction,
                       std::vector<LabelledRun>& train, std::vector<LabelledRun>& test);

}  // namespace tactile::analysis
