// The workbench's main window: menus, status bar and the place the run views dock into.
#pragma once

#include <QMainWindow>

class QLabel;

namespace tactile::gui {

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void createMenus();
  void showAbout();
  void restoreSettings();
  void saveSettings() const;

  QLabel* welcome_ = nullptr;
};

}  // namespace tactile::gui
