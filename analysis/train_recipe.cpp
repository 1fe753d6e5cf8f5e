// The one training recipe (training.h): trains every group, scores it as the split says with every
// decision mode, and records provenance and evaluation in the models. `tactile train` (run files
// and database) and the workbench's Train model all come here.
#include <algorithm>
#include <map>
#include <set>

#include "analysis/training.h"

namespace tactile::analysis {

namespace {

// Rows of `data` whose run is (keep) or is not (!keep) in `runs`.
GroupDataSet rowsOfRuns(const GroupDataSet& data, const std::vector<std::uint8_t>& inRuns,
                        bool keep) {
  GroupDataSet out;
  out.group = data.group;
  out.kind = data.kind;
  std::vector<Eigen::Index> rows;
  for (std::size_t i = 0; i < data.size(); ++i) {
    if ((inRuns[data.runIndex[i]] != 0) == keep) rows.push_back(static_cast<Eigen::Index>(i));
  }
  out.x.resize(static_cast<Eigen::Index>(rows.size()), data.x.cols());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto r = static_cast<std::size_t>(rows[i]);
    out.x.row(static_cast<Eigen::Index>(i)) = data.x.row(rows[i]);
    out.y.push_back(data.y[r]);
    out.runIndex.push_back(data.runIndex[r]);
    out.step.push_back(data.step[r]);
  }
  return out;
}

// Why a group's training data cannot give a model, or empty.
std::string tooLittleData(const GroupDataSet& data, std::size_t minRows) {
  if (data.size() < minRows) {
    return std::to_string(data.size()) + " labelled contact rows for training (at least " +
           std::to_string(minRows) + " needed)";
  }
  const ClassSelection classes = selectClasses(data);
  if (classes.modelled.size() < 2) {
    return "fewer than two classes with enough rows to model (" +
           std::to_string(classes.modelled.size()) + ")";
  }
  return {};
}

std::string sceneOf(const RunReference& ref) {
  return ref.scene.empty() ? ref.name : ref.scene;
}

void mergeInto(std::array<ConfusionMatrix, kDecisionModeCount>& into,
               const std::array<ConfusionMatrix, kDecisionModeCount>& from) {
  for (std::size_t m = 0; m < kDecisionModeCount; ++m)
    into[m].merge(from[m]);
}

}  // namespace

std::string_view evaluationSplitName(EvaluationSplit split) {
  switch (split) {
    case EvaluationSplit::TrainingData:
      return "training-data";
    case EvaluationSplit::TestRuns:
      return "by-run";
    case EvaluationSplit::Holdout:
      return "holdout";
    case EvaluationSplit::LeaveOneRunOut:
      return "leave-one-run-out";
    case EvaluationSplit::ByScene:
      return "by-scene";
  }
  return "by-run";
}

std::string evaluatedOnText(EvaluationSplit split, double holdout) {
  switch (split) {
    case EvaluationSplit::TrainingData:
      return "training runs";
    case EvaluationSplit::TestRuns:
      return "test runs";
    case EvaluationSplit::Holdout:
      return "held-out steps (last " + std::to_string(static_cast<int>(holdout * 100 + 0.5)) +
             "% of each run)";
    case EvaluationSplit::LeaveOneRunOut:
      return "leave-one-run-out";
    case EvaluationSplit::ByScene:
      return "leave-one-scene-out";
  }
  return "test runs";
}

Result<TrainJobOutcome> trainAndEvaluate(const TrainJob& job, const ProgressFn& progress) {
  if (job.runs.empty()) return Error("no runs to train on");
  std::vector<RunReference> refs = job.runRefs;
  refs.resize(job.runs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (refs[i].name.empty()) refs[i].name = "run " + std::to_string(i + 1);
    if (refs[i].steps == 0) refs[i].steps = static_cast<std::int64_t>(job.runs[i].run->stepCount());
  }
  std::vector<RunReference> testRefs = job.testRunRefs;
  testRefs.resize(job.testRuns.size());
  EvaluationSplit split = job.split;
  if (split == EvaluationSplit::TestRuns && job.testRuns.empty()) {
    split = EvaluationSplit::TrainingData;
  }
  if (split != EvaluationSplit::TestRuns && !job.testRuns.empty()) {
    return Error(std::string(evaluationSplitName(split)) +
                 " scores the training runs themselves; give no test runs");
  }
  if (split == EvaluationSplit::Holdout && (job.holdout <= 0.0 || job.holdout >= 1.0)) {
    return Error("the held-out fraction must be in (0, 1)");
  }
  if (split == EvaluationSplit::LeaveOneRunOut && job.runs.size() < 2) {
    return Error("leave-one-run-out needs at least two runs, found " +
                 std::to_string(job.runs.size()));
  }
  // Scenes in first-seen order, and each run's scene.
  std::vector<std::string> scenes;
  std::vector<std::size_t> sceneOfRun(job.runs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const std::string s = sceneOf(refs[i]);
    auto it = std::find(scenes.begin(), scenes.end(), s);
    if (it == scenes.end()) it = scenes.insert(scenes.end(), s);
    sceneOfRun[i] = static_cast<std::size_t>(it - scenes.begin());
  }
  if (split == EvaluationSplit::ByScene && scenes.size() < 2) {
    return Error("by-scene needs runs of at least two scenes, found " +
                 std::to_string(scenes.size()) + (scenes.empty() ? "" : " (" + scenes[0] + ")"));
  }

  std::vector<LabelledRun> train = job.runs, test;
  if (split == EvaluationSplit::Holdout) splitLabelledRuns(job.runs, job.holdout, train, test);
  const std::vector<LabelledRun>& scoredRuns =
      split == EvaluationSplit::TestRuns ? job.testRuns : test;

  std::vector<SensorGroup> groups = job.groups;
  if (groups.empty()) {
    for (const GroupInfo& g : kSensorGroups)
      groups.push_back(g.group);
  }
  TrainJobOutcome outcome;
  outcome.evaluatedOn = evaluatedOnText(split, job.holdout);
  std::size_t done = 0;
  for (SensorGroup g : groups) {
    if (progress && !progress(done, groups.size())) return Error("cancelled");
    ++done;
    GroupJobReport report;
    report.group = g;
    const TrainSettings& settings = job.settings.of(g);
    const GroupDataSet data = buildGroupDataSet(train, g, settings.features);
    report.samplesTrain = data.size();
    if (std::string why = tooLittleData(data, job.minRowsPerGroup); !why.empty()) {
      report.skippedBecause = why;
      outcome.groups.push_back(std::move(report));
      continue;
    }
    GroupTrainResult tr = trainGroupModel(data, settings);
    if (!tr.ok) {
      report.skippedBecause = tr.reason;
      outcome.groups.push_back(std::move(report));
      continue;
    }
    for (ContactClass c : tr.classes.unmodelled)
      report.warnings.push_back("class " + std::string(contactClassName(c)) +
                                " has too few samples to model");
    for (const std::string& w : tr.fit.warnings)
      report.warnings.push_back(w);

    ModelEvaluation e;
    GroupEvaluation ev;
    switch (split) {
      case EvaluationSplit::TrainingData:
        ev = evaluateGroupModel(tr.model, data, &train);
        e.byDecision = ev.byDecision;
        break;
      case EvaluationSplit::TestRuns:
      case EvaluationSplit::Holdout: {
        const GroupDataSet testData = buildGroupDataSet(scoredRuns, g, settings.features);
        ev = evaluateGroupModel(tr.model, testData, &scoredRuns);
        e.byDecision = ev.byDecision;
        break;
      }
      case EvaluationSplit::LeaveOneRunOut:
      case EvaluationSplit::ByScene: {
        // One fold per run or per scene: trained on the rest, scored on it. A fold whose rest
        // cannot give a model leaves its rows unscored.
        const bool byScene = split == EvaluationSplit::ByScene;
        const std::size_t folds = byScene ? scenes.size() : job.runs.size();
        for (std::size_t f = 0; f < folds; ++f) {
          if (progress && !progress(done - 1, groups.size())) return Error("cancelled");
          std::vector<std::uint8_t> inFold(job.runs.size(), 0);
          for (std::size_t r = 0; r < job.runs.size(); ++r)
            inFold[r] = (byScene ? sceneOfRun[r] == f : r == f) ? 1 : 0;
          const GroupDataSet held = rowsOfRuns(data, inFold, true);
          const GroupDataSet rest = rowsOfRuns(data, inFold, false);
          SceneScore score;
          score.scene = byScene ? scenes[f] : refs[f].name;
          if (held.size() > 0 && tooLittleData(rest, job.minRowsPerGroup).empty()) {
            const GroupTrainResult foldModel = trainGroupModel(rest, settings);
            if (foldModel.ok) {
              const GroupEvaluation fe = evaluateGroupModel(foldModel.model, held);
              score.byDecision = fe.byDecision;
              mergeInto(e.byDecision, fe.byDecision);
              ev.predictSeconds += fe.predictSeconds + fe.decideSeconds;
            }
          }
          if (byScene) e.scenes.push_back(std::move(score));
        }
        break;
      }
    }
    e.evaluatedOn = outcome.evaluatedOn;
    e.samplesTrain = data.size();
    e.fitSeconds = tr.fit.fitSeconds;
    e.predictSeconds = ev.predictSeconds + ev.decideSeconds;
    e.warnings = report.warnings;
    e.meanLogLikelihood = ev.meanLogLikelihood;
    e.negInfRows = ev.negInfRows;
    e.zeroRows = ev.zeroRows;
    e.patterns = ev.patterns;
    e.oneVsRest = ev.oneVsRest;
    for (std::size_t c = 0; c < tr.model.classes.size(); ++c) {
      ClassFitRecord r;
      if (c < tr.fit.iterations.size()) r.iterations = tr.fit.iterations[c];
      if (c < tr.fit.converged.size()) r.converged = static_cast<bool>(tr.fit.converged[c]);
      if (c < tr.fit.trainMeanLogLikelihood.size())
        r.trainMeanLogLikelihood = tr.fit.trainMeanLogLikelihood[c];
      if (c < tr.fit.droppedComponents.size()) r.droppedComponents = tr.fit.droppedComponents[c];
      e.fit.push_back(r);
    }
    ModelProvenance p = job.provenance;
    p.trainRuns = refs;
    p.testRuns = split == EvaluationSplit::TestRuns ? testRefs : std::vector<RunReference>{};
    p.split = std::string(evaluationSplitName(split));
    p.holdout = split == EvaluationSplit::Holdout ? job.holdout : 0.0;
    p.classifier = settings.classifier;
    p.classifier.featureNames.clear();
    p.samples = data.size();
    p.classCounts = data.classCounts();
    p.zeroRows = data.zeroRows;
    p.unmodelled = tr.classes.unmodelled;
    tr.model.provenance = std::move(p);
    tr.model.evaluation = std::move(e);
    report.trained = true;
    outcome.bundle.models.push_back(std::move(tr.model));
    outcome.groups.push_back(std::move(report));
  }
  if (outcome.bundle.models.empty()) {
    std::string why = "no group could be trained:";
    for (const GroupJobReport& r : outcome.groups)
      why += " " + std::string(groupInfo(r.group).shortName) + ": " + r.skippedBecause + ";";
    why.pop_back();
    return Error(why);
  }
  return outcome;
}

}  // namespace tactile::analysis
