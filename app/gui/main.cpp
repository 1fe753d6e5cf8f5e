// tactile-workbench: the desktop workbench.
#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QIcon>
#include <QSettings>
#include <QTimer>

#include <cstdio>

#include "app/gui/common/settings_keys.h"
#include "app/gui/common/ui_language.h"
#include "app/gui/learning/sweep_results_window.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/sim/sim_window.h"
#include "app/gui/sim/status_picture_view.h"

namespace {

int fail(const QString& message) {
  std::fprintf(stderr, "tactile-workbench: error: %s\n", qPrintable(message));
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("TactileWorkbench"));
  QApplication::setApplicationName(QStringLiteral("tactile-workbench"));
  QApplication::setApplicationVersion(QStringLiteral(TACTILE_VERSION));
  // The installed desktop entry and icon (share/applications, share/icons/hicolor).
  QGuiApplication::setDesktopFileName(QStringLiteral("tactile-workbench"));
  QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("tactile-workbench")));

  // The Preferences language or the system's, where a translation exists; English otherwise.
  // Numbers follow the interface language.
  tactile::gui::installUiLanguage(app);

  QCommandLineParser parser;
  parser.setApplicationDescription(
      QApplication::translate("main", "Tactile Workbench: tactile-navigation research desktop"));
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption dbOption(
      QStringLiteral("db"),
      QApplication::translate("main", "Open the run database DB (default: the last one used)."),
      QStringLiteral("DB"));
  const QCommandLineOption runOption(QStringLiteral("run"),
                                     QApplication::translate("main", "Open the run named NAME."),
                                     QStringLiteral("NAME"));
  const QCommandLineOption stepOption(QStringLiteral("step"),
                                      QApplication::translate("main", "Put the cursor on step K."),
                                      QStringLiteral("K"));
  const QCommandLineOption screenshot(
      QStringLiteral("screenshot"),
      QApplication::translate("main",
                              "Render the window (or with --sweep the results window) at "
                              "1600x1000 to the PNG file FILE, then quit."),
      QStringLiteral("FILE"));
  const QCommandLineOption sweepOption(
      QStringLiteral("sweep"),
      QApplication::translate("main", "Open the results of the stored sweep ID (needs --db)."),
      QStringLiteral("ID"));
  const QCommandLineOption modelOption(
      QStringLiteral("model"),
      QApplication::translate("main",
                              "Show the stored model NAME's predictions under the labels (needs "
                              "--run); with --simulate --mode autonomous: the navigator's model."),
      QStringLiteral("NAME"));
  // The simulator window (docs/workbench.md#simulator).
  const QCommandLineOption simulateOption(
      QStringLiteral("simulate"),
      QApplication::translate("main",
                              "Open the simulator window on SCENE (a built-in scene, a scene JSON "
                              "file or random:N:SEED); runs go into --db (or the last database)."),
      QStringLiteral("SCENE"));
  const QCommandLineOption modeOption(
      QStringLiteral("mode"),
      QApplication::translate("main",
                              "With --simulate: practice (default), experiment or autonomous."),
      QStringLiteral("MODE"));
  const QCommandLineOption subjectOption(
      QStringLiteral("subject"),
      QApplication::translate("main", "With --simulate: the subject's name."),
      QStringLiteral("NAME"));
  const QCommandLineOption seedOption(
      QStringLiteral("seed"),
      QApplication::translate("main",
                              "With --simulate --mode experiment: the seed of start and goal; "
                              "--mode autonomous: the seed of the start (as tactile navigate "
                              "--seeds)."),
      QStringLiteral("N"));
  const QCommandLineOption commandsOption(
      QStringLiteral("commands"),
      QApplication::translate("main",
                              "With --simulate: start a run and replay the v, omega commands of "
                              "the run file FILE, one a step."),
      QStringLiteral("FILE"));
  const QCommandLineOption rateOption(
      QStringLiteral("rate"),
      QApplication::translate("main",
                              "With --simulate: steps per second (default 10; 0 as fast as "
                              "possible)."),
      QStringLiteral("N"));
  const QCommandLineOption dataOption(
      QStringLiteral("data"),
      QApplication::translate("main", "With --simulate: show the data panel."));
  const QCommandLineOption statusOption(
      QStringLiteral("status"),
      QApplication::translate("main",
                              "With --simulate --mode autonomous: what the navigator's status "
                              "comes from, model (with --model), truth or bumper, as tactile "
                              "navigate --status."),
      QStringLiteral("SOURCE"));
  const QCommandLineOption wholeOption(
      QStringLiteral("whole-scene"),
      QApplication::translate("main", "With --simulate: show the whole scene where allowed."));
  for (const QCommandLineOption* o :
       {&simulateOption, &modeOption, &subjectOption, &seedOption, &commandsOption, &rateOption,
        &dataOption, &wholeOption, &statusOption})
    parser.addOption(*o);
  parser.addOption(dbOption);
  parser.addOption(sweepOption);
  parser.addOption(modelOption);
  parser.addOption(runOption);
  parser.addOption(stepOption);
  parser.addOption(screenshot);
  parser.process(app);

  bool stepOk = true;
  const qlonglong step =
      parser.isSet(stepOption) ? parser.value(stepOption).toLongLong(&stepOk) : 0;
  if (!stepOk || step < 0)
    return fail(QApplication::translate("main", "--step needs a step number, got '%1'")
                    .arg(parser.value(stepOption)));
  if (parser.isSet(runOption) && !parser.isSet(dbOption))
    return fail(QApplication::translate("main", "--run needs --db"));
  if (parser.isSet(sweepOption) && !parser.isSet(dbOption))
    return fail(QApplication::translate("main", "--sweep needs --db"));
  if (parser.isSet(modelOption) && !parser.isSet(runOption) && !parser.isSet(simulateOption))
    return fail(QApplication::translate("main", "--model needs --run"));
  bool sweepOk = true;
  const qlonglong sweepId =
      parser.isSet(sweepOption) ? parser.value(sweepOption).toLongLong(&sweepOk) : 0;
  if (!sweepOk || (parser.isSet(sweepOption) && sweepId <= 0))
    return fail(QApplication::translate("main", "--sweep needs a sweep id, got '%1'")
                    .arg(parser.value(sweepOption)));

  tactile::gui::MainWindow window;
  if (parser.isSet(screenshot)) window.resize(1600, 1000);
  QString db = parser.value(dbOption);
  if (db.isEmpty()) {
    const QString last = QSettings().value(tactile::gui::settings_keys::kLastDatabase).toString();
    if (!last.isEmpty() && QFileInfo::exists(last)) db = last;
  }
  if (!db.isEmpty()) {
    if (parser.isSet(dbOption) && !QFileInfo::exists(db))
      return fail(QApplication::translate("main", "%1: no such database").arg(db));
    tactile::Status opened = window.openDatabase(db);
    if (!opened) {
      if (parser.isSet(dbOption)) return fail(QString::fromStdString(opened.errorText()));
      std::fprintf(stderr, "tactile-workbench: warning: %s\n", opened.errorText().c_str());
    }
  }
  if (parser.isSet(runOption)) {
    tactile::Status opened = window.openRun(parser.value(runOption));
    if (!opened) return fail(QString::fromStdString(opened.errorText()));
  }
  if (parser.isSet(modelOption) && !parser.isSet(simulateOption)) {
    tactile::Status shown = window.showPredictions(parser.value(modelOption));
    if (!shown) return fail(QString::fromStdString(shown.errorText()));
  }
  if (parser.isSet(stepOption) && !parser.isSet(simulateOption))
    window.session()->setCurrentStep(step);
  QWidget* shot = &window;
  if (parser.isSet(statusOption) &&
      (!parser.isSet(simulateOption) || parser.value(modeOption) != QStringLiteral("autonomous")))
    return fail(QApplication::translate("main", "--status needs --simulate and --mode autonomous"));
  tactile::gui::SimWindow* simWindow = nullptr;
  if (parser.isSet(simulateOption)) {
    simWindow = window.openSimulator(parser.value(simulateOption));
    const QString mode = parser.value(modeOption);
    if (mode == QStringLiteral("experiment")) {
      simWindow->setMode(tactile::gui::SimMode::Experiment);
    } else if (mode == QStringLiteral("autonomous")) {
      simWindow->setMode(tactile::gui::SimMode::Autonomous);
      const QString status = parser.value(statusOption);
      if (status == QStringLiteral("truth") || status == QStringLiteral("bumper")) {
        if (parser.isSet(modelOption))
          return fail(QApplication::translate("main", "--status %1 takes no --model").arg(status));
        simWindow->setNavigatorSource(status == QStringLiteral("truth")
                                          ? tactile::nav::StatusSource::Truth
                                          : tactile::nav::StatusSource::Bumper);
      } else if (!status.isEmpty() && status != QStringLiteral("model")) {
        return fail(
            QApplication::translate("main", "--status must be model, truth or bumper, got '%1'")
                .arg(status));
      } else if (status == QStringLiteral("model") && !parser.isSet(modelOption)) {
        return fail(QApplication::translate("main", "--status model needs --model NAME"));
      }
      if (parser.isSet(modelOption)) {
        if (!simWindow->navigatorModels().contains(parser.value(modelOption)))
          return fail(QApplication::translate("main", "no stored model named '%1'")
                          .arg(parser.value(modelOption)));
        simWindow->setNavigatorModel(parser.value(modelOption));
      }
    } else if (!mode.isEmpty() && mode != QStringLiteral("practice")) {
      return fail(QApplication::translate(
                      "main", "--mode must be practice, experiment or autonomous, got '%1'")
                      .arg(mode));
    }
    simWindow->setSubject(parser.value(subjectOption));
    if (parser.isSet(seedOption)) {
      bool ok = true;
      const int seed = parser.value(seedOption).toInt(&ok);
      if (!ok || seed < 1)
        return fail(QApplication::translate("main", "--seed needs a positive number, got '%1'")
                        .arg(parser.value(seedOption)));
      simWindow->setSeed(seed);
    }
    if (parser.isSet(rateOption)) {
      bool ok = true;
      const double rate = parser.value(rateOption).toDouble(&ok);
      if (!ok || rate < 0)
        return fail(QApplication::translate("main", "--rate needs a number >= 0, got '%1'")
                        .arg(parser.value(rateOption)));
      simWindow->setStepsPerSecond(rate);
    }
    const tactile::Status started = parser.isSet(commandsOption)
                                        ? simWindow->replayCommands(parser.value(commandsOption))
                                        : simWindow->startRun();
    if (!started) return fail(QString::fromStdString(started.errorText()));
    // --step K with --simulate: the run takes K steps at once (screenshots of a run under way).
    if (parser.isSet(stepOption)) simWindow->session()->advance(static_cast<std::size_t>(step));
    // Autonomous mode plays at once (Play pressed); not for a screenshot, which shows the run
    // after --step K steps exactly.
    if (mode == QStringLiteral("autonomous") && !parser.isSet(screenshot))
      simWindow->session()->setPaused(false);
    if (parser.isSet(dataOption)) simWindow->setDataPanelShown(true);
    if (parser.isSet(wholeOption)) simWindow->picture()->setWholeScene(true);
    shot = simWindow;
  } else {
    window.show();
  }
  if (parser.isSet(sweepOption)) {
    tactile::Status opened = window.openSweep(sweepId);
    if (!opened) return fail(QString::fromStdString(opened.errorText()));
    shot = window.sweepResults();
  }
  if (parser.isSet(screenshot)) {
    const QString path = parser.value(screenshot);
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
