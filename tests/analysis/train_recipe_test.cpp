// The one training recipe (trainAndEvaluate): splits, per-decision scores, held-out scenes, and
// the online decider agreeing with the whole-run online decision.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "analysis/classify_run.h"
#include "analysis/online_decider.h"
#include "analysis/training.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

GroupSettings quick() {
  TrainSettings s;
  s.features = FeatureKind::Normal;
  s.classifier.gmm.components = 1;
  s.classifier.gmm.form = CovarianceForm::NodalDiag;
  s.classifier.gmm.varianceFloor = 0.01;
  s.classifier.gmm.maxIterations = 20;
  return GroupSettings::same(s);
}

struct Runs {
  std::vector<RunData> data;
  std::vector<LabelledRun> labelled;
  std::vector<RunReference> refs;
};

// Runs of the synthetic generator, run i in scenes[i].
Runs makeRuns(const std::vector<std::string>& scenes, std::size_t steps = 600) {
  Runs r;
  r.data.reserve(scenes.size());
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    r.data.push_back(testdata::makeLabelledRun(steps, 100 + i));
    r.refs.push_back({"run" + std::to_string(i), 0, "", scenes[i]});
  }
  for (const RunData& d : r.data)
    r.labelled.push_back({&d, labelsFromTruth(d)});
  return r;
}

// Each held-out scene is scored only by models trained without it: a scene whose Right-group
// contact is labelled DeadPath (a class no other scene has) can never have DeadPath predicted
// when it is held out, while training on it would predict DeadPath nearly always.
TEST(TrainRecipe, BySceneNeverTrainsOnTheScoredScene) {
  Runs r = makeRuns({"a", "b", "odd", "a"});
  const std::size_t g = static_cast<std::size_t>(groupIndex(SensorGroup::Right));
  std::vector<std::optional<ContactClass>>& odd = r.labelled[2].labels;
  for (std::size_t t = 0; t < r.data[2].stepCount(); ++t) {
    auto& label = odd[t * kGroupCount + g];
    if (label && *label != ContactClass::NoContact) label = ContactClass::DeadPath;
  }
  TrainJob job;
  job.runs = r.labelled;
  job.runRefs = r.refs;
  job.split = EvaluationSplit::ByScene;
  job.groups = {SensorGroup::Right};
  job.settings = quick();
  auto out = trainAndEvaluate(job);
  ASSERT_TRUE(out.ok()) << out.errorText();
  const GroupModel& m = out->bundle.models.front();
  ASSERT_EQ(m.evaluation.scenes.size(), 3u);  // a, b, odd in first-seen order
  EXPECT_EQ(m.evaluation.scenes[2].scene, "odd");
  for (std::size_t d = 0; d < kDecisionModeCount; ++d) {
    const ConfusionMatrix& c = m.evaluation.scenes[2].byDecision[d];
    ASSERT_GT(c.trueCount(ContactClass::DeadPath), 30u);
    EXPECT_EQ(c.count(ContactClass::DeadPath, ContactClass::DeadPath), 0u) << d;
  }
  // The other scenes are scored by models that did see DeadPath (from "odd"), and the pooled
  // confusion is the sum of the scenes'.
  std::size_t pooled = 0;
  for (const SceneScore& s : m.evaluation.scenes)
    pooled += s.byDecision[0].total();
  EXPECT_EQ(pooled, m.evaluation.samplesTest());
  // The mean over scenes is the mean of the scenes' balanced accuracies.
  double sum = 0.0;
  for (const SceneScore& s : m.evaluation.scenes)
    sum += computeMetrics(s.byDecision[1]).balancedAccuracy;
  EXPECT_NEAR(*meanSceneBalancedAccuracy(m.evaluation.scenes, DecisionMode::Online), sum / 3.0,
              1e-12);
  // One scene is refused.
  job.runs.resize(1);
  job.runRefs.resize(1);
  EXPECT_FALSE(trainAndEvaluate(job).ok());
}

// Every decision mode is scored; the chain is estimated and online is the default.
TEST(TrainRecipe, ScoresEveryDecisionModeOnTestRuns) {
  Runs train = makeRuns({"a", "b"}, 1500);
  Runs test = makeRuns({"c"}, 800);
  TrainJob job;
  job.runs = train.labelled;
  job.runRefs = train.refs;
  job.testRuns = test.labelled;
  job.testRunRefs = test.refs;
  job.split = EvaluationSplit::TestRuns;
  job.settings = quick();
  job.groups = {SensorGroup::Left, SensorGroup::Back};
  auto out = trainAndEvaluate(job);
  ASSERT_TRUE(out.ok()) << out.errorText();
  for (const GroupModel& m : out->bundle.models) {
    EXPECT_EQ(m.decision, DecisionMode::Online);
    EXPECT_FALSE(m.transitions.empty());
    for (DecisionMode d : kDecisionModes) {
      ASSERT_TRUE(m.evaluation.balancedAccuracy(d).has_value());
      EXPECT_EQ(m.evaluation.confusion(d).total(), m.evaluation.samplesTest());
      EXPECT_GT(*m.evaluation.balancedAccuracy(d), 0.8) << decisionModeName(d);
    }
    EXPECT_EQ(m.provenance.split, "by-run");
    EXPECT_EQ(m.provenance.testRuns.size(), 1u);
  }
}

// A group with no test rows is trained but not scored: no rates at all, never 0.
TEST(TrainRecipe, GroupWithoutTestRowsIsNotScored) {
  Runs train = makeRuns({"a"}, 1200);
  Runs test = makeRuns({"b"}, 300);
  const std::size_t g = static_cast<std::size_t>(groupIndex(SensorGroup::Front));
  for (auto& label : test.labelled[0].labels)
    label.reset();  // nothing labelled in the test run
  (void)g;
  TrainJob job;
  job.runs = train.labelled;
  job.runRefs = train.refs;
  job.testRuns = test.labelled;
  job.testRunRefs = test.refs;
  job.settings = quick();
  job.groups = {SensorGroup::Front};
  auto out = trainAndEvaluate(job);
  ASSERT_TRUE(out.ok()) << out.errorText();
  const ModelEvaluation& e = out->bundle.models.front().evaluation;
  EXPECT_FALSE(e.scored());
  for (DecisionMode d : kDecisionModes)
    EXPECT_FALSE(e.balancedAccuracy(d).has_value());
}

// --min-rows is honoured: a group below it is skipped with the reason.
TEST(TrainRecipe, MinRowsSkipsAGroup) {
  Runs train = makeRuns({"a"}, 300);
  TrainJob job;
  job.runs = train.labelled;
  job.runRefs = train.refs;
  job.settings = quick();
  job.groups = {SensorGroup::Front, SensorGroup::Back};
  job.minRowsPerGroup = 1000000;
  auto out = trainAndEvaluate(job);
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.errorText().find("at least 1000000 needed"), std::string::npos) << out.errorText();
}

// Degenerate groups under boosted trees: a group whose contact has one class only is skipped with
// its reason, and a group whose features are all the same trains to equal posteriors whose
// decisions stay finite; never a crash, never a NaN.
TEST(TrainRecipe, TreesOnDegenerateGroupsGiveAReasonOrEqualPosteriors) {
  Runs train = makeRuns({"a", "b"}, 600);
  for (LabelledRun& lr : train.labelled) {
    for (std::size_t t = 0; t < lr.run->stepCount(); ++t) {
      auto& right = lr.labels[t * kGroupCount + groupIndex(SensorGroup::Right)];
      if (right) right = ContactClass::Wall;  // one class only
    }
  }
  TrainJob job;
  job.runs = train.labelled;
  job.runRefs = train.refs;
  job.settings = quick();
  for (TrainSettings& s : job.settings.byGroup) {
    s.classifier.method = ClassifierMethod::Gbt;
    s.classifier.gbt.trees = 10;
  }
  job.groups = {SensorGroup::Right, SensorGroup::Left};
  job.minRowsPerGroup = 1;
  auto out = trainAndEvaluate(job);
  ASSERT_TRUE(out.ok()) << out.errorText();
  ASSERT_EQ(out->groups.size(), 2u);
  EXPECT_EQ(out->groups[0].group, SensorGroup::Right);
  EXPECT_FALSE(out->groups[0].skippedBecause.empty());
  EXPECT_NE(out->groups[0].skippedBecause.find("class"), std::string::npos)
      << out->groups[0].skippedBecause;
  EXPECT_TRUE(out->groups[1].skippedBecause.empty()) << out->groups[1].skippedBecause;

  // Constant features: every row of every class the same.
  Runs flatRuns = makeRuns({"a", "b"}, 600);
  std::vector<RunData>& flat = flatRuns.data;
  for (RunData& run : flat)
    for (std::size_t t = 0; t < run.stepCount(); ++t)
      for (int d = 0; d < kSensorCount; ++d) {
        double& n = run.sensors[t * kValuesPerStep + static_cast<std::size_t>(normalOffset(d))];
        if (n != 0.0) n = 0.5;
      }
  job.runs = flatRuns.labelled;
  job.runRefs = flatRuns.refs;
  job.groups = {SensorGroup::Left};
  auto constant = trainAndEvaluate(job);
  ASSERT_TRUE(constant.ok()) << constant.errorText();
  ASSERT_EQ(constant->bundle.models.size(), 1u);
  const RunClassification r = classifyRun(flat[0], constant->bundle, {});
  const GroupClassification& left =
      r.groups[static_cast<std::size_t>(groupIndex(SensorGroup::Left))];
  ASSERT_GT(left.logLikelihoods.size(), 0);
  std::size_t decided = 0;
  for (Eigen::Index i = 0; i < left.logLikelihoods.size(); ++i)
    EXPECT_FALSE(std::isnan(left.logLikelihoods.data()[i]));
  for (const auto& d : left.decided)
    decided += d.has_value() ? 1 : 0;
  EXPECT_GT(decided, 0u);
}

// The online decider fed step by step decides exactly what classifyRun's online decision says,
// and its decision at t does not depend on later steps: for mixtures and for boosted trees (the
// defaults' family in most groups, with the motion kind in some).
TEST(OnlineDecider, AgreesWithTheWholeRunOnlineDecision) {
  Runs train = makeRuns({"a", "b"}, 1500);
  struct Case {
    FeatureKind kind;
    double weight;
    ClassifierMethod method;
  };
  // The emission weight of the settings reaches the model's chain, the whole-run deciders and the
  // step-by-step one alike.
  for (const Case& c : {Case{FeatureKind::NormalShear, 1.0, ClassifierMethod::Gmm},
                        Case{FeatureKind::Context, 1.0, ClassifierMethod::Gmm},
                        Case{FeatureKind::Context, 0.2, ClassifierMethod::Gmm},
                        Case{FeatureKind::Neighbours, 3.0, ClassifierMethod::Gbt},
                        Case{FeatureKind::Motion, 2.0, ClassifierMethod::Gbt}}) {
    const auto [kind, weight, method] = c;
    SCOPED_TRACE(std::string(featureKindName(kind)) + " weight " + std::to_string(weight));
    TrainJob job;
    job.runs = train.labelled;
    job.runRefs = train.refs;
    job.settings = quick();
    for (TrainSettings& s : job.settings.byGroup) {
      s.features = kind;
      s.emissionWeight = weight;
      s.classifier.method = method;
      s.classifier.gbt.trees = 20;
      s.classifier.gbt.depth = 4;
    }
    job.groups = {SensorGroup::Left, SensorGroup::FrontRightCorner};
    auto out = trainAndEvaluate(job);
    ASSERT_TRUE(out.ok()) << out.errorText();
    const ModelBundle& bundle = out->bundle;
    for (const GroupModel& m : bundle.models) {
      EXPECT_EQ(m.transitions.emissionWeight, weight);
      EXPECT_EQ(m.classifier.method(), method);
      EXPECT_EQ(m.features, kind);
    }
    const RunData run = testdata::makeLabelledRun(700, 999);
    ClassifyOptions options;
    options.allDecisions = true;
    const RunClassification whole = classifyRun(run, bundle, options);
    OnlineDecider decider(bundle);
    std::size_t contact = 0;
    for (std::size_t t = 0; t < run.stepCount(); ++t) {
      decider.update(run.stepSensors(t), run.v[t], run.omega[t]);
      for (SensorGroup g : job.groups) {
        const GroupClassification& gc = whole.groups[static_cast<std::size_t>(groupIndex(g))];
        const std::string said = gc.className(t);
        const std::optional<ContactClass> mine = decider.decided(g);
        ASSERT_TRUE(mine.has_value());
        ASSERT_EQ(std::string(contactClassName(*mine)), said) << t;
        EXPECT_EQ(gc.nameOf(gc.online, t), said);
        const std::optional<ContactClass> step = decider.perStep(g);
        ASSERT_TRUE(step.has_value());
        EXPECT_EQ(std::string(contactClassName(*step)), gc.stepClassName(t));
        contact += *mine != ContactClass::NoContact ? 1 : 0;
      }
    }
    EXPECT_GT(contact, 200u);
  }
}

// classifyRun evaluates a long run's contact rows in chunks; every step's log-likelihoods and
// per-step class equal those of the whole feature matrix evaluated at once, across chunk edges.
TEST(ClassifyRun, ChunkedEvaluationEqualsTheWholeMatrixAtOnce) {
  Runs train = makeRuns({"a", "b"}, 1500);
  TrainJob job;
  job.runs = train.labelled;
  job.runRefs = train.refs;
  job.settings = quick();
  job.groups = {SensorGroup::Left};
  auto out = trainAndEvaluate(job);
  ASSERT_TRUE(out.ok()) << out.errorText();
  const RunData run = testdata::makeLabelledRun(30000, 4242);
  const RunClassification r = classifyRun(run, out->bundle, {});
  const GroupClassification& gc = r.groups[static_cast<std::size_t>(groupIndex(SensorGroup::Left))];
  ASSERT_NE(gc.model, nullptr);
  const GroupSteps gs = extractGroupSteps(run, SensorGroup::Left, gc.model->features);
  Eigen::MatrixXd all;
  gc.model->classifier.logLikelihoods(gs.features, all);
  const std::vector<int> pred = gc.model->classifier.predictFromLogLikelihoods(all);
  std::size_t contact = 0;
  for (std::size_t t = 0; t < run.stepCount(); ++t) {
    if (gs.isZero[t]) {
      EXPECT_FALSE(gc.predicted[t].has_value()) << t;
      continue;
    }
    // A row per contact step, in step order.
    const auto row = static_cast<Eigen::Index>(contact++);
    ASSERT_LT(row, gc.logLikelihoods.rows()) << t;
    for (Eigen::Index c = 0; c < all.cols(); ++c)
      ASSERT_EQ(gc.logLikelihoods(row, c), all(static_cast<Eigen::Index>(t), c)) << t;
    ASSERT_EQ(gc.predicted[t], pred[t]) << t;
  }
  EXPECT_GT(contact, 3u * 4096u);  // several chunks
}

// Context features from a run equal those the decider computes from its kept history.
TEST(ContextFeatures, RunAndStreamAgree) {
  const RunData run = testdata::makeLabelledRun(200, 5);
  const SensorGroup g = SensorGroup::Right;
  const GroupInfo& info = groupInfo(g);
  EXPECT_EQ(featureDimension(g, FeatureKind::Context), 3 * info.sensorCount + kTouchFlags + 3);
  for (FeatureKind kind : {FeatureKind::Context, FeatureKind::Neighbours}) {
    const int d = featureDimension(g, kind);
    std::vector<double> a(static_cast<std::size_t>(d)), b(static_cast<std::size_t>(d));
    int touched = 0;
    for (std::size_t t = 0; t < run.stepCount(); ++t) {
      groupFeatures(run, t, g, kind, a.data());
      StepContext c;
      c.values = run.stepSensors(t);
      c.laggedValues = t >= kContextLag ? run.stepSensors(t - kContextLag) : nullptr;
      c.v = run.v[t];
      c.omega = run.omega[t];
      c.contactSteps = touched;
      groupFeatures(c, g, kind, b.data());
      ASSERT_EQ(a, b) << t;
      touched = groupIsZero(run, t, g) ? 0 : touched + 1;
      // Lagged differences: n_t - n_{t-k} (both kinds begin with the context features).
      const double before = t >= kContextLag ? run.normal(t - kContextLag, info.firstSensor) : 0.0;
      EXPECT_EQ(a[static_cast<std::size_t>(2 * info.sensorCount + kTouchFlags)],
                run.normal(t, info.firstSensor) - before);
    }
  }
}

}  // namespace
}  // namespace tactile::analysis
