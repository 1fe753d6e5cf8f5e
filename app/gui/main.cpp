// tactile-workbench: the desktop workbench.
#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

#include <cstdio>

#include "app/gui/main_window.h"

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("TactileWorkbench"));
  QApplication::setApplicationName(QStringLiteral("tactile-workbench"));
  QApplication::setApplicationVersion(QStringLiteral(TACTILE_VERSION));

  QCommandLineParser parser;
  parser.setApplicationDescription(
      QApplication::translate("main", "Tactile Workbench: tactile-navigation research desktop"));
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption screenshot(
      QStringLiteral("screenshot"),
      QApplication::translate("main", "Save a PNG of the window to FILE once shown, then quit."),
      QStringLiteral("FILE"));
  parser.addOption(screenshot);
  parser.process(app);

  tactile::gui::MainWindow window;
  window.show();
  if (parser.isSet(screenshot)) {
    const QString path = parser.value(screenshot);
    QTimer::singleShot(500, &window, [&window, path] {
      const bool saved = window.grab().save(path);
      if (!saved)
        std::fprintf(stderr, "tactile-workbench: error: cannot save %s\n", qPrintable(path));
      QApplication::exit(saved ? 0 : 1);
    });
  }
  return app.exec();
}
