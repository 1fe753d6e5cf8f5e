// The main window as an annotator uses it: keys step exactly, a drag on the timeline plus a number
// key stores a segment at once, undo takes it out of the database, and the window comes back as
// it was left (database, run, step, label set, docks, view settings).
#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <memory>

#include "app/gui/labels/label_model.h"
#include "app/gui/labels/label_panel_view.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/route_view.h"
#include "app/gui/runs/run_list_view.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"
#include "run/run_csv.h"
#include "tests/app/gui_fixture.h"

using tactile::ContactClass;
using tactile::SensorGroup;
using tactile::gui::MainWindow;
using tactile::gui::testing::GuiFixture;

namespace {

// Segments of the set stored in the database for one group.
std::size_t storedSegments(GuiFixture& fx, const std::string& set, SensorGroup group,
                           ContactClass cls) {
  auto info = fx.workspace->database().findLabelSet(set);
  if (!info) return 0;
  auto all = fx.workspace->database().segments(info->id);
  std::size_t n = 0;
  for (const auto& s : all.value()) {
    n += s.group == group && s.cls == cls ? 1 : 0;
  }
  return n;
}

}  // namespace

class MainWindowTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    QLocale::setDefault(QLocale::c());
    QVERIFY(settingsDir_.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
    QCoreApplication::setOrganizationName(QStringLiteral("TactileWorkbenchTest"));
  }

  void init() { QSettings().clear(); }

  void docksAndMenusHaveStableNames() {
    MainWindow window;
    for (const char* name : {"runsDock", "routeDock", "labelsDock"})
      QVERIFY2(window.findChild<QDockWidget*>(QLatin1String(name)) != nullptr, name);
    QStringList menus;
    for (QAction* action : window.menuBar()->actions())
      menus << action->text();
    QCOMPARE(menus, (QStringList{"&File", "&Edit", "&Go", "&View", "&Learn", "&Help"}));
  }

  void keysStepExactly() {
    GuiFixture fx(2000);
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    QVERIFY(window.openRun(QString::fromStdString(fx.runName)).ok());
    auto* s = window.session();
    QCOMPARE(s->currentStep(), 0);
    QWidget* target = window.timeline();
    // Each key press and the step it must land on, in order.
    const struct {
      Qt::Key key;
      Qt::KeyboardModifiers modifiers;
      std::int64_t expected;
    } presses[] = {
        {Qt::Key_Right, Qt::NoModifier, 1},
        {Qt::Key_Right, Qt::ShiftModifier, 11},
        {Qt::Key_Right, Qt::ControlModifier, 111},
        {Qt::Key_Left, Qt::NoModifier, 110},
        {Qt::Key_Left, Qt::ShiftModifier, 100},
        {Qt::Key_Left, Qt::ControlModifier, 0},
        {Qt::Key_End, Qt::NoModifier, 1999},
        {Qt::Key_Right, Qt::NoModifier, 1999},  // clamped
    };
    for (const auto& p : presses) {
      QTest::keyClick(target, p.key, p.modifiers);
      QCOMPARE(s->currentStep(), p.expected);
    }
    QTest::keyClick(target, Qt::Key_Home);
    QCOMPARE(s->currentStep(), 0);
    // Ten single presses are ten steps, however long the run.
    for (int i = 0; i < 10; ++i)
      QTest::keyClick(target, Qt::Key_Right);
    QCOMPARE(s->currentStep(), 10);
    // A screen is the visible range.
    window.timeline()->setVisibleRange({0, 199});
    QTest::keyClick(target, Qt::Key_PageDown);
    QCOMPARE(s->currentStep(), 210);
    // The step spin box follows and drives the cursor.
    auto* spin = window.findChild<QSpinBox*>(QStringLiteral("stepSpin"));
    QVERIFY(spin != nullptr);
    QCOMPARE(spin->value(), 210);
    spin->setValue(1234);
    QCOMPARE(s->currentStep(), 1234);
  }

  void dragAndNumberKeyStoreASegmentAndUndoRemovesIt() {
    GuiFixture fx(1000);
    MainWindow window;
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    QVERIFY(window.openRun(QString::fromStdString(fx.runName)).ok());
    QVERIFY(window.labels()->createSet("annotator").ok());
    tactile::gui::TimelineView* t = window.timeline();
    t->setVisibleRange({0, 999});
    QCoreApplication::processEvents();
    // Select the left group, then drag over steps 200..399 on the heading strip.
    window.session()->setSelectedGroup(SensorGroup::Left);
    QWidget* plot = reinterpret_cast<QWidget*>(t->plot());
    const int y = t->headingRect().center().y();
    const QPoint from = plot->mapFrom(t, QPoint(qRound(t->stepToX(200)), y));
    const QPoint to = plot->mapFrom(t, QPoint(qRound(t->stepToX(399)), y));
    QTest::mousePress(plot, Qt::LeftButton, {}, from);
    QTest::mouseMove(plot, (from + to) / 2);
    QTest::mouseMove(plot, to);
    QTest::mouseRelease(plot, Qt::LeftButton, {}, to);
    QVERIFY(window.session()->selection().has_value());
    const auto sel = *window.session()->selection();
    QVERIFY2(std::abs(sel.first - 200) <= 1 && std::abs(sel.last - 399) <= 1,
             qPrintable(QStringLiteral("%1-%2").arg(sel.first).arg(sel.last)));
    QAction* wallAction = window.findChild<QAction*>(QStringLiteral("labelAs2"));
    QVERIFY(wallAction != nullptr);
    QSignalSpy fired(wallAction, &QAction::triggered);
    QTest::keyClick(t, Qt::Key_2);  // Wall
    QCOMPARE(fired.count(), 1);
    QVERIFY2(window.lastError().isEmpty(), qPrintable(window.lastError()));
    QCOMPARE(storedSegments(fx, "annotator", SensorGroup::Left, ContactClass::Wall),
             std::size_t{1});
    QCOMPARE(*window.labels()->classAt(SensorGroup::Left, 300), ContactClass::Wall);
    QTest::keyClick(t, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(storedSegments(fx, "annotator", SensorGroup::Left, ContactClass::Wall),
             std::size_t{0});
    QTest::keyClick(t, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(storedSegments(fx, "annotator", SensorGroup::Left, ContactClass::Wall),
             std::size_t{1});
    // Checked groups: one key press labels both, one undo takes both back.
    window.labelPanel()->setGroupsMode(tactile::gui::LabelPanelView::GroupsMode::Checked);
    window.labelPanel()->setGroupChecked(SensorGroup::Right, true);
    window.labelPanel()->setGroupChecked(SensorGroup::Back, true);
    QTest::keyClick(t, Qt::Key_3);  // Corner
    QCOMPARE(storedSegments(fx, "annotator", SensorGroup::Right, ContactClass::Corner),
             std::size_t{1});
    QCOMPARE(storedSegments(fx, "annotator", SensorGroup::Back, ContactClass::Corner),
             std::size_t{1});
    QTest::keyClick(t, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(storedSegments(fx, "annotator", SensorGroup::Right, ContactClass::Corner),
             std::size_t{0});
    QCOMPARE(storedSegments(fx, "annotator", SensorGroup::Back, ContactClass::Corner),
             std::size_t{0});
  }

  void clickOnTheTimelineSeeksToTheNearestStep() {
    GuiFixture fx(500);
    MainWindow window;
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    tactile::gui::TimelineView* t = window.timeline();
    t->setVisibleRange({0, 99});
    QCoreApplication::processEvents();
    QWidget* plot = reinterpret_cast<QWidget*>(t->plot());
    for (int step : {3, 50, 97}) {
      // A little off the step's centre still lands on it.
      const QPoint at =
          plot->mapFrom(t, QPoint(qRound(t->stepToX(step) + 0.3 * (t->stepToX(1) - t->stepToX(0))),
                                  t->headingRect().center().y()));
      QTest::mouseClick(plot, Qt::LeftButton, {}, at);
      QCOMPARE(window.session()->currentStep(), step);
    }
  }

  void comesBackAsItWasLeft() {
    GuiFixture fx(800);
    {
      MainWindow window;
      window.show();
      QVERIFY(QTest::qWaitForWindowExposed(&window));
      QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
      QVERIFY(window.labels()->createSet("kept").ok());
      window.session()->setCurrentStep(321);
      window.timeline()->setChannel(tactile::gui::TimelineView::Channel::Shear);
      window.route()->setWholeScene(false);
      window.labelPanel()->setGroupsMode(tactile::gui::LabelPanelView::GroupsMode::Contacting);
      window.resize(1111, 777);
      window.findChild<QDockWidget*>(QStringLiteral("routeDock"))->hide();
      window.close();
    }
    MainWindow again;
    QVERIFY(again.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QCOMPARE(again.size(), QSize(1111, 777));
    QCOMPARE(again.session()->info().name, fx.runName);
    QCOMPARE(again.session()->currentStep(), 321);
    QCOMPARE(again.labels()->setName(), std::string("kept"));
    QCOMPARE(again.timeline()->channel(), tactile::gui::TimelineView::Channel::Shear);
    QVERIFY(!again.route()->wholeScene());
    QCOMPARE(again.labelPanel()->groupsMode(),
             tactile::gui::LabelPanelView::GroupsMode::Contacting);
    QVERIFY(again.findChild<QDockWidget*>(QStringLiteral("routeDock"))->isHidden());
  }

  void importedRunFilesAppearInTheRunList() {
    GuiFixture fx(300);
    // Two run files: one good, one with a broken line.
    auto run = fx.workspace->loadRun(fx.runName);
    QVERIFY(run.ok());
    run->setMeta("subject", "another annotator");  // not a copy of the stored run
    const QString good = fx.dir.filePath(QStringLiteral("extra.csv"));
    QVERIFY(tactile::writeRunCsv(run.value(), good.toStdString()).ok());
    const QString bad = fx.dir.filePath(QStringLiteral("broken.csv"));
    {
      QFile f(bad);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("# format: tactile-run 1\nstep,x\n1,2,3\n");
    }
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    auto* table = window.runList()->table();
    QCOMPARE(table->model()->rowCount(), 1);
    window.importRuns({good, bad});
    QTRY_COMPARE_WITH_TIMEOUT(table->model()->rowCount(), 2, 10000);
    // The broken file is reported with its name, and the good one was kept.
    QTRY_VERIFY(window.lastError().contains(QStringLiteral("broken.csv")));
    QVERIFY(fx.workspace->database().findRun("extra").ok());
    // The filter narrows the list.
    window.runList()->setFilterText(QStringLiteral("extra"));
    QCOMPARE(table->model()->rowCount(), 1);
  }

  // Regression: the last run was remembered only on a clean close, so a killed session came back
  // to the first run.
  void theRunOpenedIsRememberedWithoutAClose() {
    GuiFixture fx(200);
    auto run = fx.workspace->loadRun(fx.runName);
    QVERIFY(run.ok());
    run->setMeta("subject", "second");
    QCOMPARE(fx.workspace->database().importRun(run.value(), "zz_second").status,
             tactile::storage::ImportStatus::Imported);
    {
      MainWindow window;
      QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
      QCOMPARE(window.session()->info().name, fx.runName);  // the first by name
      QVERIFY(window.openRun(QStringLiteral("zz_second")).ok());
      QVERIFY(window.labels()->createSet("later").ok());
      // No close(): the window is destroyed as if the session were killed.
    }
    MainWindow again;
    QVERIFY(again.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    QCOMPARE(again.session()->info().name, std::string("zz_second"));
    QCOMPARE(again.labels()->setName(), std::string("later"));
  }

  void droppingADatabaseOpensItAndDroppingRunFilesImportsThem() {
    GuiFixture fx(150);
    auto run = fx.workspace->loadRun(fx.runName);
    QVERIFY(run.ok());
    run->setMeta("subject", "dropped");
    const QString csv = fx.dir.filePath(QStringLiteral("dropped.csv"));
    QVERIFY(tactile::writeRunCsv(run.value(), csv.toStdString()).ok());
    // The event handler as the drag and drop machinery calls it.
    struct DropTarget : MainWindow {
      using MainWindow::dropEvent;
    } window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto drop = [&window](const QString& file) {
      QMimeData mime;
      mime.setUrls({QUrl::fromLocalFile(file)});
      QDropEvent event(QPointF(100, 100), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
      window.dropEvent(&event);
    };
    drop(QString::fromStdString(fx.dbPath));
    QVERIFY2(window.lastError().isEmpty(), qPrintable(window.lastError()));
    QCOMPARE(window.databasePath(),
             QFileInfo(QString::fromStdString(fx.dbPath)).absoluteFilePath());
    QCOMPARE(window.session()->info().name, fx.runName);
    drop(csv);
    QTRY_COMPARE_WITH_TIMEOUT(window.runList()->table()->model()->rowCount(), 2, 10000);
    QVERIFY(fx.workspace->database().findRun("dropped").ok());
  }

  void droppingAFolderImportsItsCsvFilesAndADatabaseWithRunsOpensItFirst() {
    GuiFixture fx(120);
    auto run = fx.workspace->loadRun(fx.runName);
    QVERIFY(run.ok());
    // A folder with two run files and a file that is not one (ignored by the folder rule).
    QDir(fx.dir.path()).mkpath(QStringLiteral("runs"));
    const QString folder = fx.dir.filePath(QStringLiteral("runs"));
    // Each file differs in its metadata, so none is skipped as a copy of another.
    for (const char* name : {"folder_a", "folder_b"}) {
      run->setMeta("subject", name);
      QVERIFY(tactile::writeRunCsv(run.value(), (folder + "/" + name + ".csv").toStdString()).ok());
    }
    QFile notes(folder + QStringLiteral("/notes.txt"));
    QVERIFY(notes.open(QIODevice::WriteOnly));
    notes.write("not a run");
    notes.close();
    run->setMeta("subject", "single");
    const QString single = fx.dir.filePath(QStringLiteral("single.csv"));
    QVERIFY(tactile::writeRunCsv(run.value(), single.toStdString()).ok());

    struct DropTarget : MainWindow {
      using MainWindow::dragEnterEvent;
      using MainWindow::dropEvent;
    } window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto mimeFor = [](const QStringList& files) {
      auto* mime = new QMimeData;
      QList<QUrl> urls;
      for (const QString& f : files)
        urls << QUrl::fromLocalFile(f);
      mime->setUrls(urls);
      return mime;
    };
    auto accepts = [&](const QStringList& files) {
      std::unique_ptr<QMimeData> mime(mimeFor(files));
      QDragEnterEvent event(QPoint(100, 100), Qt::CopyAction, mime.get(), Qt::LeftButton,
                            Qt::NoModifier);
      event.setAccepted(false);
      window.dragEnterEvent(&event);
      return event.isAccepted();
    };
    auto drop = [&](const QStringList& files) {
      std::unique_ptr<QMimeData> mime(mimeFor(files));
      QDropEvent event(QPointF(100, 100), Qt::CopyAction, mime.get(), Qt::LeftButton,
                       Qt::NoModifier);
      window.dropEvent(&event);
    };
    // Only what the window can use is accepted while dragging.
    QVERIFY(!accepts({folder + QStringLiteral("/notes.txt")}));
    QVERIFY(accepts({folder}));
    QVERIFY(accepts({QString::fromStdString(fx.dbPath)}));

    // A database and a run file in one drop: the database opens and the run goes into it.
    drop({single, QString::fromStdString(fx.dbPath)});
    QCOMPARE(window.databasePath(),
             QFileInfo(QString::fromStdString(fx.dbPath)).absoluteFilePath());
    QTRY_COMPARE_WITH_TIMEOUT(window.runList()->table()->model()->rowCount(), 2, 10000);
    QVERIFY(fx.workspace->database().findRun("single").ok());

    // A folder: both of its run files, nothing else.
    drop({folder});
    QTRY_COMPARE_WITH_TIMEOUT(window.runList()->table()->model()->rowCount(), 4, 10000);
    QVERIFY(fx.workspace->database().findRun("folder_a").ok());
    QVERIFY(fx.workspace->database().findRun("folder_b").ok());
    QVERIFY2(window.lastError().isEmpty(), qPrintable(window.lastError()));

    // A file that is neither is reported and changes nothing.
    drop({folder + QStringLiteral("/notes.txt")});
    QVERIFY(window.lastError().contains(QStringLiteral("notes.txt")));
    QCOMPARE(window.runList()->table()->model()->rowCount(), 4);
  }

  void badDatabaseIsAnErrorAndChangesNothing() {
    MainWindow window;
    QTemporaryDir dir;
    const QString missing = dir.filePath(QStringLiteral("absent.db"));
    QVERIFY(!window.openDatabase(missing).ok());
    QVERIFY(!QFileInfo::exists(missing));
    QVERIFY(window.databasePath().isEmpty());
  }

 private:
  QTemporaryDir settingsDir_;
};

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
