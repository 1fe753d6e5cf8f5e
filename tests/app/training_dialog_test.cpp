// The train-and-sweep dialog: a sweep started from it runs off the GUI thread with progress and a
// time estimate, streams its cells into the sortable table, can be cancelled keeping its finished
// cells, and stores exactly the numbers `tactile sweep` stores for the same request.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

#include "analysis/model_file.h"
#include "app/gui/learning/sweep_cells_model.h"
#include "app/gui/learning/sweep_results_view.h"
#include "app/gui/learning/sweep_results_window.h"
#include "app/gui/learning/sweep_worker.h"
#include "app/gui/learning/training_dialog.h"
#include "tests/app/gui_fixture.h"

using namespace tactile;
using tactile::gui::TrainingDialog;

namespace {

// The fixture's run plus two more from other scenes, all labelled from their truth in set
// "truth"; room3_demo is the test run.
struct LearningFixture : gui::testing::GuiFixture {
  LearningFixture() : GuiFixture(500, "room1") {
    for (const char* scene : {"room2", "room3"}) {
      auto loaded = sim::loadScene(scene);
      if (!loaded) throw std::runtime_error(loaded.errorText());
      auto world = std::make_shared<const sim::World>(std::move(loaded.value()));
      sim::RunOptions options;
      options.maxSteps = 500;
      options.stopAtGoal = false;
      auto run = sim::simulateRun(world, scene, options);
      if (!run) throw std::runtime_error(run.errorText());
      const std::string name = std::string(scene) + "_demo";
      const storage::ImportOutcome out = workspace->runStore().importRun(run.value().run, name);
      if (out.status != storage::ImportStatus::Imported) throw std::runtime_error(out.message);
    }
    for (const char* name : {"room1_demo", "room2_demo", "room3_demo"}) {
      auto info = workspace->runStore().find(name);
      if (!info) throw std::runtime_error(info.errorText());
      auto written = workspace->labelStore().autolabel(info->id, "truth");
      if (!written) throw std::runtime_error(written.errorText());
    }
  }
};

// A small grid: 2 groups x 2 orders x 1 form x 2 floors = 8 cells.
void smallGrid(TrainingDialog& dialog) {
  dialog.setLabelSet(QStringLiteral("truth"));
  dialog.setRunRole(QStringLiteral("room1_demo"), TrainingDialog::RunRole::Train);
  dialog.setRunRole(QStringLiteral("room2_demo"), TrainingDialog::RunRole::Train);
  dialog.setRunRole(QStringLiteral("room3_demo"), TrainingDialog::RunRole::Test);
  dialog.setGroupsChecked({SensorGroup::Front, SensorGroup::Left});
  dialog.setFormsChecked({analysis::CovarianceForm::NodalDiag});
  dialog.setGrid(QStringLiteral("1, 2"), QStringLiteral("0.03 0.1"), QStringLiteral("1"));
}

// Runs the small grid's sweep from the dialog; the stored sweep's id, or 0 when none was stored.
qint64 sweepFromDialog(TrainingDialog& dialog) {
  smallGrid(dialog);
  QSignalSpy stored(&dialog, &TrainingDialog::sweepStored);
  QSignalSpy finished(&dialog, &TrainingDialog::jobFinished);
  dialog.startSweep();
  if (!finished.wait(120000) || stored.count() != 1) return 0;
  return stored.first().at(0).toLongLong();
}

QPushButton* button(TrainingDialog& dialog, const char* name) {
  auto* b = dialog.findChild<QPushButton*>(QString::fromLatin1(name));
  if (b == nullptr) qFatal("no button %s", name);
  return b;
}

}  // namespace

class TrainingDialogTest : public QObject {
  Q_OBJECT

 private slots:
  // Each test starts with no remembered form (the dialog remembers its last label set and grid).
  void init() {
    settingsDir_ = std::make_unique<QTemporaryDir>();
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_->path());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings().clear();
  }
  void defaultSplitHoldsOutEveryFourthRun();
  void splitOffersTheCommandLinesSplitsWithItsDefault();
  void sweepShowsProgressAndStreamsSortedCells();
  void cliStoresTheSameNumbers();
  void cancelKeepsFinishedCells();
  void badGridIsReportedAndNothingStarts();
  void trainStoresAModel();
  void trainWithGroupDefaultsUsesEachGroupsOwn();
  void evidenceWeightIsEachGroupsDefaultUnlessSet();
  void resultsWindowExportsReportAndCellModel();
  void dialogRemembersLabelSetAndGrid();
  void resultsTableHasRoomForEightGroups();
  void planNamesGroupsTheTestRunsCannotScore();
  void planEstimatesFromEachCellsOwnCost();
  void orderOutOfRangeGetsTheCommandLinesWords();
  void resultsWindowFillsAsAWorkerProcessStoresCells();

 private:
  std::unique_ptr<QTemporaryDir> settingsDir_;
};

void TrainingDialogTest::defaultSplitHoldsOutEveryFourthRun() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  dialog.setLabelSet(QStringLiteral("truth"));
  auto request = dialog.sweepRequest();
  QVERIFY2(request.ok(), request.ok() ? "" : request.errorText().c_str());
  // Three runs: none is fourth, so the last by name is held out, as `tactile train` does.
  QCOMPARE(request->testRuns, std::vector<std::string>{"room3_demo"});
  QCOMPARE(request->trainRuns, (std::vector<std::string>{"room1_demo", "room2_demo"}));
}

// The split box names the command line's splits (by-scene among them) and starts on the command
// line's default; by-scene and by-run reach the requests, leave-one-run-out only the training one.
void TrainingDialogTest::splitOffersTheCommandLinesSplitsWithItsDefault() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  dialog.setLabelSet(QStringLiteral("truth"));
  auto* split = dialog.findChild<QComboBox*>(QStringLiteral("split"));
  QVERIFY(split != nullptr);
  QCOMPARE(split->count(), 3);
  for (const char* name : {"by-run", "by-scene", "leave-one-run-out"}) {
    const std::optional<workspace::SplitMode> mode = workspace::parseSplitMode(name);
    QVERIFY(mode.has_value());
    const int index = split->findData(static_cast<int>(*mode));
    QVERIFY2(index >= 0, name);
    QVERIFY2(split->itemText(index).startsWith(QString::fromLatin1(name) + QStringLiteral(" - ")),
             qPrintable(split->itemText(index)));
  }
  // `tactile train` and `tactile sweep` default to by-run.
  QCOMPARE(split->currentData().toInt(), static_cast<int>(*workspace::parseSplitMode("by-run")));
  QVERIFY(split->currentText().startsWith(QStringLiteral("by-run")));
  split->setCurrentIndex(split->findData(static_cast<int>(workspace::SplitMode::ByScene)));
  auto sweep = dialog.sweepRequest();
  QVERIFY2(sweep.ok(), sweep.ok() ? "" : sweep.errorText().c_str());
  QCOMPARE(sweep->split, workspace::SplitMode::ByScene);
  QVERIFY(sweep->testRuns.empty());
  auto train = dialog.trainRequest();
  QVERIFY2(train.ok(), train.ok() ? "" : train.errorText().c_str());
  QCOMPARE(train->split, workspace::SplitMode::ByScene);
  split->setCurrentIndex(split->findData(static_cast<int>(workspace::SplitMode::LeaveOneRunOut)));
  QVERIFY(!dialog.sweepRequest().ok());
  auto loo = dialog.trainRequest();
  QVERIFY2(loo.ok(), loo.ok() ? "" : loo.errorText().c_str());
  QCOMPARE(loo->split, workspace::SplitMode::LeaveOneRunOut);
}

void TrainingDialogTest::evidenceWeightIsEachGroupsDefaultUnlessSet() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  smallGrid(dialog);
  auto* weight = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("emissionWeight"));
  QVERIFY(weight);
  QCOMPARE(weight->value(), 0.0);
  QCOMPARE(weight->text(), weight->specialValueText());
  auto* groupDefaults = dialog.findChild<QCheckBox*>(QStringLiteral("groupDefaults"));
  QVERIFY(groupDefaults);
  for (bool defaults : {true, false}) {
    groupDefaults->setChecked(defaults);
    weight->setValue(0.0);
    auto request = dialog.trainRequest();
    QVERIFY2(request.ok(), request.ok() ? "" : request.errorText().c_str());
    bool someGroupIsNotOne = false;
    for (const GroupInfo& info : kSensorGroups) {
      // Each group's default model's weight, or, unticked, the default of the form's method
      // (GMM here) for the group.
      const double expected =
          defaults ? analysis::defaultTrainSettings(info.group).emissionWeight
                   : analysis::defaultEmissionWeight(info.group, analysis::ClassifierMethod::Gmm);
      QCOMPARE(request->settings.of(info.group).emissionWeight, expected);
      someGroupIsNotOne = someGroupIsNotOne || expected != 1.0;
    }
    QVERIFY(someGroupIsNotOne);
    weight->setValue(0.45);
    request = dialog.trainRequest();
    QVERIFY(request.ok());
    for (const analysis::TrainSettings& s : request->settings.byGroup)
      QCOMPARE(s.emissionWeight, 0.45);
    // Above 1 too: the trees' defaults weigh their evidence by up to 4.
    weight->setValue(4.0);
    QCOMPARE(weight->value(), 4.0);
    request = dialog.trainRequest();
    QVERIFY(request.ok());
    for (const analysis::TrainSettings& s : request->settings.byGroup)
      QCOMPARE(s.emissionWeight, 4.0);
  }
}

void TrainingDialogTest::sweepShowsProgressAndStreamsSortedCells() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  smallGrid(dialog);
  QSignalSpy progressed(dialog.worker(), &gui::SweepWorker::progressed);
  QSignalSpy cells(dialog.worker(), &gui::SweepWorker::cellFinished);
  QSignalSpy stored(&dialog, &TrainingDialog::sweepStored);
  QSignalSpy finished(&dialog, &TrainingDialog::jobFinished);
  QTest::mouseClick(button(dialog, "runSweep"), Qt::LeftButton);
  QVERIFY(dialog.worker()->isRunning());
  QVERIFY(!button(dialog, "runSweep")->isEnabled());
  QVERIFY(button(dialog, "cancel")->isEnabled());
  QCOMPARE(dialog.progressBar()->maximum(), 8);
  QVERIFY(!dialog.formEditable());  // the grid is locked while it runs
  QVERIFY(finished.wait(120000));
  QVERIFY(dialog.formEditable());
  // The stored sweep is named by what it swept, and the plan now estimates from its times.
  auto sweeps = f.workspace->sweeps();
  QVERIFY(sweeps.ok() && !sweeps->empty());
  QVERIFY2(QString::fromStdString(sweeps->back().name).contains(QStringLiteral("order 1-2")),
           sweeps->back().name.c_str());
  QVERIFY2(dialog.planLabel()->text().contains(QStringLiteral("about")),
           qPrintable(dialog.planLabel()->text()));

  QCOMPARE(cells.count(), 8);
  QCOMPARE(dialog.cellsModel()->rowCount(), 8);
  QVERIFY(progressed.count() >= 1);
  QCOMPARE(progressed.last().at(0).toLongLong(), 8);  // done
  QCOMPARE(progressed.last().at(1).toLongLong(), 8);  // of
  QCOMPARE(dialog.progressBar()->value(), 8);
  QVERIFY2(dialog.statusLabel()->text().contains(QStringLiteral("finished")),
           qPrintable(dialog.statusLabel()->text()));
  QCOMPARE(stored.count(), 1);
  const qint64 sweepId = stored.first().at(0).toLongLong();
  QVERIFY(sweepId > 0);
  QVERIFY(button(dialog, "runSweep")->isEnabled());
  QVERIFY(!button(dialog, "cancel")->isEnabled());

  // The table is sorted by balanced accuracy, best first, and shows each cell's own score.
  const QAbstractItemModel* view = dialog.cellsView()->model();
  double previous = 1e9;
  for (int row = 0; row < view->rowCount(); ++row) {
    const double score =
        view->data(view->index(row, gui::SweepCellsModel::BalancedAccuracy), Qt::UserRole)
            .toDouble();
    QVERIFY(score <= previous);
    previous = score;
  }
  double best = -1;
  for (const analysis::SweepCellResult& c : dialog.cellsModel()->cells())
    if (c.ok) best = std::max(best, 100.0 * c.metrics.balancedAccuracy);
  QVERIFY(best > 0.0);  // cells were fitted and scored
  QCOMPARE(
      view->data(view->index(0, gui::SweepCellsModel::BalancedAccuracy), Qt::UserRole).toDouble(),
      best);

  // What the table shows is what was stored.
  auto loaded = f.workspace->loadSweep(sweepId);
  QVERIFY(loaded.ok());
  QCOMPARE(loaded->cells.size(), std::size_t{8});
}

void TrainingDialogTest::cliStoresTheSameNumbers() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  const qint64 guiSweep = sweepFromDialog(dialog);
  QVERIFY(guiSweep > 0);

  QProcess cli;
  cli.start(QStringLiteral(TACTILE_CLI), {QStringLiteral("sweep"),
                                          QStringLiteral("--db"),
                                          QString::fromStdString(f.dbPath),
                                          QStringLiteral("--set"),
                                          QStringLiteral("truth"),
                                          QStringLiteral("--train-runs"),
                                          QStringLiteral("room1_demo,room2_demo"),
                                          QStringLiteral("--test-runs"),
                                          QStringLiteral("room3_demo"),
                                          QStringLiteral("--groups"),
                                          QStringLiteral("F,L"),
                                          QStringLiteral("--orders"),
                                          QStringLiteral("1,2"),
                                          QStringLiteral("--covs"),
                                          QStringLiteral("nodal-diag"),
                                          QStringLiteral("--floors"),
                                          QStringLiteral("0.03,0.1"),
                                          QStringLiteral("--seeds"),
                                          QStringLiteral("1"),
                                          QStringLiteral("--json")});
  QVERIFY(cli.waitForFinished(180000));
  QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());

  auto sweeps = f.workspace->sweeps();
  QVERIFY(sweeps.ok());
  QCOMPARE(sweeps->size(), std::size_t{2});
  const std::int64_t cliSweep =
      sweeps->front().id == guiSweep ? sweeps->back().id : sweeps->front().id;
  auto a = f.workspace->loadSweep(guiSweep);
  auto b = f.workspace->loadSweep(cliSweep);
  QVERIFY(a.ok() && b.ok());
  QCOMPARE(a->cells.size(), b->cells.size());
  QCOMPARE(a->cells.size(), std::size_t{8});
  for (std::size_t i = 0; i < a->cells.size(); ++i) {
    const analysis::SweepCellResult& x = a->cells[i];
    const analysis::SweepCellResult& y = b->cells[i];
    QCOMPARE(x.cell.group, y.cell.group);
    QCOMPARE(x.cell.order, y.cell.order);
    QCOMPARE(x.cell.varianceFloor, y.cell.varianceFloor);
    QCOMPARE(x.ok, y.ok);
    QCOMPARE(x.trainRows, y.trainRows);
    QCOMPARE(x.testRows, y.testRows);
    QCOMPARE(x.iterations, y.iterations);
    QVERIFY(x.confusion == y.confusion);
    QVERIFY(x.confusion.total() > 0 || !x.ok);
    QCOMPARE(x.metrics.balancedAccuracy, y.metrics.balancedAccuracy);
    QCOMPARE(x.meanLogLikelihood.has_value(), y.meanLogLikelihood.has_value());
    if (x.meanLogLikelihood) QCOMPARE(*x.meanLogLikelihood, *y.meanLogLikelihood);
  }
}

void TrainingDialogTest::cancelKeepsFinishedCells() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  dialog.setLabelSet(QStringLiteral("truth"));
  // Big enough not to finish before the cancel: 8 groups x 7 orders x 4 forms x 3 floors.
  dialog.setFormsChecked({analysis::CovarianceForm::NodalFull, analysis::CovarianceForm::NodalDiag,
                          analysis::CovarianceForm::GrandFull,
                          analysis::CovarianceForm::GrandDiag});
  dialog.setGrid(QStringLiteral("1,2,4,8,16,32,64"), QStringLiteral("0.01,0.03,0.1"),
                 QStringLiteral("1"));
  QSignalSpy cells(dialog.worker(), &gui::SweepWorker::cellFinished);
  QSignalSpy finished(&dialog, &TrainingDialog::jobFinished);
  QSignalSpy stored(&dialog, &TrainingDialog::sweepStored);
  dialog.startSweep();
  QCOMPARE(dialog.progressBar()->maximum(), 8 * 7 * 4 * 3);
  QVERIFY(cells.wait(120000));
  QTest::mouseClick(button(dialog, "cancel"), Qt::LeftButton);
  QVERIFY(!button(dialog, "cancel")->isEnabled());
  QVERIFY(finished.wait(60000));
  QVERIFY2(dialog.statusLabel()->text().contains(QStringLiteral("cancelled")),
           qPrintable(dialog.statusLabel()->text()));
  const int shown = dialog.cellsModel()->rowCount();
  QVERIFY(shown >= 1);
  QVERIFY(shown < 8 * 7 * 4 * 3);
  QCOMPARE(stored.count(), 1);
  auto sweep = f.workspace->loadSweep(stored.first().at(0).toLongLong());
  QVERIFY(sweep.ok());
  QVERIFY(sweep->cancelled);
  QCOMPARE(static_cast<int>(sweep->cells.size()), shown);
  QVERIFY(button(dialog, "runSweep")->isEnabled());
}

void TrainingDialogTest::badGridIsReportedAndNothingStarts() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  smallGrid(dialog);
  dialog.setGrid(QStringLiteral("1, x"), QStringLiteral("0.1"), QStringLiteral("1"));
  dialog.startSweep();
  QVERIFY(!dialog.worker()->isRunning());
  QVERIFY2(dialog.statusLabel()->text().contains(QStringLiteral("&#x27;x&#x27;")) ||
               dialog.statusLabel()->text().contains(QStringLiteral("'x'")),
           qPrintable(dialog.statusLabel()->text()));
  dialog.setGrid(QStringLiteral("1"), QStringLiteral("-0.1"), QStringLiteral("1"));
  dialog.startSweep();
  QVERIFY(!dialog.worker()->isRunning());
  QVERIFY2(dialog.statusLabel()->text().contains(QStringLiteral("-0.1 is out of range")),
           qPrintable(dialog.statusLabel()->text()));
  QVERIFY2(dialog.planLabel()->text().contains(QStringLiteral("-0.1 is out of range")),
           qPrintable(dialog.planLabel()->text()));
  auto sweeps = f.workspace->sweeps();
  QVERIFY(sweeps.ok());
  QVERIFY(sweeps->empty());
  // Once the form is fixed the message goes, and the plan counts the cells before any start.
  dialog.setGrid(QStringLiteral("1, 2"), QStringLiteral("0.1"), QStringLiteral("1"));
  QVERIFY2(!dialog.statusLabel()->text().contains(QStringLiteral("out of range")),
           qPrintable(dialog.statusLabel()->text()));
  auto request = dialog.sweepRequest();
  QVERIFY(request.ok());
  const auto cells = analysis::expandGrid(request->grid).size();
  QVERIFY2(dialog.planLabel()->text().startsWith(QStringLiteral("%1 cell").arg(cells)),
           qPrintable(dialog.planLabel()->text()));
}

void TrainingDialogTest::trainStoresAModel() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  smallGrid(dialog);
  auto* groupDefaults = dialog.findChild<QCheckBox*>(QStringLiteral("groupDefaults"));
  QVERIFY(groupDefaults);
  QVERIFY(groupDefaults->isChecked());
  groupDefaults->setChecked(false);  // the first value of every list
  QSignalSpy trained(&dialog, &TrainingDialog::modelTrained);
  QSignalSpy finished(&dialog, &TrainingDialog::jobFinished);
  QTest::mouseClick(button(dialog, "trainModel"), Qt::LeftButton);
  QVERIFY(finished.wait(120000));
  QCOMPARE(trained.count(), 1);
  // The new result is shown: a row per group trained, not the cells of an earlier sweep.
  QCOMPARE(dialog.trainResultView()->rowCount(), 2);
  QVERIFY(dialog.trainResultView()->isVisibleTo(&dialog));
  const QString name = trained.first().at(0).toString();
  auto bundle = f.workspace->loadModel(name.toStdString());
  QVERIFY2(bundle.ok(), bundle.ok() ? "" : bundle.errorText().c_str());
  // Groups F and L only, each either in the bundle or reported as skipped; order 1 (the first).
  QVERIFY(!bundle->models.empty());
  for (const char* group : {"F", "L"}) {
    bool inBundle = false;
    for (const analysis::GroupModel& m : bundle->models) {
      QVERIFY(m.group == SensorGroup::Front || m.group == SensorGroup::Left);
      inBundle = inBundle || groupInfo(m.group).shortName == group;
    }
    const bool skipped =
        dialog.statusLabel()->text().contains(QStringLiteral("%1: skipped").arg(group));
    QVERIFY2(inBundle != skipped, qPrintable(dialog.statusLabel()->text()));
  }
  for (const analysis::GroupModel& m : bundle->models) {
    QCOMPARE(m.varianceFloor, 0.03);
    // The class chain weighs the evidence as a sweep of these settings scored it.
    QCOMPARE(m.transitions.emissionWeight,
             analysis::defaultEmissionWeight(m.group, analysis::ClassifierMethod::Gmm));
    for (const analysis::GaussianMixture& mixture : m.classifier.models())
      QCOMPARE(mixture.components(), 1);
  }
}

void TrainingDialogTest::trainWithGroupDefaultsUsesEachGroupsOwn() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  smallGrid(dialog);
  dialog.setGroupsChecked({SensorGroup::Front, SensorGroup::Left, SensorGroup::Right});
  QSignalSpy trained(&dialog, &TrainingDialog::modelTrained);
  QSignalSpy finished(&dialog, &TrainingDialog::jobFinished);
  QTest::mouseClick(button(dialog, "trainModel"), Qt::LeftButton);
  QVERIFY(finished.wait(120000));
  QCOMPARE(trained.count(), 1);
  auto bundle = f.workspace->loadModel(trained.first().at(0).toString().toStdString());
  QVERIFY2(bundle.ok(), bundle.ok() ? "" : bundle.errorText().c_str());
  QVERIFY(!bundle->models.empty());
  // Not the lists' firsts (order 1, floor 0.03, normal): each group's own defaults.
  bool trees = false;
  for (const analysis::GroupModel& m : bundle->models) {
    const analysis::TrainSettings d = analysis::defaultTrainSettings(m.group);
    QCOMPARE(m.features, d.features);
    QCOMPARE(m.transitions.emissionWeight, d.emissionWeight);
    // Each group's own family too.
    QCOMPARE(m.classifier.trees() != nullptr,
             d.classifier.method == analysis::ClassifierMethod::Gbt);
    if (m.classifier.trees() != nullptr) {
      trees = true;
      QCOMPARE(m.provenance.classifier.gbt.trees, d.classifier.gbt.trees);
      QCOMPARE(m.provenance.classifier.gbt.depth, d.classifier.gbt.depth);
      continue;
    }
    QCOMPARE(m.covariance, d.classifier.gmm.form);
    QCOMPARE(m.varianceFloor, d.classifier.gmm.varianceFloor);
    for (const analysis::GaussianMixture& mixture : m.classifier.models())
      QVERIFY(mixture.components() <= d.classifier.gmm.components);
    QCOMPARE(m.provenance.classifier.gmm.components, d.classifier.gmm.components);
  }
  QVERIFY(trees);  // F, L and R are trees by default
}

void TrainingDialogTest::resultsWindowExportsReportAndCellModel() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  const qint64 id = sweepFromDialog(dialog);
  QVERIFY(id > 0);

  gui::SweepResultsWindow window(*f.workspace, QString::fromStdString(f.dbPath));
  QVERIFY(window.showSweep(id).ok());
  QVERIFY(window.windowTitle().contains(QStringLiteral("finished")));
  QCOMPARE(window.sweep().cells.size(), std::size_t{8});
  QVERIFY(!window.showSweep(id + 100).ok());  // an unknown sweep is an error, the shown one stays
  QCOMPARE(window.sweepId(), id);

  // The report is exactly what `tactile report --out` writes (the same core function).
  QTemporaryDir dir;
  const QString html = dir.filePath(QStringLiteral("r.html"));
  QVERIFY(window.exportReport(html).ok());
  const QString md = dir.filePath(QStringLiteral("r.md"));
  QVERIFY(window.exportReport(md).ok());
  QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("r_files/time_error.svg"))));
  QProcess cli;
  const QString cliHtml = dir.filePath(QStringLiteral("cli.html"));
  cli.start(QStringLiteral(TACTILE_CLI),
            {QStringLiteral("report"), QStringLiteral("--db"), QString::fromStdString(f.dbPath),
             QStringLiteral("--sweep"), QString::number(id), QStringLiteral("--format"),
             QStringLiteral("html"), QStringLiteral("--out"), cliHtml});
  QVERIFY(cli.waitForFinished(60000));
  QCOMPARE(cli.exitCode(), 0);
  QFile a(html), b(cliHtml);
  QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
  QCOMPARE(a.readAll(), b.readAll());

  // Store stores: the selected cell's model under the typed name, which the title then names; it
  // scores as the cell did.
  const int cell = window.view()->selectedCell();
  QVERIFY(cell >= 0);
  QSignalSpy modelStored(&window, &gui::SweepResultsWindow::modelStored);
  QVERIFY(window.trainSelectedCell(QStringLiteral("best cell")));
  QVERIFY(modelStored.wait(60000));
  QCOMPARE(modelStored.first().at(0).toString(), QStringLiteral("best cell"));
  auto model = f.workspace->modelStore().info("best cell");
  QVERIFY(model.ok());
  const nlohmann::json metrics = nlohmann::json::parse(model->metricsJson);
  const analysis::SweepCellResult& chosen = window.sweep().cells[static_cast<std::size_t>(cell)];
  const std::string group(groupInfo(chosen.cell.group).shortName);
  QVERIFY2(metrics.contains(group), model->metricsJson.c_str());
  auto* title = window.view()->findChild<QLabel*>(QStringLiteral("sweepTitle"));
  QVERIFY(title != nullptr);
  QVERIFY2(title->text().contains(QStringLiteral("best cell")), qPrintable(title->text()));
  QVERIFY(!title->text().contains(QStringLiteral("no model")));

  // Export exports (guards the export that also stored a model under a sentence-long name): the
  // file is written and read back, and no model is added to the database.
  auto before = f.workspace->models();
  QVERIFY(before.ok());
  QSignalSpy done(window.worker(), &gui::SweepWorker::finished);
  const QString file = dir.filePath(QStringLiteral("cell.json"));
  QVERIFY(window.trainSelectedCell(QString(), file));
  QVERIFY(done.wait(60000));
  QTest::qWait(10);
  QVERIFY(QFileInfo::exists(file));
  QVERIFY(analysis::readModelFile(file.toStdString()).ok());
  auto after = f.workspace->models();
  QVERIFY(after.ok());
  QCOMPARE(after->size(), before->size());
  QCOMPARE(modelStored.size(), 1);
  // Close (Ctrl+W) closes the window.
  auto* close = window.findChild<QAction*>(QStringLiteral("closeResults"));
  QVERIFY(close != nullptr);
  QCOMPARE(close->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_W));
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  close->trigger();
  QVERIFY(!window.isVisible());
}

// Guards the dialog that forgot its label set and grid between openings: closing remembers them
// (QSettings) and the next dialog opens with them.
void TrainingDialogTest::dialogRemembersLabelSetAndGrid() {
  LearningFixture f;
  QVERIFY(f.workspace->labelStore().create("other").ok());
  {
    TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
    auto* orders = dialog.findChild<QLineEdit*>(QStringLiteral("orders"));
    QVERIFY(orders != nullptr);
    QVERIFY(orders->text() != QStringLiteral("3, 5"));
    dialog.setLabelSet(QStringLiteral("other"));
    dialog.setGrid(QStringLiteral("3, 5"), QStringLiteral("0.2"), QStringLiteral("7"));
    dialog.setFormsChecked({analysis::CovarianceForm::GrandDiag});
    dialog.show();
    dialog.close();
  }
  TrainingDialog again(*f.workspace, QString::fromStdString(f.dbPath));
  QCOMPARE(again.findChild<QComboBox*>(QStringLiteral("labelSet"))->currentText(),
           QStringLiteral("other"));
  QCOMPARE(again.findChild<QLineEdit*>(QStringLiteral("orders"))->text(), QStringLiteral("3, 5"));
  QCOMPARE(again.findChild<QLineEdit*>(QStringLiteral("floors"))->text(), QStringLiteral("0.2"));
  QCOMPARE(again.findChild<QLineEdit*>(QStringLiteral("seeds"))->text(), QStringLiteral("7"));
  again.setLabelSet(QStringLiteral("truth"));  // "other" labels no run to sweep
  auto grid = again.sweepRequest();
  QVERIFY2(grid.ok(), grid.ok() ? "" : grid.errorText().c_str());
  QCOMPARE(grid->grid.forms,
           std::vector<analysis::CovarianceForm>{analysis::CovarianceForm::GrandDiag});
  QCOMPARE(grid->grid.orders, (std::vector<int>{3, 5}));
}

// Guards the results table that was one row tall at the dialog's default size: the eight groups'
// rows fit without scrolling.
void TrainingDialogTest::resultsTableHasRoomForEightGroups() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  dialog.show();
  QVERIFY(QTest::qWaitForWindowExposed(&dialog));
  auto* table = dialog.findChild<QTableWidget*>(QStringLiteral("trainResult"));
  QVERIFY(table != nullptr);
  const int needed = table->horizontalHeader()->height() +
                     kGroupCount * table->verticalHeader()->defaultSectionSize();
  auto* cells = dialog.findChild<QTableView*>(QStringLiteral("cells"));
  QVERIFY(cells != nullptr);
  QVERIFY2(cells->height() >= needed,
           qPrintable(QStringLiteral("%1 < %2").arg(cells->height()).arg(needed)));
}

// The plan says before the sweep which groups the test runs cannot score, and Leave Them Out
// unticks them.
void TrainingDialogTest::planNamesGroupsTheTestRunsCannotScore() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  dialog.setLabelSet(QStringLiteral("truth"));
  dialog.show();
  QVERIFY(QTest::qWaitForWindowExposed(&dialog));
  auto* note = dialog.findChild<QLabel*>(QStringLiteral("unscorable"));
  auto* leaveOut = dialog.findChild<QPushButton*>(QStringLiteral("leaveOut"));
  QVERIFY(note != nullptr && leaveOut != nullptr);
  // Counts from the test run itself: the groups with fewer contact steps than a score needs.
  auto rows = f.workspace->labelledContactSteps("truth", {"room3_demo"});
  QVERIFY(rows.ok());
  QStringList expected;
  for (const GroupInfo& g : kSensorGroups)
    if (rows.value()[static_cast<std::size_t>(groupIndex(g.group))] < analysis::kMinTestSteps)
      expected << QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size()));
  if (expected.isEmpty()) QSKIP("the test run scores every group");
  QVERIFY(note->isVisible());
  for (const QString& g : expected)
    QVERIFY2(note->text().contains(g), qPrintable(note->text()));
  QTest::mouseClick(leaveOut, Qt::LeftButton);
  auto request = dialog.sweepRequest();
  QVERIFY(request.ok());
  for (SensorGroup g : request->grid.groups)
    QVERIFY(!expected.contains(QString::fromUtf8(
        groupInfo(g).shortName.data(), static_cast<qsizetype>(groupInfo(g).shortName.size()))));
  QVERIFY(!note->isVisible());
}

// Guards the estimate taken from the last sweep's mean cell (60 times off for a grid of larger
// orders): with the cost model, a grid of orders up to 16 is estimated far above one of order 1
// alone (31 components against 5 per group and floor), and no stored sweep means no estimate.
void TrainingDialogTest::planEstimatesFromEachCellsOwnCost() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  smallGrid(dialog);
  QCOMPARE(dialog.plannedSeconds(), -1.0);  // nothing stored to time it by
  QVERIFY(sweepFromDialog(dialog) > 0);
  dialog.findChild<QSpinBox*>(QStringLiteral("threads"))->setValue(1);
  dialog.setGrid(QStringLiteral("1"), QStringLiteral("0.03"), QStringLiteral("1"));
  const double small = dialog.plannedSeconds();
  QVERIFY(small > 0);
  dialog.setGrid(QStringLiteral("1, 2, 4, 8, 16"), QStringLiteral("0.03"), QStringLiteral("1"));
  const double large = dialog.plannedSeconds();
  QVERIFY2(large > 4.0 * small, qPrintable(QStringLiteral("%1 vs %2").arg(large).arg(small)));
  // Full covariance costs more per row than diagonal, at the same orders.
  dialog.setFormsChecked({analysis::CovarianceForm::NodalFull});
  QVERIFY(dialog.plannedSeconds() > large);
}

// The dialog checks a sweep with the one check of a request: order 5000 gets the words
// `tactile sweep plan` gives, and nothing is planned.
void TrainingDialogTest::orderOutOfRangeGetsTheCommandLinesWords() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  smallGrid(dialog);
  dialog.setGrid(QStringLiteral("1, 5000"), QStringLiteral("0.1"), QStringLiteral("1"));
  auto request = dialog.sweepRequest();
  QVERIFY(!request.ok());
  const QString words = QString::fromStdString(request.errorText());
  QCOMPARE(words,
           QStringLiteral("model order 5000 is out of range: an order is a whole number from 1 "
                          "to 4096"));
  QVERIFY2(dialog.planLabel()->text().contains(words), qPrintable(dialog.planLabel()->text()));
  dialog.planForWorkers();
  QVERIFY2(dialog.statusLabel()->text().contains(words), qPrintable(dialog.statusLabel()->text()));
  QVERIFY(!dialog.workerCommands()->isVisible());

  QProcess cli;
  cli.start(QStringLiteral(TACTILE_CLI),
            {QStringLiteral("sweep"), QStringLiteral("plan"), QStringLiteral("--db"),
             QString::fromStdString(f.dbPath), QStringLiteral("--set"), QStringLiteral("truth"),
             QStringLiteral("--train-runs"), QStringLiteral("room1_demo,room2_demo"),
             QStringLiteral("--test-runs"), QStringLiteral("room3_demo"),
             QStringLiteral("--orders"), QStringLiteral("1,5000")});
  QVERIFY(cli.waitForFinished(60000));
  QVERIFY(cli.exitCode() != 0);
  const QString cliWords = QString::fromUtf8(cli.readAllStandardError());
  QVERIFY2(cliWords.startsWith(QStringLiteral("tactile: error: ") + words), qPrintable(cliWords));
  auto sweeps = f.workspace->sweeps();
  QVERIFY(sweeps.ok());
  QVERIFY(sweeps->empty());
}

// Plan for workers stores the sweep with every cell pending and shows the commands that fill it;
// the results window follows it while the real `tactile sweep work`, run as shown, stores cells:
// the counts, the cells and the title follow, and the window stops looking once all are done.
void TrainingDialogTest::resultsWindowFillsAsAWorkerProcessStoresCells() {
  LearningFixture f;
  TrainingDialog dialog(*f.workspace, QString::fromStdString(f.dbPath));
  smallGrid(dialog);
  QSignalSpy planned(&dialog, &TrainingDialog::sweepPlanned);
  dialog.planForWorkers();
  QCOMPARE(planned.count(), 1);
  const qint64 id = planned.first().at(0).toLongLong();
  QVERIFY(id > 0);
  const QStringList lines = dialog.workerCommands()->toPlainText().split(QLatin1Char('\n'));
  const QString work = QStringLiteral("tactile sweep work --db %1 --sweep %2 --threads 1")
                           .arg(QString::fromStdString(f.dbPath))
                           .arg(id);
  QVERIFY2(lines.contains(work), qPrintable(dialog.workerCommands()->toPlainText()));
  QVERIFY2(lines.contains(QStringLiteral("tactile sweep submit --db %1 --sweep %2 --workers 4")
                              .arg(QString::fromStdString(f.dbPath))
                              .arg(id)),
           qPrintable(dialog.workerCommands()->toPlainText()));

  gui::SweepResultsWindow window(*f.workspace, QString::fromStdString(f.dbPath));
  QVERIFY(window.showSweep(id).ok());
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  QVERIFY(window.following());
  QVERIFY(window.sweep().cells.empty());
  QVERIFY2(window.statusLabel()->text().startsWith(QStringLiteral("0 of 8 cells done")),
           qPrintable(window.statusLabel()->text()));
  QVERIFY2(window.statusLabel()->text().contains(QStringLiteral("waiting for workers")),
           qPrintable(window.statusLabel()->text()));

  // The shown command, run: first stopping after two cells, then to the end.
  QStringList args = work.split(QLatin1Char(' '));
  args.removeFirst();
  QProcess worker;
  worker.start(QStringLiteral(TACTILE_CLI),
               args + QStringList{QStringLiteral("--max-cells"), QStringLiteral("2")});
  QVERIFY(worker.waitForFinished(120000));
  QVERIFY2(worker.exitCode() == 0, worker.readAllStandardError().constData());
  QTRY_COMPARE_WITH_TIMEOUT(window.sweep().cells.size(), std::size_t{2}, 10000);
  QVERIFY(window.following());
  QVERIFY2(window.statusLabel()->text().startsWith(QStringLiteral("2 of 8 cells done")),
           qPrintable(window.statusLabel()->text()));
  QVERIFY2(window.windowTitle().contains(QStringLiteral("cancelled")) ||
               window.windowTitle().contains(QStringLiteral("running")),
           qPrintable(window.windowTitle()));

  worker.start(QStringLiteral(TACTILE_CLI), args);
  QVERIFY(worker.waitForStarted(10000));
  QTRY_COMPARE_WITH_TIMEOUT(window.sweep().cells.size(), std::size_t{8}, 120000);
  // (The process may have ended while the window was being waited for.)
  if (worker.state() != QProcess::NotRunning) QVERIFY(worker.waitForFinished(120000));
  QCOMPARE(worker.exitStatus(), QProcess::NormalExit);
  QCOMPARE(worker.exitCode(), 0);
  QTRY_VERIFY_WITH_TIMEOUT(!window.following(), 10000);
  QVERIFY2(window.statusLabel()->text().startsWith(QStringLiteral("8 of 8 cells done")),
           qPrintable(window.statusLabel()->text()));
  QVERIFY2(window.windowTitle().contains(QStringLiteral("finished")),
           qPrintable(window.windowTitle()));
  // The shown cells are the stored ones, each once.
  auto stored = f.workspace->loadSweep(id);
  QVERIFY(stored.ok());
  QCOMPARE(window.view()->findChild<QTableView*>() != nullptr, true);
  QCOMPARE(window.sweep().cells.size(), stored->cells.size());
  for (const analysis::SweepCellResult& c : stored->cells) {
    const auto shown =
        std::count_if(window.sweep().cells.begin(), window.sweep().cells.end(),
                      [&c](const analysis::SweepCellResult& s) { return s.cell == c.cell; });
    QCOMPARE(shown, std::ptrdiff_t{1});
  }
}

QTEST_MAIN(TrainingDialogTest)
#include "training_dialog_test.moc"
