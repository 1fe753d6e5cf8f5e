// The workbench's main window: the runs, route and labels docks around the timelines, the step
// controls, menus with recent databases, drag and drop of a database or run files, keyboard
// stepping and labelling, and every view setting kept in QSettings.
#pragma once

#include <QHash>
#include <QKeySequence>
#include <QList>
#include <QMainWindow>

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "base/error.h"
#include "run/sensor_layout.h"

class QAction;
class QDockWidget;
class QTimer;
class QLabel;
class QMenu;

namespace tactile::workspace {
class Workspace;
}

namespace tactile::gui {

class LabelModel;
class LabelPanelView;
class RouteView;
class RunListModel;
class RunListView;
class RunSession;
class PredictionModel;
class SimWindow;
class StepControlsView;
class SweepResultsWindow;
class TrainingDialog;
class TimelineView;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a database (an existing one, or a new one when `create`), then the last run and label
  // set used with it when they still exist.
  Status openDatabase(const QString& path, bool create = false);
  Status openRun(const QString& name);
  // Imports run files into the open database with a progress dialog (Cancel keeps finished runs).
  void importRuns(const QStringList& files);

  // ---- MCAP (docs/interop.md) ----
  // File > Export Run > MCAP: the export dialog for the open run, then exportRunMcap().
  void chooseMcapExport();
  // Writes the open run to an MCAP file on a worker thread, with a progress dialog whose Cancel
  // stops it (nothing is then left at `path`); an error goes to the status bar and a message box.
  void exportRunMcap(const QString& path, const QStringList& labelSets, const QString& model);
  // File > Import MCAP: a file dialog, then importMcapFile().
  void chooseMcapToImport();
  // An export of this program imports at once; any other MCAP file (a ROS 2 bag) opens the
  // mapping dialog first.
  void importMcapFile(const QString& path);
  // Imports on a worker thread: with the mapping's text for a bag, without one for an export of
  // this program; `name` empty: the file's name.
  void importMcap(const QString& path, const std::string& mappingJson, const QString& name);
  // True while an MCAP export or import runs.
  bool mcapBusy() const { return mcapBusy_; }

  RunSession* session() const { return session_; }
  LabelModel* labels() const { return labels_; }
  TimelineView* timeline() const { return timeline_; }
  RouteView* route() const { return route_; }
  LabelPanelView* labelPanel() const { return labelPanel_; }
  RunListView* runList() const { return runList_; }
  StepControlsView* stepControls() const { return steps_; }
  QString databasePath() const { return dbPath_; }
  // The last error shown in the status bar (empty when none since the last success).
  QString lastError() const { return lastError_; }

  // ---- learning ----
  // The train-and-sweep dialog (made on first use; null without a database).
  TrainingDialog* trainingDialog();
  void showTrainingDialog();
  // Opens a stored sweep's results window.
  Status openSweep(qint64 sweepId);
  SweepResultsWindow* sweepResults() const { return results_; }
  // Shows a stored model's predictions (one model for every group, or one per group) for the open
  // run, and for every run opened after it, until hidden.
  Status showPredictions(const QString& model);
  Status showPredictions(const std::array<QString, kGroupCount>& models);
  PredictionModel* predictions() const { return predictions_; }
  // Blocks until predictions being computed are shown (screenshots and tests).
  void waitForPredictions();
  // N / Shift+N: the cursor to the next / previous step where the model disagrees with a label.
  void jumpToDisagreement(bool forward);

  // Opens a simulator window on this window's database (scene: a built-in name or a file; empty:
  // the practice scene); "Open in Workbench" there opens the run here.
  SimWindow* openSimulator(const QString& scene = {});

  // Saves window and view settings now (also done on close, and shortly after any of them
  // changes, so a killed session keeps them).
  void saveSettings() const;
  // Saves the settings after a short quiet time (many changes in a row make one write).
  void scheduleSave();
  // Applies the preferences stored in QSettings (annotator, timeline row height).
  void applyPreferences();
  // Help > Keyboard Shortcuts and File > Preferences (modeless; null until first shown).
  void showKeyboardShortcuts();
  void showPreferences();
  // Help > User Guide (modeless; made on first use).
  void showUserGuide();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;
  // Keeps the step, class and undo keys working whatever has the focus, except a text field being
  // typed in; Escape leaves a text field.
  bool eventFilter(QObject* watched, QEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createViews();
  void createActions();
  void bindShortcut(QAction* action, const QString& id);
  void restoreSettings();
  void showError(const QString& message);
  // A database that cannot be opened: the status bar and a message box with the whole text (what
  // is wrong and what to do, e.g. a write-ahead log that does not belong), which does not block.
  void showOpenError(const QString& message);
  void showMessage(const QString& message);
  void updateTitle();
  void updateStatus();
  void rememberDatabase(const QString& path);
  void rebuildRecentMenu();
  void stepBy(std::int64_t delta);
  void stepByScreen(int direction);
  void chooseDatabase(bool create);
  // File > Open Server: a PostgreSQL address (recent ones offered, never with a password); a
  // password the server asks for is asked once and kept in this process only.
  void chooseServer();
  // The server went away: says so and tries to open it again every few seconds.
  void serverLost(const QString& message);
  // A run's assignment from the runs dock's context menu (RunListView::assignmentRequested).
  void changeAssignment(const QString& run, const QString& action);
  // Learn > Label from Model: the selection (or the steps in view) of the labelled groups take the
  // offline decision of the predictions' models, as one undoable edit.
  void labelFromModel();
  // Learn > Next Doubt (D): the next stretch where the predictions are unsure.
  void jumpToDoubt();
  // Greys out what the database's role may not do (docs/team.md#roles).
  void applyRights();
  void chooseRunFiles();
  void showAbout();
  void chooseSweep();
  void chooseModelToExport();
  void chooseModelToImport();
  void choosePredictionModels();
  bool predictionsWanted() const;

  std::unique_ptr<workspace::Workspace> workspace_;
  QString dbPath_;
  QString lastError_;
  bool switching_ = false;  // inside openDatabase
  bool mcapBusy_ = false;
  void showMcapError(const QString& title, const QString& message);
  RunSession* session_;
  LabelModel* labels_;
  RunListModel* runModel_;
  RunListView* runList_ = nullptr;
  RouteView* route_ = nullptr;
  TimelineView* timeline_ = nullptr;
  LabelPanelView* labelPanel_ = nullptr;
  StepControlsView* steps_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QLabel* stepLabel_ = nullptr;
  QLabel* setLabel_ = nullptr;
  TrainingDialog* training_ = nullptr;
  SweepResultsWindow* results_ = nullptr;
  PredictionModel* predictions_ = nullptr;
  QTimer* saveTimer_ = nullptr;
  QTimer* reconnectTimer_ = nullptr;
  QList<QKeySequence> globalKeys_;  // keys a focused widget other than a text field cannot take
  QHash<QKeySequence, QAction*> actionOfKey_;  // every bound key
};

}  // namespace tactile::gui
