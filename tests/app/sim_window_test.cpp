// The simulator window: the key table gives the documented commands, M switches the picture
// (never to the scene in experiment mode), the collision light turns red on a blocked step, Give
// Up records `gave-up`, a run driven in the window equals `tactile simulate` replaying its
// commands, and a window killed mid-run leaves the steps so far in the database. Autonomous mode:
// Play lets the navigator drive and records its strategy and status as `tactile navigate` does,
// Step takes exactly one step, Pause stops, and a killed autonomous run keeps those columns.
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <signal.h>

#include <chrono>
#include <thread>

#include "app/gui/runs/navigator_track_model.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/sim/drive_keys.h"
#include "app/gui/sim/experiment_panel.h"
#include "app/gui/sim/sim_window.h"
#include "app/gui/sim/status_picture_view.h"
#include "nav/navigate.h"
#include "nav/navigator.h"
#include "run/run_csv.h"
#include "sim/recorder.h"
#include "sim/scene_source.h"
#include "sim/simulator.h"
#include "sim/start_goal.h"
#include "sim/world.h"
#include "tests/run_compare.h"
#include "workspace/workspace.h"

using namespace tactile;
using tactile::gui::SimMode;
using tactile::gui::SimWindow;

namespace {

std::unique_ptr<workspace::Workspace> openWorkspace(const QString& path) {
  auto opened = workspace::Workspace::open(path.toStdString());
  if (!opened) qFatal("%s", opened.errorText().c_str());
  return std::move(opened.value());
}

// A run file whose only use is its commands: `steps` steps of (v, omega), sensors zero.
void writeCommandFile(const QString& path, std::size_t steps, double v, double omega) {
  RunData run;
  run.metadata = {{"format", "tactile-run 1"}};
  const std::array<double, kValuesPerStep> zeros{};
  for (std::size_t k = 0; k < steps; ++k)
    run.appendStep(0, 0, 0, v, omega, false, zeros.data(), nullptr);
  const Status written = writeRunCsv(run, path.toStdString());
  if (!written) qFatal("%s", written.errorText().c_str());
}

// `tactile navigate`'s run on the chapter-5 scene from seed `seed`'s start with at most
// `maxSteps` steps: what a window's autonomous run must equal.
Result<nav::NavigateResult> navigateChapter5(nav::StatusSource source, std::uint64_t seed,
                                             std::size_t maxSteps) {
  auto scene = sim::loadScene("chapter5");
  if (!scene) return scene.error();
  auto world = std::make_shared<const sim::World>(std::move(scene.value()));
  nav::NavigatorConfig config;
  config.source = source;
  nav::NavigateOptions options;
  options.maxSteps = maxSteps;
  options.seed = seed;
  return nav::navigate(world, "chapter5", nav::drawStart(world, seed), world->scene().goal, config,
                       options, true);
}

// The real workbench's process, on its own settings (not the user's) and offscreen.
void isolateWorkbench(QProcess& child, const QTemporaryDir& dir) {
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
  env.insert(QStringLiteral("HOME"), dir.path());  // its own settings
  env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
  child.setProcessEnvironment(env);
}

// Starts the real workbench on `db` with `args`, waits until the database holds at least
// `minSteps` steps of one run, then kills it with SIGKILL. Returns the steps seen before the kill
// (fewer than `minSteps` when the window stored too few within 30 s; -1 when the process failed).
std::int64_t killWorkbenchAfterSteps(const QTemporaryDir& dir, const QString& db,
                                     const QStringList& args, std::int64_t minSteps) {
  QProcess child;
  isolateWorkbench(child, dir);
  child.start(QStringLiteral(TACTILE_WORKBENCH), QStringList{QStringLiteral("--db"), db} + args);
  if (!child.waitForStarted(10000)) return -1;
  auto ws = openWorkspace(db);
  std::int64_t seen = 0;
  for (int i = 0; i < 300 && seen < minSteps; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    auto runs = ws->runStore().list();
    if (runs.ok() && !runs->empty()) seen = runs->front().stepCount;
  }
  if (::kill(static_cast<pid_t>(child.processId()), SIGKILL) != 0) return -1;
  if (!child.waitForFinished(10000) || child.exitStatus() != QProcess::CrashExit) return -1;
  return seen;
}

}  // namespace

class SimWindowTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { QLocale::setDefault(QLocale::c()); }

  // Guards Data >> making the window 1182 px tall: with the data panel open the window asks for
  // no more than a 1366x768 screen has, and the buttons stay where they were when the state text
  // changes.
  void dataPanelFitsASmallScreenAndButtonsStayPut() {
    QTemporaryDir dir;
    SimWindow window(dir.filePath(QStringLiteral("d.db")));
    window.setStepsPerSecond(1);
    window.resize(1366, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.startRun().ok());
    window.setDataPanelShown(true);
    QTest::qWait(20);
    QVERIFY2(window.minimumSizeHint().height() <= 768 - 70,
             qPrintable(QString::number(window.minimumSizeHint().height())));
    auto* giveUp = window.findChild<QPushButton*>(QStringLiteral("giveUpButton"));
    auto* state = window.findChild<QLabel*>(QStringLiteral("stateLabel"));
    QVERIFY(giveUp != nullptr && state != nullptr);
    const QPoint before = giveUp->mapTo(&window, QPoint(0, 0));
    state->setText(QStringLiteral("one\ntwo\nthree\nfour\nfive\nsix"));
    QTest::qWait(20);
    QCOMPARE(giveUp->mapTo(&window, QPoint(0, 0)), before);
  }

  void keysGiveTheDocumentedCommands() {
    QTemporaryDir dir;
    SimWindow window(dir.filePath(QStringLiteral("k.db")));
    window.setStepsPerSecond(1);  // the clock stays out of the way
    QVERIFY(window.startRun().ok());
    gui::SimSession* s = window.session();
    QVERIFY(s->isPaused());
    // From (20, 0.1): every key's documented effect.
    struct Case {
      int key;
      double v;
      double omega;
    };
    const Case cases[] = {
        {Qt::Key_Up, 40, 0.1}, {Qt::Key_Down, 0, 0.1},  {Qt::Key_W, 25, 0.1},
        {Qt::Key_S, 15, 0.1},  {Qt::Key_Left, 20, 0.3}, {Qt::Key_Right, 20, -0.1},
        {Qt::Key_A, 20, 0.15}, {Qt::Key_D, 20, 0.05},   {Qt::Key_Space, 0, 0},
    };
    for (const Case& c : cases) {
      s->setCommand({20, 0.1});
      const std::size_t before = s->stepCount();
      QTest::keyClick(&window, static_cast<Qt::Key>(c.key));
      QCOMPARE(s->command().v, c.v);
      QCOMPARE(s->command().omega, c.omega);
      // The key moved the robot at once (one step taken before the key event returned), and
      // the table agrees.
      QCOMPARE(s->stepCount(), before + 1);
      const gui::SimKey* k = gui::simKeyFor(c.key);
      QVERIFY(k != nullptr);
      const sim::Command fromTable = gui::applyDriveAction(k->action, {20, 0.1});
      QCOMPARE(fromTable.v, c.v);
      QCOMPARE(fromTable.omega, c.omega);
    }
    QVERIFY(!s->isPaused());  // the first drive key started the clock
    // Limits, and small steps that add back up to exactly zero.
    s->setCommand({0, 0});
    for (int i = 0; i < 10; ++i)
      QTest::keyClick(&window, Qt::Key_Up);
    QCOMPARE(s->command().v, gui::kMaxDriveSpeed);
    for (int i = 0; i < 4; ++i)
      QTest::keyClick(&window, Qt::Key_A);
    QTest::keyClick(&window, Qt::Key_Right);
    QCOMPARE(s->command().omega, 0.0);
    // The command label shows it.
    QVERIFY2(window.commandText().contains(QStringLiteral("120")),
             qPrintable(window.commandText()));
    // Every key of the table does something the window knows.
    for (const gui::SimKey& k : gui::simKeys())
      QVERIFY(window.handleKey(k.key));
    QVERIFY(!window.handleKey(Qt::Key_F7));
  }

  void pauseAndStepKeys() {
    QTemporaryDir dir;
    SimWindow window(dir.filePath(QStringLiteral("p.db")));
    window.setStepsPerSecond(1);
    QVERIFY(window.startRun().ok());
    gui::SimSession* s = window.session();
    QTest::keyClick(&window, Qt::Key_W);  // starts the clock
    QVERIFY(!s->isPaused());
    QTest::keyClick(&window, Qt::Key_P);
    QVERIFY(s->isPaused());
    const std::size_t before = s->stepCount();
    QTest::keyClick(&window, Qt::Key_Period);
    QTest::keyClick(&window, Qt::Key_N);
    QCOMPARE(s->stepCount(), before + 2);
    QTest::keyClick(&window, Qt::Key_P);
    QVERIFY(!s->isPaused());
  }

  void mTogglesTheViewExceptInExperimentMode() {
    QTemporaryDir dir;
    SimWindow window(dir.filePath(QStringLiteral("m.db")));
    QVERIFY(window.startRun().ok());
    QVERIFY(!window.picture()->wholeScene());
    QTest::keyClick(&window, Qt::Key_M);
    QVERIFY(window.picture()->wholeScene());
    QTest::keyClick(&window, Qt::Key_M);
    QVERIFY(!window.picture()->wholeScene());
    // Practice in whole-scene view, then an experiment: the scene is hidden and stays hidden.
    QTest::keyClick(&window, Qt::Key_M);
    QVERIFY(window.picture()->wholeScene());
    window.setMode(SimMode::Experiment);
    window.setSubject(QStringLiteral("Ada"));
    window.setScene(QStringLiteral("room1"));
    QVERIFY(window.startRun().ok());
    QVERIFY(!window.picture()->wholeScene());
    QTest::keyClick(&window, Qt::Key_M);
    QVERIFY(!window.picture()->wholeScene());
    QVERIFY(!window.picture()->setWholeScene(true));
  }

  void collisionLightTurnsRedOnABlockedStep() {
    QTemporaryDir dir;
    SimWindow window(dir.filePath(QStringLiteral("c.db")));
    window.setStepsPerSecond(1);
    QVERIFY(window.startRun().ok());
    QCOMPARE(window.light(), SimWindow::Light::Idle);
    for (int i = 0; i < 4; ++i)
      QTest::keyClick(&window, Qt::Key_Up);  // 80 units/s straight ahead
    QCOMPARE(window.light(), SimWindow::Light::Moving);
    auto* light = window.findChild<QLabel*>(QStringLiteral("collisionLight"));
    QVERIFY(light != nullptr);
    QVERIFY(light->styleSheet().contains(QStringLiteral("#20a040")));
    window.session()->setPaused(true);
    // Straight on until a step is blocked (the practice box or a wall).
    int steps = 0;
    while (!window.session()->simulator()->blocked() && steps < 3000) {
      window.session()->stepOnce();
      ++steps;
    }
    QVERIFY2(window.session()->simulator()->blocked(), "never blocked");
    QCOMPARE(window.light(), SimWindow::Light::Blocked);
    QVERIFY(light->styleSheet().contains(QStringLiteral("#d62020")));
    // Backing off frees it again.
    window.session()->setCommand({-40, 0});
    window.session()->stepOnce();
    window.session()->stepOnce();
    QCOMPARE(window.light(), SimWindow::Light::Moving);
  }

  void giveUpRecordsGaveUpAndTheSubject() {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("g.db"));
    {
      SimWindow window(db);
      window.setStepsPerSecond(1);
      window.setMode(SimMode::Experiment);
      window.setScene(QStringLiteral("room1"));
      QVERIFY(!window.startRun().ok());  // no subject yet
      // The red line about the missing name goes once a name is typed (it once stayed).
      auto* error = window.findChild<QLabel*>(QStringLiteral("simError"));
      QVERIFY(error != nullptr);
      QVERIFY(!error->isHidden());
      window.setSubject(QStringLiteral("Ada Lovelace"));
      QVERIFY(error->isHidden());
      window.setSeed(5);
      window.setTimeLimitSeconds(120);
      QVERIFY(window.startRun().ok());
      QTest::keyClick(&window, Qt::Key_Up);
      window.session()->setPaused(true);
      window.session()->advance(30);
      auto* giveUp = window.findChild<QPushButton*>(QStringLiteral("giveUpButton"));
      QVERIFY(giveUp != nullptr && giveUp->isEnabled());
      QSignalSpy ended(window.session(), &gui::SimSession::runEnded);
      QTest::mouseClick(giveUp, Qt::LeftButton);
      QCOMPARE(ended.count(), 1);
      QVERIFY(!giveUp->isEnabled());
    }
    auto ws = openWorkspace(db);
    auto runs = ws->runStore().list();
    QVERIFY(runs.ok());
    QCOMPARE(runs->size(), std::size_t{1});
    const storage::RunInfo& info = runs->front();
    QCOMPARE(info.outcome, std::string("gave-up"));
    QCOMPARE(info.subject, std::string("Ada Lovelace"));
    QCOMPARE(info.stepCount, std::int64_t{31});
    auto run = ws->loadRun(info.name);
    QVERIFY(run.ok());
    QCOMPARE(*run->meta("mode"), std::string("experiment"));
    QCOMPARE(*run->meta("seed"), std::string("5"));
    QCOMPARE(*run->meta("time_limit"), std::string("120"));
    QCOMPARE(*run->meta("outcome"), std::string("gave-up"));
    // Start and goal are the ones drawn from seed 5, not the scene's.
    auto scene = sim::loadScene("room1");
    auto drawn = sim::drawStartGoal(scene.value(), 5);
    QCOMPARE(run->start()->x, drawn->start.x);
    QCOMPARE(run->goal()->first, drawn->goal.x());
    QVERIFY(run->start()->x != scene->start.x);
  }

  void timeLimitEndsTheRunWithTimeout() {
    QTemporaryDir dir;
    SimWindow window(dir.filePath(QStringLiteral("t.db")));
    window.setMode(SimMode::Experiment);
    window.setSubject(QStringLiteral("Bo"));
    window.setScene(QStringLiteral("room2"));
    window.setTimeLimitSeconds(10);  // 100 steps of 0.1 s
    QVERIFY(window.startRun().ok());
    QCOMPARE(window.session()->advance(1000), std::size_t{100});
    QCOMPARE(window.session()->outcome(), RunOutcome::Timeout);
    auto info =
        window.session()->workspace()->runStore().find(window.session()->runName().toStdString());
    QVERIFY(info.ok());
    QCOMPARE(info->outcome, std::string("timeout"));
    QCOMPARE(info->stepCount, std::int64_t{100});
  }

  void recordedRunEqualsSimulateReplay() {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("r.db"));
    QString name;
    {
      SimWindow window(db);
      window.setStepsPerSecond(1);
      window.setMode(SimMode::Experiment);
      window.setSubject(QStringLiteral("Cy"));
      window.setSeed(9);
      window.setScene(QStringLiteral("room3"));
      QVERIFY(window.startRun().ok());
      window.setDataPanelShown(true);
      gui::SimSession* s = window.session();
      s->setPaused(true);
      // A drive with turns and contacts: keys change the command, steps in between.
      const int keys[] = {Qt::Key_Up, Qt::Key_Up,    Qt::Key_Up,    Qt::Key_A,    Qt::Key_Left,
                          Qt::Key_D,  Qt::Key_W,     Qt::Key_Right, Qt::Key_Down, Qt::Key_Up,
                          Qt::Key_Up, Qt::Key_Space, Qt::Key_Down,  Qt::Key_Left};
      for (int key : keys) {
        s->setCommand(gui::applyDriveAction(gui::simKeyFor(key)->action, s->command()));
        for (int i = 0; i < 60; ++i)
          s->stepOnce();
      }
      name = s->runName();
      // The data panel follows the run.
      window.refreshDataPanel();
      QCOMPARE(window.dataSession()->stepCount(), static_cast<std::int64_t>(s->storedSteps()));
      window.giveUp();
    }
    auto ws = openWorkspace(db);
    auto recorded = ws->loadRun(name.toStdString());
    QVERIFY(recorded.ok());
    QCOMPARE(recorded->stepCount(), std::size_t{14 * 60});
    const QString exported = dir.filePath(QStringLiteral("recorded.csv"));
    auto info = ws->runStore().find(name.toStdString());
    QVERIFY(ws->runStore().exportRun(info->id, exported.toStdString()).ok());
    const QString replayed = dir.filePath(QStringLiteral("replayed.csv"));
    QProcess cli;
    cli.start(QStringLiteral(TACTILE_CLI),
              {QStringLiteral("simulate"), QStringLiteral("--scene"), QStringLiteral("room3"),
               QStringLiteral("--commands"), exported, QStringLiteral("--out"), replayed});
    QVERIFY(cli.waitForFinished(60000));
    QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
    auto replay = readRunCsv(replayed.toStdString());
    QVERIFY2(replay.ok(), replay.ok() ? "" : replay.errorText().c_str());
    QCOMPARE(replay->stepCount(), recorded->stepCount());
    QVERIFY(test_support::bitEqual(replay->x, recorded->x));
    QVERIFY(test_support::bitEqual(replay->y, recorded->y));
    QVERIFY(test_support::bitEqual(replay->theta, recorded->theta));
    QVERIFY(test_support::bitEqual(replay->v, recorded->v));
    QVERIFY(test_support::bitEqual(replay->omega, recorded->omega));
    QVERIFY(test_support::bitEqual(replay->sensors, recorded->sensors));
    QVERIFY(replay->blocked == recorded->blocked);
    QVERIFY(replay->truth == recorded->truth);
    QCOMPARE(*replay->meta("start"), *recorded->meta("start"));
    // The drive touched something, so the comparison covers contact values and blocked steps.
    QVERIFY(std::count(recorded->blocked.begin(), recorded->blocked.end(), 1) > 0);
  }

  void killedWindowKeepsTheStepsSoFar() {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("kill.db"));
    const QString commands = dir.filePath(QStringLiteral("commands.csv"));
    writeCommandFile(commands, 20000, 30, 0.25);
    { auto ws = openWorkspace(db); }  // the database exists before the window opens it
    const std::int64_t seen = killWorkbenchAfterSteps(
        dir, db,
        {QStringLiteral("--simulate"), QStringLiteral("practice"), QStringLiteral("--commands"),
         commands, QStringLiteral("--rate"), QStringLiteral("100")},
        60);
    QVERIFY2(seen >= 60, "the window stored no steps");
    auto ws = openWorkspace(db);

    auto runs = ws->runStore().list();
    QVERIFY(runs.ok());
    QCOMPARE(runs->size(), std::size_t{1});
    const storage::RunInfo info = runs->front();
    QVERIFY(info.stepCount >= seen);
    QVERIFY(info.stepCount < 20000);  // killed mid-run
    QCOMPARE(info.outcome, std::string("unknown"));
    auto kept = ws->loadRun(info.name);
    QVERIFY(kept.ok());
    QCOMPARE(static_cast<std::int64_t>(kept->stepCount()), info.stepCount);
    QVERIFY(ws->check().ok);
    // The steps kept are the steps the simulator took: the same commands stepped here.
    auto scene = sim::loadScene("practice");
    sim::RunOptions options;
    options.maxSteps = sim::kMaxStepsPerRun;
    auto loop = sim::RunLoop::start(std::make_shared<const sim::World>(scene.value()), "practice",
                                    "x", options);
    for (std::size_t k = 0; k < kept->stepCount(); ++k)
      loop.value()->step(sim::Command{30, 0.25});
    const RunData& again = loop.value()->recorder().run();
    QVERIFY(test_support::bitEqual(again.x, kept->x));
    QVERIFY(test_support::bitEqual(again.sensors, kept->sensors));
  }

  void killedAutonomousRunKeepsTheNavigatorsColumns() {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("kill-nav.db"));
    { auto ws = openWorkspace(db); }  // no model stored: the navigator with the bumper
    const std::int64_t seen = killWorkbenchAfterSteps(
        dir, db,
        {QStringLiteral("--simulate"), QStringLiteral("chapter5"), QStringLiteral("--mode"),
         QStringLiteral("autonomous"), QStringLiteral("--seed"), QStringLiteral("9"),
         QStringLiteral("--rate"), QStringLiteral("50")},
        40);
    QVERIFY2(seen >= 40, "the window stored no steps");
    auto ws = openWorkspace(db);

    auto runs = ws->runStore().list();
    QVERIFY(runs.ok());
    QCOMPARE(runs->size(), std::size_t{1});
    QCOMPARE(runs->front().outcome, std::string("unknown"));  // killed mid-run
    auto kept = ws->loadRun(runs->front().name);
    QVERIFY(kept.ok());
    const std::size_t steps = kept->stepCount();
    QVERIFY(steps >= static_cast<std::size_t>(seen));
    // Every step kept has the navigator's columns, equal to tactile navigate's first steps.
    auto reference = navigateChapter5(nav::StatusSource::Bumper, 9, steps);
    QVERIFY(reference.ok());
    QCOMPARE(reference->run.stepCount(), steps);  // the navigator had not finished there
    QVERIFY(kept->extraColumns == reference->run.extraColumns);
    QVERIFY(kept->extraValues == reference->run.extraValues);
    QVERIFY(test_support::bitEqual(kept->x, reference->run.x));
  }

  void autonomousModeTheNavigatorDrivesWithItsPanelLive() {
    QTemporaryDir dir;
    SimWindow window(dir.filePath(QStringLiteral("a.db")));
    window.setMode(SimMode::Autonomous);
    window.setScene(QStringLiteral("chapter5"));
    window.setNavigatorModel(QString());  // the Bug2 bumper baseline needs no model
    QVERIFY(window.navigatorModels().contains(QString()));
    QVERIFY(window.startRun().ok());
    gui::SimSession* s = window.session();
    QCOMPARE(window.experimentPanel()->markedStrategyRow(), -1);  // nothing before a step
    const double x0 = s->simulator()->pose().x;
    QCOMPARE(s->advance(200), std::size_t{200});
    QVERIFY(s->simulator()->pose().x != x0);
    const int row = window.experimentPanel()->markedStrategyRow();
    QVERIFY(row >= 0 && row < 7);
    QVERIFY(window.experimentPanel()->statusText(0) != QStringLiteral("-"));
    // The recorded commands are the navigator's; drive keys do not touch them.
    const sim::Command before = s->command();
    QTest::keyClick(&window, Qt::Key_Up);
    QCOMPARE(s->command().v, before.v);
    QCOMPARE(s->stepCount(), std::size_t{200});
    const RunData* run = s->run();
    QCOMPARE(run->v.back(), before.v);
    QCOMPARE(*run->meta("mode"), std::string("autonomous"));
    window.giveUp();
  }

  void autonomousPlayRecordsTheNavigatorsColumnsAsNavigateDoes() {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("nav.db"));
    constexpr int kSeed = 1;
    constexpr double kLimitSeconds = 80.0;  // 800 steps at most
    std::size_t steps = 0;
    {
      SimWindow window(db);
      window.setMode(SimMode::Autonomous);
      window.setScene(QStringLiteral("chapter5"));
      window.setNavigatorModel(QString());  // the navigator with the skin as a bumper
      window.setSeed(kSeed);
      window.setTimeLimitSeconds(kLimitSeconds);
      window.setStepsPerSecond(0);
      window.setDataPanelShown(true);
      window.show();
      QVERIFY(window.startRun().ok());
      gui::SimSession* s = window.session();
      QVERIFY(s->isPaused());  // waits for Play
      auto* play = window.findChild<QPushButton*>(QStringLiteral("pauseButton"));
      QVERIFY(play != nullptr);
      QCOMPARE(play->text(), SimWindow::tr("Play"));
      play->click();
      QVERIFY(!s->isPaused());
      QTRY_VERIFY_WITH_TIMEOUT(s->hasEnded(), 60000);
      steps = s->stepCount();
      QVERIFY(steps > 10);
      // The data panel shows the navigator's strips for the run it recorded.
      window.refreshDataPanel();
      QVERIFY(window.navigatorTrack()->hasTrack());
      QCOMPARE(window.navigatorTrack()->stepCount(), static_cast<std::int64_t>(steps));
      auto* strips = window.findChild<QWidget*>(QStringLiteral("navigatorStrips"));
      QVERIFY(strips != nullptr && strips->isVisibleTo(&window));
      QVERIFY(strips->height() >= 60);  // all six rows, not squeezed away by the timelines
    }

    // The stored run: the x_ columns of `tactile navigate`, value for value, and the same route:
    // the navigator run by nav::navigate from the same seed's start.
    auto ws = openWorkspace(db);
    auto runs = ws->runStore().list();
    QVERIFY(runs.ok());
    QCOMPARE(runs->size(), std::size_t{1});
    auto stored = ws->runStore().load(runs->front().id);
    QVERIFY(stored.ok());
    QCOMPARE(stored->stepCount(), steps);
    std::vector<std::string> expectedColumns{"x_strategy", "x_status"};
    for (const GroupInfo& g : kSensorGroups)
      expectedColumns.push_back("x_status_" + std::string(g.shortName));
    QVERIFY(stored->extraColumns == expectedColumns);
    QCOMPARE(*stored->meta("status_source"), std::string("bumper"));
    QCOMPARE(*stored->meta("seed"), std::to_string(kSeed));

    auto reference = navigateChapter5(nav::StatusSource::Bumper, kSeed,
                                      static_cast<std::size_t>(kLimitSeconds / 0.1 + 0.5));
    QVERIFY(reference.ok());
    QCOMPARE(std::string(runOutcomeName(reference->outcome)), runs->front().outcome);
    QCOMPARE(reference->run.stepCount(), steps);
    QVERIFY(reference->run.extraColumns == stored->extraColumns);
    QVERIFY(reference->run.extraValues == stored->extraValues);
    QVERIFY(test_support::bitEqual(reference->run.x, stored->x));
    QVERIFY(test_support::bitEqual(reference->run.theta, stored->theta));
    QVERIFY(test_support::bitEqual(reference->run.v, stored->v));
    QVERIFY(test_support::bitEqual(reference->run.omega, stored->omega));
    // Every cell is a strategy key or a status as nav/ spells them.
    for (std::size_t k = 0; k < steps; ++k) {
      const std::size_t row = k * expectedColumns.size();
      QVERIFY(nav::parseStrategyKey(stored->extraValues[row]).has_value());
      for (std::size_t c = 1; c < expectedColumns.size(); ++c)
        QVERIFY(nav::parseStatusText(stored->extraValues[row + c]).has_value());
    }
    // The workbench reads them as the navigator's track.
    gui::RunSession session;
    session.setWorkspace(ws.get());
    gui::NavigatorTrackModel track(&session);
    QVERIFY(session.open(runs->front().name));
    QVERIFY(track.hasTrack());
    for (std::size_t k = 0; k < steps; k += 37) {
      const auto strategy = track.strategyAt(static_cast<std::int64_t>(k));
      QVERIFY(strategy.has_value());
      QCOMPARE(std::string(nav::strategyKey(*strategy)),
               stored->extraValues[k * expectedColumns.size()]);
    }
    session.setWorkspace(nullptr);
  }

  void autonomousOnTheTruthDrivesAsNavigateStatusTruth() {
    QTemporaryDir dir;
    constexpr int kSeed = 1;  // a start from which the robot meets the wall
    constexpr double kLimitSeconds = 90.0;
    SimWindow window(dir.filePath(QStringLiteral("truth.db")));
    window.setMode(SimMode::Autonomous);
    window.setScene(QStringLiteral("chapter5"));
    window.setNavigatorSource(nav::StatusSource::Truth);
    QCOMPARE(window.navigatorSource(), nav::StatusSource::Truth);
    QVERIFY(!window.navigatorModels().isEmpty());  // the bumper; truth is not a model
    window.setSeed(kSeed);
    window.setTimeLimitSeconds(kLimitSeconds);
    QVERIFY(window.startRun().ok());
    gui::SimSession* s = window.session();
    while (!s->hasEnded() && s->advance(100) > 0) {
    }
    QVERIFY(s->hasEnded());
    const RunData* run = s->run();
    QCOMPARE(*run->meta("status_source"), std::string("truth"));

    auto reference = navigateChapter5(nav::StatusSource::Truth, kSeed,
                                      static_cast<std::size_t>(kLimitSeconds / 0.1 + 0.5));
    QVERIFY(reference.ok());
    QCOMPARE(*s->outcome(), reference->outcome);
    // How the run ended is shown large beside the buttons, and in the status bar.
    auto* outcome = window.findChild<QLabel*>(QStringLiteral("outcomeLabel"));
    QVERIFY(outcome != nullptr && !outcome->isHidden());
    QVERIFY(!outcome->text().isEmpty());
    if (reference->outcome == RunOutcome::Success)
      QVERIFY2(outcome->text().startsWith(QStringLiteral("Goal reached")),
               qPrintable(outcome->text()));
    QCOMPARE(window.statusBar()->currentMessage(), outcome->text());
    QCOMPARE(run->stepCount(), reference->run.stepCount());
    QVERIFY(test_support::bitEqual(reference->run.x, run->x));
    QVERIFY(reference->run.extraValues == run->extraValues);
    // The truth reached the navigator: some step has a contact status.
    bool contact = false;
    for (std::size_t k = 0; k < run->stepCount() && !contact; ++k)
      contact = run->extraValues[k * run->extraColumns.size() + 1] != "NoContact";
    QVERIFY(contact);

    // The workbench's --status truth stores the run as such; an unknown source is refused.
    const QString db = dir.filePath(QStringLiteral("args.db"));
    { auto ws = openWorkspace(db); }
    const auto workbench = [&](const QStringList& args, QString* err) {
      QProcess child;
      isolateWorkbench(child, dir);
      child.start(
          QStringLiteral(TACTILE_WORKBENCH),
          QStringList{QStringLiteral("--db"), db, QStringLiteral("--simulate"),
                      QStringLiteral("chapter5"), QStringLiteral("--mode"),
                      QStringLiteral("autonomous"), QStringLiteral("--step"), QStringLiteral("50"),
                      QStringLiteral("--screenshot"), dir.filePath(QStringLiteral("shot.png"))} +
              args);
      if (!child.waitForFinished(60000)) return -1;
      *err = QString::fromUtf8(child.readAllStandardError());
      return child.exitStatus() == QProcess::NormalExit ? child.exitCode() : -1;
    };
    QString err;
    QCOMPARE(workbench({QStringLiteral("--status"), QStringLiteral("truth")}, &err), 0);
    {
      auto ws = openWorkspace(db);
      auto runs = ws->runStore().list();
      QVERIFY(runs.ok());
      QCOMPARE(runs->size(), std::size_t{1});
      auto stored = ws->runStore().load(runs->front().id);
      QVERIFY(stored.ok());
      QCOMPARE(*stored->meta("status_source"), std::string("truth"));
      QCOMPARE(stored->stepCount(), std::size_t{50});
    }
    QVERIFY(workbench({QStringLiteral("--status"), QStringLiteral("sideways")}, &err) > 0);
    QVERIFY2(err.contains(QStringLiteral("--status must be")), qPrintable(err));
  }

  // Seed 0 is the scene's own start and goal: the window drives a benchmark map's run as the
  // benchmark (and `tactile navigate --seeds 0`) does.
  void seedZeroStartsWhereTheBenchmarkDoes() {
    QTemporaryDir dir;
    const QString spec = QStringLiteral("random:office:900002");
    constexpr double kLimitSeconds = 40.0;
    SimWindow window(dir.filePath(QStringLiteral("zero.db")));
    window.setMode(SimMode::Autonomous);
    window.setScene(spec);
    window.setNavigatorSource(nav::StatusSource::Truth);
    window.setSeed(0);
    auto* seedBox = window.findChild<QSpinBox*>(QStringLiteral("seedBox"));
    QVERIFY(seedBox != nullptr);
    QCOMPARE(seedBox->text(), QStringLiteral("0: the scene's own"));
    window.setTimeLimitSeconds(kLimitSeconds);
    QVERIFY(window.startRun().ok());
    gui::SimSession* s = window.session();
    while (!s->hasEnded() && s->advance(100) > 0) {
    }
    const RunData* run = s->run();

    auto scene = sim::loadScene(spec.toStdString());
    QVERIFY(scene.ok());
    auto world = std::make_shared<const sim::World>(std::move(scene.value()));
    nav::NavigatorConfig config;
    config.source = nav::StatusSource::Truth;
    nav::NavigateOptions options;
    options.maxSteps = static_cast<std::size_t>(kLimitSeconds / 0.1 + 0.5);
    options.seed = 0;
    auto reference = nav::navigate(world, spec.toStdString(), world->scene().start,
                                   world->scene().goal, config, options, true);
    QVERIFY(reference.ok());
    QVERIFY(run->stepCount() > 100);
    QCOMPARE(run->stepCount(), reference->run.stepCount());
    QVERIFY(test_support::bitEqual(reference->run.x, run->x));
    QVERIFY(reference->run.extraValues == run->extraValues);

    // Seed 1 starts elsewhere (drawn near the scene's start).
    window.setSeed(1);
    QVERIFY(window.startRun().ok());
    s->advance(1);
    QVERIFY(!test_support::bitEqual(reference->run.x, s->run()->x));
  }

  void autonomousStepByStepTakesOneStepAndPauseStops() {
    QTemporaryDir dir;
    SimWindow window(dir.filePath(QStringLiteral("steps.db")));
    window.setMode(SimMode::Autonomous);
    window.setScene(QStringLiteral("chapter5"));
    window.setNavigatorModel(QString());
    window.setStepsPerSecond(100);
    window.show();
    QVERIFY(window.startRun().ok());
    gui::SimSession* s = window.session();
    const auto* navigator = dynamic_cast<const nav::Navigator*>(s->setup().driver.get());
    QVERIFY(navigator != nullptr);
    QVERIFY(s->isPaused());
    // N and the Step button: exactly one step each, and the run stays paused.
    for (std::size_t k = 1; k <= 3; ++k) {
      QTest::keyClick(&window, Qt::Key_N);
      QCOMPARE(s->stepCount(), k);
      QVERIFY(s->isPaused());
    }
    window.findChild<QPushButton*>(QStringLiteral("stepButton"))->click();
    QCOMPARE(s->stepCount(), std::size_t{4});
    QTest::qWait(150);
    QCOMPARE(s->stepCount(), std::size_t{4});  // nothing moves while paused
    // The panel marks the navigator's strategy and shows its status.
    QCOMPARE(window.experimentPanel()->markedStrategyRow(),
             static_cast<int>(navigator->strategy()));
    QCOMPARE(window.experimentPanel()->statusText(0),
             gui::ExperimentPanel::statusTitle(navigator->integratedStatus()));
    for (const GroupInfo& g : kSensorGroups) {
      const auto i = static_cast<std::size_t>(groupIndex(g.group));
      QCOMPARE(window.experimentPanel()->statusText(1 + static_cast<int>(i)),
               gui::ExperimentPanel::statusTitle(navigator->groupStatus()[i]));
    }
    QCOMPARE(gui::ExperimentPanel::statusTitle({nav::StatusKind::Hole, 109.6}),
             QStringLiteral("Hole, 110 wide"));
    QCOMPARE(gui::ExperimentPanel::strategyTitle(nav::Strategy::FollowWall),
             QStringLiteral("Follow Wall"));
    // P plays, P pauses: no step after the pause.
    QTest::keyClick(&window, Qt::Key_P);
    QVERIFY(!s->isPaused());
    QTRY_VERIFY_WITH_TIMEOUT(s->stepCount() >= 20, 10000);
    QTest::keyClick(&window, Qt::Key_P);
    QVERIFY(s->isPaused());
    const std::size_t paused = s->stepCount();
    QTest::qWait(300);
    QCOMPARE(s->stepCount(), paused);
    QCOMPARE(window.experimentPanel()->markedStrategyRow(),
             static_cast<int>(navigator->strategy()));
    window.giveUp();
  }

  void modelsStoredLaterAreOfferedInAutonomousMode() {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("models.db"));
    { auto ws = openWorkspace(db); }
    SimWindow window(db);
    QCOMPARE(window.navigatorModels(), QStringList{QString()});  // only the bumper baseline
    // A model stored by another program while the window is open.
    const QString runFile = dir.filePath(QStringLiteral("r.csv"));
    const QString modelFile = dir.filePath(QStringLiteral("m.json"));
    const auto cli = [](const QStringList& args) {
      QProcess p;
      p.start(QStringLiteral(TACTILE_CLI), args);
      return p.waitForFinished(120000) && p.exitStatus() == QProcess::NormalExit &&
             p.exitCode() == 0;
    };
    QVERIFY(cli({QStringLiteral("simulate"), QStringLiteral("--scene"), QStringLiteral("room1"),
                 QStringLiteral("--steps"), QStringLiteral("3000"), QStringLiteral("--out"),
                 runFile, QStringLiteral("--quiet")}));
    QVERIFY(cli({QStringLiteral("train"), QStringLiteral("--runs"), runFile,
                 QStringLiteral("--groups"), QStringLiteral("R"), QStringLiteral("--threads"),
                 QStringLiteral("1"), QStringLiteral("--min-rows"), QStringLiteral("1"),
                 QStringLiteral("--out"), modelFile}));
    QVERIFY(cli({QStringLiteral("models"), QStringLiteral("import"), QStringLiteral("--db"), db,
                 QStringLiteral("--name"), QStringLiteral("later"), modelFile}));
    window.setMode(SimMode::Autonomous);
    QVERIFY(window.navigatorModels().contains(QStringLiteral("later")));
    window.setNavigatorModel(QStringLiteral("later"));
    auto* box = window.findChild<QComboBox*>(QStringLiteral("modelBox"));
    QVERIFY(box != nullptr);
    QCOMPARE(box->currentData().toString(), QStringLiteral("later"));
    // How the navigator drives: plan drive by default (as tactile navigate), or the thesis
    // strategies; the bumper baseline has no choice.
    auto* control = window.findChild<QComboBox*>(QStringLiteral("controlBox"));
    QVERIFY(control != nullptr);
    QVERIFY(control->isEnabled());
    QCOMPARE(control->currentData().toBool(), nav::NavigatorConfig{}.planDrive);
    for (int i = 0; i < control->count(); ++i) {
      control->setCurrentIndex(i);
      QVERIFY(window.startRun().ok());
      const auto* navigator =
          dynamic_cast<const nav::Navigator*>(window.session()->setup().driver.get());
      QVERIFY(navigator != nullptr);
      QCOMPARE(navigator->config().planDrive, control->itemData(i).toBool());
      QCOMPARE(navigator->config().source, nav::StatusSource::Model);
      window.giveUp();
    }
    window.setNavigatorModel(QString());
    QVERIFY(!control->isEnabled());
  }

  void touchMapIsDrawnOverThePictureAndTTogglesIt() {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("map.db"));
    { auto ws = openWorkspace(db); }
    const auto cli = [](const QStringList& args) {
      QProcess p;
      p.start(QStringLiteral(TACTILE_CLI), args);
      return p.waitForFinished(120000) && p.exitStatus() == QProcess::NormalExit &&
             p.exitCode() == 0;
    };
    // Models for every group, by a short run of the training recipe.
    const QString runs = dir.filePath(QStringLiteral("train"));
    const QString modelFile = dir.filePath(QStringLiteral("m.json"));
    QVERIFY(
        cli({QStringLiteral("simulate"), QStringLiteral("--plan"), QStringLiteral("training"),
             QStringLiteral("--runs"), QStringLiteral("12"), QStringLiteral("--seed"),
             QStringLiteral("1"), QStringLiteral("--out-dir"), runs, QStringLiteral("--quiet")}));
    QStringList train{QStringLiteral("train"), QStringLiteral("--runs")};
    for (const QString& f : QDir(runs).entryList({QStringLiteral("*.csv")}, QDir::Files))
      train << QDir(runs).filePath(f);
    train << QStringLiteral("--threads") << QStringLiteral("2") << QStringLiteral("--out")
          << modelFile;
    QVERIFY(cli(train));
    QVERIFY(cli({QStringLiteral("models"), QStringLiteral("import"), QStringLiteral("--db"), db,
                 QStringLiteral("--name"), QStringLiteral("m"), modelFile}));

    SimWindow window(db);
    window.setMode(SimMode::Autonomous);
    window.setScene(QStringLiteral("chapter5"));
    window.setNavigatorModel(QStringLiteral("m"));
    window.setSeed(1);
    window.resize(1600, 1000);
    window.show();
    QVERIFY(window.startRun().ok());
    gui::SimSession* s = window.session();
    const auto* navigator = dynamic_cast<const nav::Navigator*>(s->setup().driver.get());
    QVERIFY(navigator != nullptr && navigator->config().planDrive);
    gui::StatusPictureView* picture = window.picture();
    QVERIFY(picture->wholeScene());
    QVERIFY(picture->showTouchMap());

    // Drive until a touched cell lies well away from the robot and where its odometry puts it
    // (the robot and the ring are drawn over the map).
    const nav::TouchMap* map = nullptr;
    int col = -1;
    int row = -1;
    for (int chunk = 0; chunk < 40 && col < 0 && !s->hasEnded(); ++chunk) {
      s->advance(20);
      map = &navigator->touchMap();
      const Pose2d pose = s->simulator()->pose();
      const Pose2d& odo = navigator->odometry();
      for (int r = 0; r < map->rows() && col < 0; ++r) {
        for (int c = 0; c < map->cols(); ++c) {
          if (!map->cellTouched(c, r)) continue;
          const sim::Vec2 at = map->cellCentre(c, r);
          if (std::hypot(at.x() - pose.x, at.y() - pose.y) > 180.0 &&
              std::hypot(at.x() - odo.x, at.y() - odo.y) > 180.0) {
            col = c;
            row = r;
            break;
          }
        }
      }
    }
    QVERIFY2(col >= 0, "the navigator never touched anything far from where it stands");
    const sim::Vec2 cell = map->cellCentre(col, row);
    QImage shown = picture->grab().toImage();
    QVERIFY(picture->touchMapDrawn());
    const QPoint px = picture->worldToWidget().map(QPointF(cell.x(), cell.y())).toPoint();
    QVERIFY(shown.rect().contains(px));
    QCOMPARE(shown.pixelColor(px).rgb(), gui::StatusPictureView::touchedColour().rgb());
    // A cell closed by it but not touched itself is shaded (orange over the scene).
    int closedCol = -1;
    for (int c = 0; c < map->cols(); ++c) {
      if (map->cellClosed(c, row) && !map->cellTouched(c, row) && std::abs(c - col) <= 2) {
        closedCol = c;
        break;
      }
    }
    QVERIFY(closedCol >= 0);
    const QPoint closedPx = picture->worldToWidget()
                                .map(QPointF(map->cellCentre(closedCol, row).x(), cell.y()))
                                .toPoint();
    const QColor closed = shown.pixelColor(closedPx);
    QVERIFY2(closed.red() > closed.blue() + 40, qPrintable(closed.name()));

    // T hides it and shows it again.
    QTest::keyClick(picture, Qt::Key_T);
    QVERIFY(!picture->showTouchMap());
    shown = picture->grab().toImage();
    QVERIFY(!picture->touchMapDrawn());
    QVERIFY(shown.pixelColor(px).rgb() != gui::StatusPictureView::touchedColour().rgb());
    QTest::keyClick(picture, Qt::Key_T);
    QVERIFY(picture->showTouchMap());
    // The close-up draws it too.
    QTest::keyClick(picture, Qt::Key_M);
    QVERIFY(!picture->wholeScene());
    picture->grab();
    QVERIFY(picture->touchMapDrawn());
    window.giveUp();
  }

  void briefingAndKeysHelpListTheTable() {
    SimWindow window(QString{});
    QVERIFY(window.startRun().ok());  // in memory: runs are not stored but the window works
    QVERIFY(window.session()->runName().startsWith(QStringLiteral("practice")));
    QTimer::singleShot(200, [&] {
      auto* box = window.findChild<QMessageBox*>(QStringLiteral("keysHelp"));
      QVERIFY(box != nullptr);
      for (const gui::SimKey& k : gui::simKeys())
        QVERIFY2(box->text().contains(gui::simKeyDescription(k).toHtmlEscaped()), k.keyText);
      box->accept();
    });
    window.showKeys();
  }
};

QTEST_MAIN(SimWindowTest)
#include "sim_window_test.moc"
