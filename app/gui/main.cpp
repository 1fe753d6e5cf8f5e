// tactile-workbench: the desktop workbench.
#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QIcon>
#include <QSettings>
#include <QTimer>

#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <string_view>

#include "app/gui/common/settings_keys.h"
#include "app/gui/common/ui_language.h"
#include "app/gui/learning/sweep_results_window.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/sim/sim_window.h"
#include "app/gui/sim/status_picture_view.h"
#include "storage/run_database.h"

namespace {

int fail(const QString& message) {
  std::fprintf(stderr, "tactile-workbench: error: %s\n", qPrintable(message));
  return 1;
}

// The command line. Built before the application object when only --help or --version is asked,
// so that both work without a display.
struct WorkbenchOptions {
  QCommandLineOption db, run, step, screenshot, sweep, model, simulate, mode, subject, seed,
      commands, rate, data, status, wholeScene;

  explicit WorkbenchOptions(QCommandLineParser& parser)
      : db(QStringLiteral("db"),
           QApplication::translate("main",
                                   "Open the run database DB (default: the last one used)."),
           QStringLiteral("DB")),
        run(QStringLiteral("run"), QApplication::translate("main", "Open the run named NAME."),
            QStringLiteral("NAME")),
        step(QStringLiteral("step"), QApplication::translate("main", "Put the cursor on step K."),
             QStringLiteral("K")),
        screenshot(
            QStringLiteral("screenshot"),
            QApplication::translate("main",
                                    "Render the window (or with --sweep the results window) at "
                                    "1600x1000 to the PNG file FILE, then quit."),
            QStringLiteral("FILE")),
        sweep(QStringLiteral("sweep"),
              QApplication::translate("main",
                                      "Open the results of the stored sweep ID (needs --db)."),
              QStringLiteral("ID")),
        model(QStringLiteral("model"),
              QApplication::translate(
                  "main",
                  "Show the stored model NAME's predictions under the labels (needs "
                  "--run); with --simulate --mode autonomous: the navigator's model."),
              QStringLiteral("NAME")),
        simulate(QStringLiteral("simulate"),
                 QApplication::translate(
                     "main",
                     "Open the simulator window on SCENE (a built-in scene, a scene JSON "
                     "file or random:N:SEED); runs go into --db (or the last database)."),
                 QStringLiteral("SCENE")),
        mode(QStringLiteral("mode"),
             QApplication::translate(
                 "main", "With --simulate: practice (default), experiment or autonomous."),
             QStringLiteral("MODE")),
        subject(QStringLiteral("subject"),
                QApplication::translate("main", "With --simulate: the subject's name."),
                QStringLiteral("NAME")),
        seed(QStringLiteral("seed"),
             QApplication::translate(
                 "main",
                 "With --simulate --mode experiment: the seed of start and goal; "
                 "--mode autonomous: the seed of the start (as tactile navigate "
                 "--seeds); 0: the scene's own start and goal."),
             QStringLiteral("N")),
        commands(QStringLiteral("commands"),
                 QApplication::translate(
                     "main",
                     "With --simulate: start a run and replay the v, omega commands of "
                     "the run file FILE, one a step."),
                 QStringLiteral("FILE")),
        rate(QStringLiteral("rate"),
             QApplication::translate("main",
                                     "With --simulate: steps per second (default 10; 0 as fast as "
                                     "possible)."),
             QStringLiteral("N")),
        data(QStringLiteral("data"),
             QApplication::translate("main", "With --simulate: show the data panel.")),
        status(QStringLiteral("status"),
               QApplication::translate(
                   "main",
                   "With --simulate --mode autonomous: what the navigator's status "
                   "comes from, model (with --model), truth or bumper, as tactile "
                   "navigate --status."),
               QStringLiteral("SOURCE")),
        wholeScene(QStringLiteral("whole-scene"),
                   QApplication::translate(
                       "main", "With --simulate: show the whole scene where allowed.")) {
    parser.setApplicationDescription(
        QApplication::translate("main", "Tactile Workbench: tactile-navigation research desktop"));
    parser.addHelpOption();
    parser.addVersionOption();
    for (const QCommandLineOption* o :
         {&simulate, &mode, &subject, &seed, &commands, &rate, &data, &wholeScene, &status, &db,
          &sweep, &model, &run, &step, &screenshot})
      parser.addOption(*o);
  }
};

void setIdentity() {
  QCoreApplication::setOrganizationName(QStringLiteral("TactileWorkbench"));
  QCoreApplication::setApplicationName(QStringLiteral("tactile-workbench"));
  QCoreApplication::setApplicationVersion(QStringLiteral(TACTILE_VERSION));
}

// True when an argument is one of `names`, or NAME=VALUE for one of them.
bool hasArgument(int argc, char** argv, std::initializer_list<std::string_view> names) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    for (std::string_view name : names)
      if (arg == name ||
          (arg.starts_with(name) && arg.size() > name.size() && arg[name.size()] == '='))
        return true;
  }
  return false;
}

bool environmentSet(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0';
}

}  // namespace

int main(int argc, char** argv) {
  // --help and --version need no display: answered before the application object that opens one.
  if (hasArgument(argc, argv, {"-h", "--help", "-?", "--help-all", "-v", "--version"})) {
    QCoreApplication core(argc, argv);
    setIdentity();
    tactile::gui::installUiLanguage(core);
    QCommandLineParser parser;
    const WorkbenchOptions options(parser);
    parser.process(core);  // prints and exits
    return 0;
  }
  // No display on a Linux desktop: a screenshot renders off screen; anything else says why it
  // cannot open a window instead of Qt's plugin message.
#if defined(Q_OS_UNIX) && !defined(Q_OS_MACOS)
  if (!environmentSet("QT_QPA_PLATFORM") && !environmentSet("DISPLAY") &&
      !environmentSet("WAYLAND_DISPLAY")) {
    if (hasArgument(argc, argv, {"--screenshot"})) {
      qputenv("QT_QPA_PLATFORM", "offscreen");
    } else {
      QCoreApplication core(argc, argv);
      setIdentity();
      tactile::gui::installUiLanguage(core);
      return fail(QCoreApplication::translate(
          "main",
          "no display to open a window on (DISPLAY and WAYLAND_DISPLAY are not set). Run it in a "
          "desktop session, or with --screenshot FILE to render without a display; the "
          "command-line tool is tactile."));
    }
  }
#endif
  QApplication app(argc, argv);
  setIdentity();
  // The installed desktop entry and icon (share/applications, share/icons/hicolor).
  QGuiApplication::setDesktopFileName(QStringLiteral("tactile-workbench"));
  QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("tactile-workbench")));

  // The Preferences language or the system's, where a translation exists; English otherwise.
  // Numbers follow the interface language.
  tactile::gui::installUiLanguage(app);

  QCommandLineParser parser;
  const WorkbenchOptions options(parser);
  parser.process(app);

  bool stepOk = true;
  const qlonglong step =
      parser.isSet(options.step) ? parser.value(options.step).toLongLong(&stepOk) : 0;
  if (!stepOk || step < 0)
    return fail(QApplication::translate("main", "--step needs a step number, got '%1'")
                    .arg(parser.value(options.step)));
  if (parser.isSet(options.run) && !parser.isSet(options.db))
    return fail(QApplication::translate("main", "--run needs --db"));
  if (parser.isSet(options.sweep) && !parser.isSet(options.db))
    return fail(QApplication::translate("main", "--sweep needs --db"));
  if (parser.isSet(options.model) && !parser.isSet(options.run) && !parser.isSet(options.simulate))
    return fail(QApplication::translate("main", "--model needs --run"));
  bool sweepOk = true;
  const qlonglong sweepId =
      parser.isSet(options.sweep) ? parser.value(options.sweep).toLongLong(&sweepOk) : 0;
  if (!sweepOk || (parser.isSet(options.sweep) && sweepId <= 0))
    return fail(QApplication::translate("main", "--sweep needs a sweep id, got '%1'")
                    .arg(parser.value(options.sweep)));

  tactile::gui::MainWindow window;
  if (parser.isSet(options.screenshot)) window.resize(1600, 1000);
  QString db = parser.value(options.db);
  if (db.isEmpty()) {
    const QString last = QSettings().value(tactile::gui::settings_keys::kLastDatabase).toString();
    if (!last.isEmpty() && QFileInfo::exists(last)) db = last;
  }
  if (!db.isEmpty()) {
    // A server address is not a file: connecting says what is wrong with it.
    if (parser.isSet(options.db) && !tactile::storage::isServerAddress(db.toStdString()) &&
        !QFileInfo::exists(db))
      return fail(QApplication::translate("main", "%1: no such database").arg(db));
    tactile::Status opened = window.openDatabase(db);
    if (!opened) {
      if (parser.isSet(options.db)) return fail(QString::fromStdString(opened.errorText()));
      std::fprintf(stderr, "tactile-workbench: warning: %s\n", opened.errorText().c_str());
    }
  }
  if (parser.isSet(options.run)) {
    tactile::Status opened = window.openRun(parser.value(options.run));
    if (!opened) return fail(QString::fromStdString(opened.errorText()));
  }
  if (parser.isSet(options.model) && !parser.isSet(options.simulate)) {
    tactile::Status shown = window.showPredictions(parser.value(options.model));
    if (!shown) return fail(QString::fromStdString(shown.errorText()));
  }
  if (parser.isSet(options.step) && !parser.isSet(options.simulate))
    window.session()->setCurrentStep(step);
  QWidget* shot = &window;
  if (parser.isSet(options.status) && (!parser.isSet(options.simulate) ||
                                       parser.value(options.mode) != QStringLiteral("autonomous")))
    return fail(QApplication::translate("main", "--status needs --simulate and --mode autonomous"));
  tactile::gui::SimWindow* simWindow = nullptr;
  if (parser.isSet(options.simulate)) {
    simWindow = window.openSimulator(parser.value(options.simulate));
    const QString mode = parser.value(options.mode);
    if (mode == QStringLiteral("experiment")) {
      simWindow->setMode(tactile::gui::SimMode::Experiment);
    } else if (mode == QStringLiteral("autonomous")) {
      simWindow->setMode(tactile::gui::SimMode::Autonomous);
      const QString status = parser.value(options.status);
      if (status == QStringLiteral("truth") || status == QStringLiteral("bumper")) {
        if (parser.isSet(options.model))
          return fail(QApplication::translate("main", "--status %1 takes no --model").arg(status));
        simWindow->setNavigatorSource(status == QStringLiteral("truth")
                                          ? tactile::nav::StatusSource::Truth
                                          : tactile::nav::StatusSource::Bumper);
      } else if (!status.isEmpty() && status != QStringLiteral("model")) {
        return fail(
            QApplication::translate("main", "--status must be model, truth or bumper, got '%1'")
                .arg(status));
      } else if (status == QStringLiteral("model") && !parser.isSet(options.model)) {
        return fail(QApplication::translate("main", "--status model needs --model NAME"));
      }
      if (parser.isSet(options.model)) {
        if (!simWindow->navigatorModels().contains(parser.value(options.model)))
          return fail(QApplication::translate("main", "no stored model named '%1'")
                          .arg(parser.value(options.model)));
        simWindow->setNavigatorModel(parser.value(options.model));
      }
    } else if (!mode.isEmpty() && mode != QStringLiteral("practice")) {
      return fail(QApplication::translate(
                      "main", "--mode must be practice, experiment or autonomous, got '%1'")
                      .arg(mode));
    }
    simWindow->setSubject(parser.value(options.subject));
    if (parser.isSet(options.seed)) {
      bool ok = true;
      const int seed = parser.value(options.seed).toInt(&ok);
      if (!ok || seed < 0)
        return fail(QApplication::translate("main", "--seed needs a number >= 0, got '%1'")
                        .arg(parser.value(options.seed)));
      simWindow->setSeed(seed);
    }
    if (parser.isSet(options.rate)) {
      bool ok = true;
      const double rate = parser.value(options.rate).toDouble(&ok);
      if (!ok || rate < 0)
        return fail(QApplication::translate("main", "--rate needs a number >= 0, got '%1'")
                        .arg(parser.value(options.rate)));
      simWindow->setStepsPerSecond(rate);
    }
    const tactile::Status started = parser.isSet(options.commands)
                                        ? simWindow->replayCommands(parser.value(options.commands))
                                        : simWindow->startRun();
    if (!started) return fail(QString::fromStdString(started.errorText()));
    // --step K with --simulate: the run takes K steps at once (screenshots of a run under way).
    if (parser.isSet(options.step)) simWindow->session()->advance(static_cast<std::size_t>(step));
    // Autonomous mode plays at once (Play pressed); not for a options.screenshot, which shows the
    // run after --step K steps exactly.
    if (mode == QStringLiteral("autonomous") && !parser.isSet(options.screenshot))
      simWindow->session()->setPaused(false);
    if (parser.isSet(options.data)) simWindow->setDataPanelShown(true);
    if (parser.isSet(options.wholeScene)) simWindow->picture()->setWholeScene(true);
    shot = simWindow;
  } else {
    window.show();
  }
  if (parser.isSet(options.sweep)) {
    tactile::Status opened = window.openSweep(sweepId);
    if (!opened) return fail(QString::fromStdString(opened.errorText()));
    shot = window.sweepResults();
  }
  if (parser.isSet(options.screenshot)) {
    const QString path = parser.value(options.screenshot);
    // Long enough for the queued replots of every view.
    // A sweep's results window is shot instead of the main window. Predictions are computed in
    // the background: wait for them as well.
    QTimer::singleShot(600, &window, [&window, shot, path, simWindow] {
      window.waitForPredictions();
      if (simWindow != nullptr) {
        // A replay finishes first (it steps in slices between events), then the data panel
        // reads the run.
        while (simWindow->session()->scriptLeft() > 0 && !simWindow->session()->hasEnded() &&
               !simWindow->session()->isPaused())
          QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
        simWindow->refreshDataPanel();
        QCoreApplication::processEvents();
        shot->resize(1400, 900);
        QCoreApplication::processEvents();
        const bool saved = shot->grab().save(path);
        if (!saved)
          std::fprintf(stderr, "tactile-workbench: error: cannot save %s\n", qPrintable(path));
        QApplication::exit(saved ? 0 : 1);
        return;
      }
      QCoreApplication::sendPostedEvents();
      QCoreApplication::processEvents();
      shot->resize(1600, 1000);
      const bool saved = shot->grab().save(path);
      if (!saved)
        std::fprintf(stderr, "tactile-workbench: error: cannot save %s\n", qPrintable(path));
      QApplication::exit(saved ? 0 : 1);
    });
  }
  return app.exec();
}
