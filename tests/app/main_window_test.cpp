#include <QAction>
#include <QLabel>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include "app/gui/main_window.h"
#include "run/builtin_scenes.h"

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

  void showsTitleMenusAndSceneCount() {
    tactile::gui::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCOMPARE(window.windowTitle(), QStringLiteral("Tactile Workbench"));
    QStringList menus;
    for (QAction* action : window.menuBar()->actions())
      menus << action->text();
    QCOMPARE(menus, (QStringList{QStringLiteral("&File"), QStringLiteral("&Help")}));
    const int scenes = static_cast<int>(tactile::builtinSceneNames().size());
    QVERIFY(window.statusBar()->currentMessage().startsWith(QString::number(scenes) + " "));
    auto* welcome = window.findChild<QLabel*>(QStringLiteral("welcome"));
    QVERIFY(welcome != nullptr);
    QVERIFY(welcome->text().contains(QStringLiteral("44 tactile domes")));
  }

  void restoresGeometryFromSettings() {
    {
      tactile::gui::MainWindow window;
      window.show();
      QVERIFY(QTest::qWaitForWindowExposed(&window));
      window.resize(900, 640);
      window.close();
    }
    tactile::gui::MainWindow again;
    QCOMPARE(again.size(), QSize(900, 640));
  }

 private:
  QTemporaryDir settingsDir_;
};

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
