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
                              "--run)."),
      QStringLiteral("NAME"));
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
  if (parser.isSet(modelOption) && !parser.isSet(runOption))
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
  if (parser.isSet(modelOption)) {
    tactile::Status shown = window.showPredictions(parser.value(modelOption));
    if (!shown) return fail(QString::fromStdString(shown.errorText()));
  }
  if (parser.isSet(stepOption)) window.session()->setCurrentStep(step);
  window.show();
  QWidget* shot = &window;
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
    QTimer::singleShot(600, &window, [&window, shot, path] {
      window.waitForPredictions();
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
