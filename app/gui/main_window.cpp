#include "app/gui/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

#include "run/builtin_scenes.h"
#include "run/sensor_layout.h"

namespace tactile::gui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setObjectName(QStringLiteral("MainWindow"));
  setWindowTitle(tr("Tactile Workbench"));
  welcome_ = new QLabel(this);
  welcome_->setObjectName(QStringLiteral("welcome"));
  welcome_->setAlignment(Qt::AlignCenter);
  welcome_->setWordWrap(true);
  welcome_->setText(
      tr("<h2>Tactile Workbench</h2>"
         "<p>Simulate a robot with %1 tactile domes in %2 sensor groups, record and label its "
         "runs, and train classifiers on them.</p>"
         "<p>The run views arrive with the workbench release; until then the <tt>tactile</tt> "
         "command-line tool does the work.</p>")
          .arg(kSensorCount)
          .arg(kGroupCount));
  setCentralWidget(welcome_);
  createMenus();
  statusBar()->showMessage(
      tr("%n built-in scene(s)", nullptr, static_cast<int>(builtinSceneNames().size())));
  resize(1200, 800);
  restoreSettings();
}

void MainWindow::createMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);
  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About Tactile Workbench"), this, &MainWindow::showAbout);
}

void MainWindow::showAbout() {
  QMessageBox::about(this, tr("About Tactile Workbench"),
                     tr("Tactile Workbench %1\nResearch workbench for tactile-based mobile-robot "
                        "navigation.")
                         .arg(QApplication::applicationVersion()));
}

void MainWindow::restoreSettings() {
  QSettings settings;
  restoreGeometry(settings.value(QStringLiteral("mainWindow/geometry")).toByteArray());
  restoreState(settings.value(QStringLiteral("mainWindow/state")).toByteArray());
}

void MainWindow::saveSettings() const {
  QSettings settings;
  settings.setValue(QStringLiteral("mainWindow/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("mainWindow/state"), saveState());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  saveSettings();
  event->accept();
}

}  // namespace tactile::gui
