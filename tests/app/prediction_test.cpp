// Predictions in the workbench: the model's per-step classes equal `tactile classify`'s core call,
// confidences are probabilities, disagreements are exactly where prediction and label differ and
// N walks them (wrapping), holes match the side scan, and the timeline, route and main window show
// them.
#include <QComboBox>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>
#include <memory>

#include "analysis/classify_run.h"
#include "analysis/features.h"
#include "analysis/hole_detection.h"
#include "analysis/temporal.h"
#include "app/gui/common/window_geometry.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/learning/model_picker_dialog.h"
#include "app/gui/learning/prediction_model.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/route_view.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"
#include "gui_fixture.h"

using namespace tactile;
using tactile::gui::PredictionModel;

namespace {

void settle() {
  for (int i = 0; i < 3; ++i)
    QTest::qWait(10);
}

// The fixture's run labelled from its truth (set "truth"), a model trained on it, and a copy of
// the set with one stretch relabelled so that the model surely disagrees there.
struct Predicted {
  gui::testing::GuiFixture fx{900, "room1"};
  std::string model = "m";
  std::int64_t runId = 0;

  explicit Predicted(analysis::ClassifierMethod method = analysis::ClassifierMethod::Gmm) {
    auto info = fx.workspace->runStore().find(fx.runName);
    if (!info) throw std::runtime_error(info.errorText());
    runId = info->id;
    if (!fx.workspace->labelStore().autolabel(runId, "truth"))
      throw std::runtime_error("autolabel failed");
    workspace::TrainRequest request;
    request.labelSet = "truth";
    request.trainRuns = {fx.runName};
    request.modelName = model;
    request.minRowsPerGroup = 5;
    for (analysis::TrainSettings& s : request.settings.byGroup) {
      s.classifier.gmm.components = 1;
      s.classifier.method = method;
      s.classifier.gbt.trees = 20;
    }
    auto trained = fx.workspace->train(request);
    if (!trained) throw std::runtime_error(trained.errorText());
  }
};

// Labels of the fixture's run in a set (an existing one, or a new empty one), and the model's
// predictions computed for that run.
struct Reviewed {
  Predicted p;
  gui::LabelModel labels;
  std::unique_ptr<PredictionModel> predictions;

  explicit Reviewed(const std::string& set, bool create) {
    labels.setWorkspace(p.fx.workspace.get());
    if (!(create ? labels.createSet(set) : labels.openSet(set)))
      throw std::runtime_error("no label set " + set);
    auto info = p.fx.workspace->runStore().find(p.fx.runName);
    labels.setRun(info->id, info->name, info->stepCount);
    predictions = std::make_unique<PredictionModel>(&labels);
    predictions->compute(QString::fromStdString(p.fx.dbPath), QString::fromStdString(p.fx.runName),
                         PredictionModel::sameForAll(QString::fromStdString(p.model)));
    predictions->waitForFinished();
  }
};

}  // namespace

class PredictionTest : public QObject {
  Q_OBJECT

 private slots:
  void posteriorsAreProbabilitiesInLogSpace();
  void predictionsEqualTheCoreClassification();
  void disagreementsAreWherePredictionAndLabelDiffer();
  void nextDisagreementWrapsAround();
  void nextDoubtFindsWhereTheModelIsUnsure();
  void nLandsOnTheNextDisagreeingStretch();
  void holesMatchTheSideScan();
  void timelineAndRouteShowPredictions();
  void mainWindowShowsAModelAndKeyNJumps();
  void pickerChoosesOneOrPerGroup();
  void windowFitsASmallScreenWithPredictionsOn();

 private:
  static void predictionsEqualCore(Predicted& p);
};

void PredictionTest::posteriorsAreProbabilitiesInLogSpace() {
  const double ninf = -std::numeric_limits<double>::infinity();
  Eigen::MatrixXd ll(3, 3);
  ll << -1000.0, -1001.0, -1003.0,  // far below exp's range: still a proper posterior
      ninf, ninf, ninf,             // no class can explain the row
      0.0, ninf, -2.0;
  const Eigen::VectorXd priors = Eigen::Vector3d::Constant(std::log(1.0 / 3.0));
  const Eigen::MatrixXd post = gui::logPosteriors(ll, priors);
  double sum = 0.0;
  for (int c = 0; c < 3; ++c)
    sum += std::exp(post(0, c));
  QVERIFY(std::abs(sum - 1.0) < 1e-12);
  QVERIFY(std::abs(std::exp(post(0, 0)) - 1.0 / (1.0 + std::exp(-1.0) + std::exp(-3.0))) < 1e-12);
  for (int c = 0; c < 3; ++c)
    QVERIFY(post(1, c) == ninf);
  QVERIFY(post(2, 1) == ninf);
  QVERIFY(!std::isnan(post.sum()));
}

void PredictionTest::predictionsEqualTheCoreClassification() {
  for (analysis::ClassifierMethod method :
       {analysis::ClassifierMethod::Gmm, analysis::ClassifierMethod::Gbt}) {
    Predicted p(method);
    predictionsEqualCore(p);
  }
}

// The strip of `p`'s model equals the core's classification step for step (the same function
// `tactile classify` calls).
void PredictionTest::predictionsEqualCore(Predicted& p) {
  gui::LabelModel labels;
  PredictionModel predictions(&labels);
  QSignalSpy ready(&predictions, &PredictionModel::ready);
  predictions.compute(QString::fromStdString(p.fx.dbPath), QString::fromStdString(p.fx.runName),
                      PredictionModel::sameForAll(QString::fromStdString(p.model)));
  QVERIFY(predictions.isComputing());
  QVERIFY(ready.wait(30000));
  auto classified = p.fx.workspace->classify(p.model, p.fx.runName);
  QVERIFY(classified.ok());
  QCOMPARE(predictions.stepCount(), static_cast<std::int64_t>(classified->result.steps));
  std::size_t predicted = 0;
  for (const GroupInfo& g : kSensorGroups) {
    const gui::GroupPrediction& mine = predictions.group(g.group);
    const analysis::GroupClassification& core =
        classified->result.groups[static_cast<std::size_t>(groupIndex(g.group))];
    QCOMPARE(mine.hasModel, core.model != nullptr);
    for (std::size_t t = 0; t < classified->result.steps; ++t) {
      const std::string name = core.stepClassName(t);
      const auto cls = mine.classAt(static_cast<std::int64_t>(t));
      QCOMPARE(cls ? std::string(contactClassName(*cls)) : std::string(), name);
      const float conf = mine.confidence[t];
      QVERIFY(std::isfinite(conf) && conf >= 0.0f && conf <= 1.0f);
      if (cls && *cls != ContactClass::NoContact) {
        ++predicted;
        // With C classes the winner's posterior is at least 1 / C...
        QVERIFY(conf >= 1.0f / static_cast<float>(core.model->classes.size()) - 1e-6f);
        // ...and it is the classifier's own posterior of that step's features.
        const analysis::ClassModelSet& classifier = core.model->classifier;
        Eigen::MatrixXd x(1, analysis::featureDimension(g.group, core.model->features));
        analysis::groupFeatures(classified->run, t, g.group, core.model->features, x.data());
        Eigen::MatrixXd ll;
        classifier.logLikelihoods(x, ll);
        const Eigen::VectorXd joint = ll.row(0).transpose() + classifier.logPriors();
        const double expected = std::exp(joint[*core.predicted[t]] - analysis::logSumExp(joint));
        QVERIFY2(std::abs(conf - expected) < 1e-5, qPrintable(QString::number(t)));
      }
    }
  }
  QVERIFY(predicted > 0);
}

void PredictionTest::disagreementsAreWherePredictionAndLabelDiffer() {
  Reviewed r("truth", false);
  gui::LabelModel& labels = r.labels;
  PredictionModel& predictions = *r.predictions;
  QVERIFY(predictions.hasPredictions());
  auto check = [&] {
    std::size_t total = 0;
    for (const GroupInfo& g : kSensorGroups) {
      const gui::GroupPrediction& pr = predictions.group(g.group);
      std::size_t counted = 0;
      for (std::int64_t t = 0; t < predictions.stepCount(); ++t) {
        const auto said = pr.classAt(t);
        const auto label = labels.classAt(g.group, t);
        const bool differs = said && label && *said != *label;
        if (differs != (pr.disagrees[static_cast<std::size_t>(t)] != 0)) return false;
        counted += differs ? 1 : 0;
      }
      if (counted != pr.disagreements) return false;
      total += counted;
    }
    (void)total;
    return true;
  };
  QVERIFY(check());
  // Relabelling a contact step as DeadPath (which this model never predicts) makes it a
  // disagreement, and the change arrives without recomputing.
  // The first group and step with a predicted contact class.
  std::optional<SensorGroup> group;
  std::int64_t first = -1;
  for (const GroupInfo& g : kSensorGroups) {
    const gui::GroupPrediction& pr = predictions.group(g.group);
    for (std::int64_t t = 0; t < predictions.stepCount() && first < 0; ++t)
      if (pr.classAt(t) && *pr.classAt(t) != ContactClass::NoContact) first = t;
    if (first >= 0) {
      group = g.group;
      break;
    }
  }
  QVERIFY(group.has_value());
  const std::size_t before = predictions.group(*group).disagreements;
  QSignalSpy changed(&predictions, &PredictionModel::changed);
  QVERIFY(labels.label({*group}, first, first, ContactClass::DeadPath).ok());
  QVERIFY(changed.count() >= 1);
  QVERIFY(check());
  QVERIFY(predictions.group(*group).disagrees[static_cast<std::size_t>(first)]);
  QVERIFY(predictions.group(*group).disagreements >= before);
}

void PredictionTest::nextDisagreementWrapsAround() {
  Reviewed r("mine", true);
  gui::LabelModel& labels = r.labels;
  PredictionModel& predictions = *r.predictions;
  QVERIFY(!predictions.nextDisagreement(0, std::nullopt));  // an empty set: nothing to disagree
  // Two labelled steps that the model cannot have predicted: DeadPath on a no-contact rule step
  // is still a disagreement (the rule says NoContact).
  const std::int64_t a = 100, b = 400;
  QVERIFY(labels.label({SensorGroup::Back}, a, a, ContactClass::DeadPath).ok());
  QVERIFY(labels.label({SensorGroup::Back}, b, b, ContactClass::DeadPath).ok());
  QCOMPARE(predictions.nextDisagreement(0, std::nullopt), std::optional<std::int64_t>(a));
  QCOMPARE(predictions.nextDisagreement(a, std::nullopt), std::optional<std::int64_t>(b));
  QCOMPARE(predictions.nextDisagreement(b, std::nullopt), std::optional<std::int64_t>(a));  // wraps
  QCOMPARE(predictions.previousDisagreement(a, std::nullopt), std::optional<std::int64_t>(b));
  QCOMPARE(predictions.nextDisagreement(0, SensorGroup::Back), std::optional<std::int64_t>(a));
  QVERIFY(!predictions.nextDisagreement(0, SensorGroup::Front));
}

// D lands on the first step of each stretch where some group's posterior is below the
// threshold, checked against the posteriors themselves; at threshold 0 nothing is unsure.
void PredictionTest::nextDoubtFindsWhereTheModelIsUnsure() {
  Reviewed r("truth", false);
  PredictionModel& predictions = *r.predictions;
  const std::int64_t steps = predictions.stepCount();
  QVERIFY(steps > 0);
  QVERIFY(!predictions.nextDoubt(0, 0.0));
  // Pick the threshold between the lowest posteriors so that some, not all, steps are unsure.
  std::vector<float> all;
  for (const GroupInfo& g : kSensorGroups) {
    const gui::GroupPrediction& p = predictions.group(g.group);
    for (std::size_t k = 0; k < p.cls.size(); ++k)
      if (p.cls[k] >= 0) all.push_back(p.confidence[k]);
  }
  std::sort(all.begin(), all.end());
  QVERIFY(!all.empty());
  QVERIFY2(all.front() < 0.999f, "the model is certain everywhere: no doubt to find");
  const double threshold = std::min(0.999, static_cast<double>(all.front()) + 1e-6);
  auto unsure = [&](std::int64_t t) {
    for (const GroupInfo& g : kSensorGroups) {
      const gui::GroupPrediction& p = predictions.group(g.group);
      const auto k = static_cast<std::size_t>(t);
      if (k < p.cls.size() && p.cls[k] >= 0 && p.confidence[k] < threshold) return true;
    }
    return false;
  };
  std::int64_t expected = -1;
  for (std::int64_t t = 1; t < steps && expected < 0; ++t)
    if (unsure(t) && !unsure(t - 1)) expected = t;
  if (expected < 0 && unsure(0)) expected = 0;
  const auto found = predictions.nextDoubt(0, threshold);
  QVERIFY(found.has_value());
  QVERIFY(unsure(*found));
  QVERIFY(*found == 0 || !unsure(*found - 1));
  if (expected > 0) QCOMPARE(*found, expected);
  const auto group = predictions.doubtfulGroup(*found, threshold);
  QVERIFY(group.has_value());
  QVERIFY(predictions.group(*group).confidence[static_cast<std::size_t>(*found)] < threshold);
  // From there the next stretch is another one (or the same after wrapping, when it is the only).
  const auto again = predictions.nextDoubt(*found, threshold);
  QVERIFY(again.has_value());
  QVERIFY(*again == *found || !unsure(*again - 1));
}

// Regression: N moved one step at a time through a stretch of disagreement (hundreds of presses
// to cross one).
void PredictionTest::nLandsOnTheNextDisagreeingStretch() {
  Reviewed r("mine", true);
  // Long labelled stretches a no-contact rule and a one-component model surely contradict.
  QVERIFY(r.labels.label({SensorGroup::Back}, 100, 299, ContactClass::DeadPath).ok());
  QVERIFY(r.labels.label({SensorGroup::Front}, 500, 599, ContactClass::DeadPath).ok());
  QVERIFY(r.labels.label({SensorGroup::Left}, 550, 650, ContactClass::DeadPath).ok());
  const PredictionModel& pm = *r.predictions;
  const std::int64_t n = pm.stepCount();
  auto any = [&](std::int64_t t) {
    for (const GroupInfo& g : kSensorGroups)
      if (pm.group(g.group).disagrees[static_cast<std::size_t>(t)]) return true;
    return false;
  };
  // The stretches, by their definition: a disagreeing step after one that does not disagree.
  std::vector<std::int64_t> starts;
  std::int64_t disagreeing = 0;
  for (std::int64_t t = 0; t < n; ++t) {
    disagreeing += any(t) ? 1 : 0;
    if (any(t) && (t == 0 || !any(t - 1))) starts.push_back(t);
  }
  QVERIFY(starts.size() >= 2);
  QVERIFY2(static_cast<std::int64_t>(starts.size()) * 4 < disagreeing,
           "stretches are far fewer than disagreeing steps");
  const std::size_t k = starts.size();
  for (std::size_t i = 0; i < k; ++i) {
    std::int64_t end = starts[i];
    while (end + 1 < n && any(end + 1))
      ++end;
    const std::int64_t next = starts[(i + 1) % k];
    const std::int64_t previous = starts[(i + k - 1) % k];
    // From the first step, the middle or the last step of a stretch: the next one's first step.
    for (std::int64_t from : {starts[i], (starts[i] + end) / 2, end})
      QCOMPARE(pm.nextDisagreement(from, std::nullopt), std::optional(next));
    // Back from the next stretch's start lands on this one's; from inside this one, on the one
    // before.
    QCOMPARE(pm.previousDisagreement(next, std::nullopt), std::optional(starts[i]));
    QCOMPARE(pm.previousDisagreement(end, std::nullopt), std::optional(previous));
  }
  // Between two stretches: N and Shift+N land on their starts.
  if (starts[1] > starts[0] + 1) {
    std::int64_t gap = starts[1] - 1;
    QVERIFY(!any(gap));
    QCOMPARE(pm.nextDisagreement(gap, std::nullopt), std::optional(starts[1]));
    QCOMPARE(pm.previousDisagreement(gap, std::nullopt), std::optional(starts[0]));
  }
}

void PredictionTest::holesMatchTheSideScan() {
  Predicted p;
  auto run = p.fx.workspace->loadRun(p.fx.runName);
  QVERIFY(run.ok());
  const std::vector<gui::HoleMark> holes = gui::findHoles(run.value());
  // Every step's holes are exactly the side scans' holes, in side order.
  const auto placements = domePlacements();
  std::size_t k = 0;
  for (std::size_t t = 0; t < run->stepCount(); ++t) {
    const auto contact = analysis::sensorContacts(run.value(), t);
    for (std::size_t side = 0; side < analysis::kSides.size(); ++side) {
      const auto& s = analysis::kSides[side];
      for (const analysis::Hole& h :
           analysis::scanSide(contact, s.firstSensor, s.count, placements).holes) {
        QVERIFY(k < holes.size());
        QCOMPARE(holes[k].step, static_cast<std::int64_t>(t));
        QCOMPARE(holes[k].side, static_cast<int>(side));
        QCOMPARE(holes[k].widthUnits, h.widthUnits);
        ++k;
      }
    }
  }
  QCOMPARE(k, holes.size());
}

void PredictionTest::timelineAndRouteShowPredictions() {
  Predicted p;
  gui::RunSession session;
  session.setWorkspace(p.fx.workspace.get());
  QVERIFY(session.open(p.fx.runName).ok());
  gui::LabelModel labels;
  labels.setWorkspace(p.fx.workspace.get());
  QVERIFY(labels.openSet("truth").ok());
  labels.setRun(session.info().id, session.info().name, session.stepCount());
  PredictionModel predictions(&labels);
  gui::TimelineView timeline(&session, &labels);
  gui::RouteView route(&session, &labels);
  timeline.resize(1200, 900);
  timeline.show();
  QVERIFY(QTest::qWaitForWindowExposed(&timeline));
  timeline.setPredictions(&predictions);
  route.setPredictions(&predictions);
  settle();
  QVERIFY(!timeline.showsPredictions());
  QVERIFY(timeline.predictionStripRect(SensorGroup::Front).isEmpty());
  predictions.compute(QString::fromStdString(p.fx.dbPath), QString::fromStdString(p.fx.runName),
                      PredictionModel::sameForAll(QString::fromStdString(p.model)));
  predictions.waitForFinished();
  settle();
  QVERIFY(timeline.showsPredictions());
  // A disagreement step shows red in its group's disagreement strip; an agreeing stretch does not.
  QVERIFY(labels.label({SensorGroup::Back}, 300, 300, ContactClass::DeadPath).ok());
  timeline.showWholeRun();
  settle();
  const QRect strip = timeline.disagreementStripRect(SensorGroup::Back);
  QVERIFY(!strip.isEmpty());
  const QImage image = timeline.grab().toImage();
  const QColor at300 =
      image.pixelColor(static_cast<int>(std::lround(timeline.stepToX(300))), strip.center().y());
  QVERIFY2(at300.red() > 150 && at300.green() < 60, qPrintable(at300.name()));
  // Tooltips: a model row says the class and its posterior, the holes row each hole's width.
  const QRect model = timeline.predictionStripRect(SensorGroup::Back);
  const QString modelTip = timeline.predictionTipAt(
      QPoint(static_cast<int>(std::lround(timeline.stepToX(300))), model.center().y()));
  QVERIFY2(modelTip.contains(QStringLiteral("step 300")) && modelTip.contains(QStringLiteral("%")),
           qPrintable(modelTip));
  QVERIFY(modelTip.contains(QStringLiteral("Dead path")));  // the label it disagrees with
  if (!predictions.holes().empty()) {
    const gui::HoleMark& h = predictions.holes().front();
    timeline.setVisibleRange({std::max<std::int64_t>(0, h.step - 20), h.step + 20});
    settle();
    const QString holeTip =
        timeline.predictionTipAt(QPoint(static_cast<int>(std::lround(timeline.stepToX(h.step))),
                                        timeline.holesStripRect().center().y()));
    QVERIFY2(holeTip.contains(QString::number(h.widthUnits, 'f', 1)), qPrintable(holeTip));
  }
  QVERIFY(timeline.predictionTipAt(timeline.heatmapRect().center()).isEmpty());
  // Route: the current step's holes are drawn across the robot.
  for (const gui::HoleMark& h : predictions.holes()) {
    QCOMPARE(route.holeMarksAt(h.step), static_cast<int>(predictions.holesAt(h.step).size()));
    break;
  }
  QCOMPARE(route.holeMarksAt(-5), 0);
  predictions.clear();
  settle();
  QVERIFY(!timeline.showsPredictions());
}

void PredictionTest::mainWindowShowsAModelAndKeyNJumps() {
  Predicted p;
  QTemporaryDir settingsDir;
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
  QSettings::setDefaultFormat(QSettings::IniFormat);
  gui::MainWindow window;
  window.resize(1400, 900);
  QVERIFY(window.openDatabase(QString::fromStdString(p.fx.dbPath)).ok());
  QVERIFY(window.openRun(QString::fromStdString(p.fx.runName)).ok());
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  QVERIFY(!window.showPredictions(QStringLiteral("no such model")).ok());
  QVERIFY(window.showPredictions(QString::fromStdString(p.model)).ok());
  window.waitForPredictions();
  QVERIFY(window.predictions()->hasPredictions());
  window.session()->setCurrentStep(0);
  const auto expected = window.predictions()->nextDisagreement(0, std::nullopt);
  QTest::keyClick(&window, Qt::Key_N);
  if (expected) {
    QCOMPARE(window.session()->currentStep(), *expected);
    QVERIFY(window.predictions()
                ->group(window.session()->selectedGroup())
                .disagrees[static_cast<std::size_t>(*expected)]);
    QTest::keyClick(&window, Qt::Key_N, Qt::ShiftModifier);
    QCOMPARE(window.session()->currentStep(),
             *window.predictions()->previousDisagreement(*expected, std::nullopt));
  } else {
    QCOMPARE(window.session()->currentStep(), std::int64_t{0});
  }
}

void PredictionTest::pickerChoosesOneOrPerGroup() {
  const QStringList models{QStringLiteral("a"), QStringLiteral("b")};
  gui::ModelPickerDialog same(models, PredictionModel::sameForAll(QStringLiteral("a")));
  QCOMPARE(same.choice(), PredictionModel::sameForAll(QStringLiteral("a")));
  PredictionModel::Choice mixed = PredictionModel::sameForAll(QStringLiteral("a"));
  mixed[static_cast<std::size_t>(groupIndex(SensorGroup::Back))] = QStringLiteral("b");
  mixed[static_cast<std::size_t>(groupIndex(SensorGroup::Left))] = QString();
  gui::ModelPickerDialog perGroup(models, mixed);
  QCOMPARE(perGroup.choice(), mixed);
  perGroup.setPerGroup(false);
  perGroup.allGroupsBox()->setCurrentIndex(perGroup.allGroupsBox()->findData(QStringLiteral("b")));
  QCOMPARE(perGroup.choice(), PredictionModel::sameForAll(QStringLiteral("b")));
  // Each model says which groups it covers; the choice is still the model's name.
  QStringList all;
  for (const GroupInfo& g : kSensorGroups)
    all << QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size()));
  perGroup.setCoverage({{QStringLiteral("a"), all},
                        {QStringLiteral("b"), {QStringLiteral("F"), QStringLiteral("L")}}});
  QComboBox* box = perGroup.allGroupsBox();
  QCOMPARE(box->itemText(box->findData(QStringLiteral("a"))), QStringLiteral("a (all groups)"));
  QCOMPARE(box->itemText(box->findData(QStringLiteral("b"))), QStringLiteral("b (F, L only)"));
  QCOMPARE(perGroup.choice(), PredictionModel::sameForAll(QStringLiteral("b")));
}

// Guards the window that grew taller than the screen (1103 px on a 1000 px screen) with predictions
// on: on a 1366x768 laptop screen (minus a title bar and a panel) the main window never asks for
// more, the timeline rows scroll instead, Hide Predictions gives the rows back, and a saved
// geometry larger than the screen comes back within it.
void PredictionTest::windowFitsASmallScreenWithPredictionsOn() {
  Predicted p;
  QTemporaryDir settingsDir;
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
  QSettings::setDefaultFormat(QSettings::IniFormat);
  gui::MainWindow window;
  QVERIFY(window.openDatabase(QString::fromStdString(p.fx.dbPath)).ok());
  QVERIFY(window.openRun(QString::fromStdString(p.fx.runName)).ok());
  window.resize(1366, 700);
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  auto* timeline = window.findChild<gui::TimelineView*>();
  QVERIFY(timeline != nullptr);
  auto* scroll = timeline->findChild<QScrollArea*>(QStringLiteral("timelineScroll"));
  QVERIFY(scroll != nullptr);
  const int plotHeightBefore = scroll->widget()->minimumHeight();
  QVERIFY(window.showPredictions(QString::fromStdString(p.model)).ok());
  window.waitForPredictions();
  settle();
  QVERIFY(window.predictions()->hasPredictions());
  constexpr int kScreenHeight = 768 - 30 - 40;  // a 1366x768 screen less a panel and a title bar
  QVERIFY2(window.minimumSizeHint().height() <= kScreenHeight,
           qPrintable(QString::number(window.minimumSizeHint().height())));
  QVERIFY(window.minimumSizeHint().width() <= 1366);
  QVERIFY2(window.height() <= 700, qPrintable(QString::number(window.height())));
  // The rows need more height than there is: they are all there, and scroll.
  const int plotHeight = scroll->widget()->minimumHeight();
  QVERIFY(plotHeight > plotHeightBefore);
  QVERIFY(plotHeight > scroll->viewport()->height());
  QVERIFY(scroll->verticalScrollBar()->maximum() > 0);
  // Hide Predictions: the rows and the height they asked for go at once.
  window.predictions()->clear();
  settle();
  QCOMPARE(scroll->widget()->minimumHeight(), plotHeightBefore);

  // A geometry saved on a taller screen comes back within this one.
  QWidget tall;
  tall.resize(1400, 4000);
  tall.move(-50, -50);
  const QByteArray saved = tall.saveGeometry();
  QWidget restored;
  gui::restoreGeometryWithinScreen(&restored, saved);
  const QRect available = restored.screen()->availableGeometry();
  QVERIFY2(available.contains(restored.geometry()), qPrintable(QStringLiteral("%1,%2 %3x%4")
                                                                   .arg(restored.x())
                                                                   .arg(restored.y())
                                                                   .arg(restored.width())
                                                                   .arg(restored.height())));
}

QTEST_MAIN(PredictionTest)
#include "prediction_test.moc"
