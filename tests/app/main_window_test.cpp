// The main window as an annotator uses it: keys step exactly, a drag on the timeline plus a number
// key stores a segment at once, undo takes it out of the database, and the window comes back as
// it was left (database, run, step, label set, docks, view settings).
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProcess>
#include <QRadioButton>
#include <QRegularExpression>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextFragment>
#include <QTextImageFormat>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest>

#include <memory>

#include "app/gui/common/settings_keys.h"
#include "app/gui/common/shortcuts.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/labels/label_panel_view.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/route_view.h"
#include "app/gui/runs/run_list_view.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"
#include "app/gui/user_guide_window.h"
#include "run/run_csv.h"
#include "tests/app/gui_fixture.h"

#include <signal.h>
#include <sys/types.h>
#include <cstdio>
#include <map>
#include <set>

using tactile::ContactClass;
using tactile::SensorGroup;
using tactile::gui::MainWindow;
using tactile::gui::UserGuideWindow;
using tactile::gui::testing::GuiFixture;

namespace {

// Segments of the set stored in the database for one group.
std::size_t storedSegments(GuiFixture& fx, const std::string& set, SensorGroup group,
                           ContactClass cls) {
  auto info = fx.workspace->labelStore().find(set);
  if (!info) return 0;
  auto all = fx.workspace->labelStore().segments(info->id);
  std::size_t n = 0;
  for (const auto& s : all.value()) {
    n += s.group == group && s.cls == cls ? 1 : 0;
  }
  return n;
}

// The environment that makes this program the session the kill test kills (see main()).
constexpr const char* kChildDbVariable = "TACTILE_TEST_KILLED_SESSION_DB";
constexpr const char* kChildSettingsVariable = "TACTILE_TEST_KILLED_SESSION_SETTINGS";

void useTestSettings(const QString& dir) {
  QSettings::setDefaultFormat(QSettings::IniFormat);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir);
  QCoreApplication::setOrganizationName(QStringLiteral("TactileWorkbenchTest"));
}

// The session to be killed: opens the database, changes the cursor, the "Apply to" mode and a
// checked group as a user would (keys and clicks), says "ready" and waits to be killed.
int runKilledSession(int argc, char** argv) {
  QApplication app(argc, argv);
  useTestSettings(qEnvironmentVariable(kChildSettingsVariable));
  MainWindow window;
  if (!window.openDatabase(qEnvironmentVariable(kChildDbVariable)).ok()) return 3;
  window.show();
  if (!QTest::qWaitForWindowExposed(&window)) return 4;
  QWidget* focus = QApplication::focusWidget();
  if (focus == nullptr) return 5;
  QTest::keyClick(focus, Qt::Key_End);
  QTest::keyClick(focus, Qt::Key_Left);
  QTest::keyClick(focus, Qt::Key_Left, Qt::ShiftModifier);  // the last step - 11
  auto* contacting = window.findChild<QRadioButton*>(QStringLiteral("groupsMode2"));
  auto* back = window.findChild<QCheckBox*>(QStringLiteral("groupCheck_B"));
  if (contacting == nullptr || back == nullptr) return 6;
  // On the indicator: a button takes clicks on its indicator and text only.
  QTest::mouseClick(contacting, Qt::LeftButton, {}, QPoint(8, contacting->height() / 2));
  QTest::mouseClick(back, Qt::LeftButton, {}, QPoint(8, back->height() / 2));
  if (!contacting->isChecked() || !back->isChecked()) return 7;
  std::printf("ready %lld\n", static_cast<long long>(window.session()->currentStep()));
  std::fflush(stdout);
  return QApplication::exec();
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
    // Undo and redo say what they did (they once said nothing).
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Undone: Label steps")),
             qPrintable(window.statusBar()->currentMessage()));
    QTest::keyClick(t, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(storedSegments(fx, "annotator", SensorGroup::Left, ContactClass::Wall),
             std::size_t{1});
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Redone: Label steps")),
             qPrintable(window.statusBar()->currentMessage()));
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
    QSize left;
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
      left = window.size();  // at least the window's minimum size
      window.findChild<QDockWidget*>(QStringLiteral("routeDock"))->hide();
      window.close();
    }
    MainWindow again;
    QVERIFY(again.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    // As it was left, within the screen (a restored geometry never comes back taller or wider
    // than the screen it lands on).
    const QSize screen = again.screen()->availableGeometry().size();
    QCOMPARE(again.size(), left.boundedTo(screen));
    QCOMPARE(again.size().width(), std::min(1111, screen.width()));
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
    QVERIFY(fx.workspace->runStore().find("extra").ok());
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
    QCOMPARE(fx.workspace->runStore().importRun(run.value(), "zz_second").status,
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
    QVERIFY(fx.workspace->runStore().find("dropped").ok());
  }

  // A database restored beside a write-ahead log that does not belong to it: nothing opens, and
  // the whole message (which log, what to do) is shown, not only a cut status line.
  void openingADatabaseWithALogThatDoesNotBelongSaysWhatToDo() {
    GuiFixture fx(120);
    auto run = fx.workspace->loadRun(fx.runName);
    QVERIFY(run.ok());
    const std::string live = fx.dir.filePath(QStringLiteral("live.db")).toStdString();
    const std::string restored = fx.dir.filePath(QStringLiteral("restored.db")).toStdString();
    auto importAs = [&](const std::string& name) {
      auto db = tactile::storage::RunDatabase::open(live, tactile::storage::OpenMode::Create);
      QVERIFY2(db.ok(), db.ok() ? "" : db.errorText().c_str());
      run->setMeta("subject", name);
      QCOMPARE(db.value()->runs().importRun(run.value(), name).status,
               tactile::storage::ImportStatus::Imported);
    };
    importAs("first");
    QVERIFY(QFile::copy(QString::fromStdString(live), QString::fromStdString(restored)));
    importAs("second");
    // Another process holds a read transaction, so the next import's commit stays in the log.
    QProcess holder;
    holder.start(QStringLiteral("sqlite3"), {QString::fromStdString(live)});
    QVERIFY(holder.waitForStarted(10000));
    holder.write("BEGIN; SELECT count(*) FROM runs;\n");
    QTest::qWait(500);
    importAs("third");
    QVERIFY(QFile::copy(QString::fromStdString(live + "-wal"),
                        QString::fromStdString(restored + "-wal")));
    holder.kill();
    holder.waitForFinished(10000);

    struct DropTarget : MainWindow {
      using MainWindow::dropEvent;
    } window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(QString::fromStdString(restored))});
    QDropEvent event(QPointF(100, 100), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    window.dropEvent(&event);
    QVERIFY2(window.lastError().contains(QStringLiteral("restored.db-wal does not belong")),
             qPrintable(window.lastError()));
    QVERIFY(window.databasePath().isEmpty());
    auto* box = window.findChild<QMessageBox*>(QStringLiteral("openError"));
    QVERIFY(box != nullptr);
    QTRY_VERIFY(box->isVisible());
    QVERIFY(box->text().contains(QStringLiteral("move")));
    box->accept();
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
    QVERIFY(fx.workspace->runStore().find("single").ok());

    // A folder: both of its run files, nothing else.
    drop({folder});
    QTRY_COMPARE_WITH_TIMEOUT(window.runList()->table()->model()->rowCount(), 4, 10000);
    QVERIFY(fx.workspace->runStore().find("folder_a").ok());
    QVERIFY(fx.workspace->runStore().find("folder_b").ok());
    QVERIFY2(window.lastError().isEmpty(), qPrintable(window.lastError()));

    // A file that is neither is reported and changes nothing.
    drop({folder + QStringLiteral("/notes.txt")});
    QVERIFY(window.lastError().contains(QStringLiteral("notes.txt")));
    QCOMPARE(window.runList()->table()->model()->rowCount(), 4);
  }

  // Regression: at start the runs filter had the focus, so Right, Left and the class keys went
  // into it and Ctrl+Z did nothing to the labels.
  void keysWorkWhateverHasTheFocusExceptATextField() {
    GuiFixture fx(1000);
    QVERIFY(fx.workspace->labelStore().create("mine").ok());
    MainWindow window;
    QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    auto* s = window.session();
    QCOMPARE(s->currentStep(), 0);
    QCOMPARE(window.labels()->setName(), std::string("mine"));
    const SensorGroup group = s->selectedGroup();
    // Right after start, whatever took the focus: the keys step and label.
    QWidget* focus = QApplication::focusWidget();
    QVERIFY(focus != nullptr);
    QVERIFY2(qobject_cast<QLineEdit*>(focus) == nullptr, focus->metaObject()->className());
    QTest::keyClick(focus, Qt::Key_Right);
    QCOMPARE(s->currentStep(), 1);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_2);
    QCOMPARE(window.labels()->classAt(group, 1), std::optional(ContactClass::Wall));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(!window.labels()->classAt(group, 1).has_value());
    auto* filter = window.findChild<QLineEdit*>(QStringLiteral("runFilter"));
    QVERIFY(filter != nullptr);
    QVERIFY(filter->text().isEmpty());
    // A table or a slider with the focus leaves the arrows and digits to the window.
    QWidget* table = window.runList()->table();
    QWidget* slider = window.findChild<QSlider*>(QStringLiteral("stepSlider"));
    for (QWidget* w : {table, slider}) {
      w->setFocus(Qt::MouseFocusReason);
      QCOMPARE(QApplication::focusWidget(), w);
      const std::int64_t before = s->currentStep();
      QTest::keyClick(w, Qt::Key_Right);
      QCOMPARE(s->currentStep(), before + 1);
      QTest::keyClick(w, Qt::Key_Left, Qt::ShiftModifier);
      QCOMPARE(s->currentStep(), std::max<std::int64_t>(0, before - 9));
      QTest::keyClick(w, Qt::Key_Right, Qt::ShiftModifier);
    }
    // A text field being typed in keeps its keys, and Escape leaves it for the timelines.
    const std::int64_t before = s->currentStep();
    filter->setFocus(Qt::MouseFocusReason);
    QTest::keyClicks(filter, QStringLiteral("room2"));
    QTest::keyClick(filter, Qt::Key_Left);
    QTest::keyClick(filter, Qt::Key_Backspace);
    QCOMPARE(filter->text(), QStringLiteral("roo2"));  // the cursor moved before the 2: "m" went
    QCOMPARE(s->currentStep(), before);
    QVERIFY(!window.labels()->classAt(group, before).has_value());
    QTest::keyClick(filter, Qt::Key_Escape);
    QVERIFY(!filter->hasFocus());
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(window.timeline()));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Right);
    QCOMPARE(s->currentStep(), before + 1);
  }

  // Regression: the cursor and "Apply to" were saved only on a clean quit; after kill -9 they
  // came back reset.
  void settingsSurviveAKilledSession() {
    GuiFixture fx(700);
    QProcess child;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QLatin1String(kChildDbVariable), QString::fromStdString(fx.dbPath));
    env.insert(QLatin1String(kChildSettingsVariable), settingsDir_.path());
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    child.setProcessEnvironment(env);
    child.start(QCoreApplication::applicationFilePath(), {});
    QVERIFY(child.waitForStarted());
    QByteArray out;
    QTRY_VERIFY_WITH_TIMEOUT((out += child.readAllStandardOutput()).contains('\n'), 20000);
    QVERIFY2(out.startsWith("ready "), out.constData());
    const qint64 step = out.mid(6).trimmed().toLongLong();
    QCOMPARE(step, 700 - 1 - 11);
    QTest::qWait(1500);  // the settings are written shortly after they change
    QCOMPARE(child.state(), QProcess::Running);
    ::kill(static_cast<pid_t>(child.processId()), SIGKILL);
    QVERIFY(child.waitForFinished());
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);
    MainWindow again;
    QVERIFY(again.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    QCOMPARE(again.session()->currentStep(), step);
    QCOMPARE(again.labelPanel()->groupsMode(),
             tactile::gui::LabelPanelView::GroupsMode::Contacting);
    QCOMPARE(again.labelPanel()->checkedGroups(), std::vector<SensorGroup>{SensorGroup::Back});
  }

  // Help > Keyboard Shortcuts lists exactly the shortcuts the window binds, and the Edit menu
  // names the classes.
  void theShortcutListEqualsTheBoundShortcuts() {
    MainWindow window;
    std::map<QString, QList<QKeySequence>> bound;
    std::set<QString> keysSeen;
    for (QAction* a : window.findChildren<QAction*>()) {
      if (a->shortcuts().isEmpty()) continue;
      QVERIFY2(!bound.count(a->objectName()), qPrintable(a->objectName()));
      bound[a->objectName()] = a->shortcuts();
      for (const QKeySequence& k : a->shortcuts()) {
        // No key does two things.
        QVERIFY2(keysSeen.insert(k.toString()).second, qPrintable(k.toString()));
      }
    }
    std::map<QString, QList<QKeySequence>> listed;
    for (const tactile::gui::ShortcutEntry& e : tactile::gui::shortcutTable())
      listed[e.id] = e.keys;
    for (const auto& [id, keys] : bound)
      QVERIFY2(listed.count(id) == 1, qPrintable(id));
    QCOMPARE(bound.size(), listed.size());
    for (const auto& [id, keys] : listed) {
      QVERIFY2(bound.count(id) == 1, qPrintable(id));
      QCOMPARE(bound[id], keys);
    }
    // The dialog shows every entry's keys and text.
    window.showKeyboardShortcuts();
    auto* text = window.findChild<QTextBrowser*>(QStringLiteral("shortcutsText"));
    QVERIFY(text != nullptr);
    const QString shown = text->toPlainText();
    for (const tactile::gui::ShortcutEntry& e : tactile::gui::shortcutTable()) {
      QVERIFY2(shown.contains(e.text), qPrintable(e.text));
      for (const QKeySequence& k : e.keys)
        QVERIFY2(shown.contains(k.toString(QKeySequence::NativeText)), qPrintable(k.toString()));
    }
    QCOMPARE(window.findChild<QAction*>(QStringLiteral("labelAs2"))->text(),
             QStringLiteral("Label as Wall"));
    QCOMPARE(window.findChild<QAction*>(QStringLiteral("labelAs4"))->text(),
             QStringLiteral("Label as Leaving wall"));
  }

  // Help > User Guide shows the embedded guide, pictures included, with no docs/ folder needed.
  void helpShowsTheEmbeddedUserGuide() {
    MainWindow window;
    QAction* entry = nullptr;
    for (QAction* a : window.findChildren<QAction*>())
      if (a->text() == QStringLiteral("&User Guide")) entry = a;
    QVERIFY(entry != nullptr);
    entry->trigger();
    auto* text = window.findChild<QTextBrowser*>(QStringLiteral("userGuideText"));
    QVERIFY(text != nullptr);
    QVERIFY(text->toPlainText().contains(QStringLiteral("User guide")));
    QVERIFY(text->toPlainText().contains(QStringLiteral("Ctrl+Z")));
    // Every picture the guide names is embedded and loads as an image.
    QFile guide(QStringLiteral(":/guide/user-guide.md"));
    QVERIFY(guide.open(QIODevice::ReadOnly));
    const QString markdown = QString::fromUtf8(guide.readAll());
    static const QRegularExpression picture(QStringLiteral("\\]\\((images/[^)]+\\.png)\\)"));
    int pictures = 0;
    for (auto it = picture.globalMatch(markdown); it.hasNext(); ++pictures) {
      const QString path = QStringLiteral(":/guide/") + it.next().captured(1);
      QVERIFY2(!QImage(path).isNull(), qPrintable(path));
    }
    QVERIFY(pictures >= 3);
  }

  // Guards the guide's links that opened a blank page ("No document for qrc:/guide/...") with no
  // way back, and its pictures cut off at the viewer's edge: every link of the guide names an
  // embedded page or picture, a page link opens that page, Back and Forward walk the history, and
  // no picture is drawn wider than the viewer.
  void userGuideLinksResolveAndBackReturns() {
    UserGuideWindow guide;
    guide.resize(980, 700);
    guide.show();
    QVERIFY(QTest::qWaitForWindowExposed(&guide));
    QFile file(QStringLiteral(":/guide/user-guide.md"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString markdown = QString::fromUtf8(file.readAll());
    static const QRegularExpression link(QStringLiteral("\\]\\(([^)\\s]+)\\)"));
    const QUrl base(UserGuideWindow::guideUrl());
    QStringList pages;
    int links = 0;
    for (auto it = link.globalMatch(markdown); it.hasNext(); ++links) {
      const QUrl target(it.next().captured(1));
      if (!target.isRelative()) continue;  // web addresses open outside
      QVERIFY2(!UserGuideWindow::embeddedTarget(base, target).isEmpty(),
               qPrintable(target.toString()));
      if (target.path().endsWith(QStringLiteral(".md"))) pages << target.toString();
    }
    QVERIFY(links >= 10);
    QVERIFY(pages.size() >= 3);
    QVERIFY(!guide.backButton()->isEnabled());
    for (const QString& page : pages) {
      guide.follow(QUrl(page));
      QCOMPARE(guide.browser()->source().fileName(), QUrl(page).fileName());
      QVERIFY2(guide.browser()->toPlainText().size() > 200, qPrintable(page));
      QVERIFY(guide.backButton()->isEnabled());
      QTest::mouseClick(guide.backButton(), Qt::LeftButton);
      QCOMPARE(guide.browser()->source(), base);
      QVERIFY(guide.forwardButton()->isEnabled());
      QTest::mouseClick(guide.forwardButton(), Qt::LeftButton);
      QCOMPARE(guide.browser()->source().fileName(), QUrl(page).fileName());
      QTest::mouseClick(guide.backButton(), Qt::LeftButton);
    }
    // Pictures: none wider than the viewer.
    const int viewer = guide.browser()->viewport()->width();
    int images = 0;
    for (QTextBlock b = guide.browser()->document()->begin(); b.isValid(); b = b.next()) {
      for (auto it = b.begin(); !it.atEnd(); ++it) {
        if (!it.fragment().charFormat().isImageFormat()) continue;
        ++images;
        const QTextImageFormat f = it.fragment().charFormat().toImageFormat();
        QVERIFY2(
            f.width() > 0 && f.width() <= viewer,
            qPrintable(QStringLiteral("%1: %2 > %3").arg(f.name()).arg(f.width()).arg(viewer)));
      }
    }
    QVERIFY(images >= 3);
  }

  // The annotator's name from the preferences is stored on every segment and exported.
  void annotatorIsStoredOnSegmentsAndExported() {
    GuiFixture fx(300);
    QVERIFY(fx.workspace->labelStore().create("named").ok());
    QSettings().setValue(tactile::gui::settings_keys::kAnnotator, QStringLiteral("ada"));
    MainWindow window;
    QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.session()->setSelection(10, 20);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_3);
    auto set = fx.workspace->labelStore().find("named");
    QVERIFY(set.ok());
    auto stored = fx.workspace->labelStore().segments(set->id);
    QVERIFY(stored.ok());
    QCOMPARE(stored->size(), std::size_t{1});
    QCOMPARE(stored->front().annotator, std::string("ada"));
    const QString csv = fx.dir.filePath(QStringLiteral("named.csv"));
    QVERIFY(window.labels()->exportFile(csv.toStdString()).ok());
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(f.readAll());
    QVERIFY2(text.contains(QStringLiteral("annotator")) &&
                 text.contains(QStringLiteral(",10,20,Corner,ada")),
             qPrintable(text));
    // A new name from the preferences applies to the next edit.
    QSettings().setValue(tactile::gui::settings_keys::kAnnotator, QStringLiteral("bob"));
    window.applyPreferences();
    window.session()->setSelection(30, 40);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_2);
    stored = fx.workspace->labelStore().segments(set->id);
    QCOMPARE(stored->back().annotator, std::string("bob"));
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

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsSet(kChildDbVariable)) return runKilledSession(argc, argv);
  QApplication app(argc, argv);
  app.setAttribute(Qt::AA_Use96Dpi, true);
  MainWindowTest test;
  QTEST_SET_MAIN_SOURCE_PATH
  return QTest::qExec(&test, argc, argv);
}
#include "main_window_test.moc"
