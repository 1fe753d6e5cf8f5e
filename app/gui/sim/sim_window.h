// The simulator window (thesis 2.3-2.5, 3.1): drive the robot by touch, practise, run experiments.
// Left: the status picture (robot close-up, or the whole scene where the mode allows; M). Right:
// the signal bars per group, the collision light (red blocked, green moving) with the current
// command, the run's state, and the run controls (mode, scene, subject, seed, time limit, step
// rate, pause, step, give up). Below, a data panel that expands to show the run so far with the
// workbench's heatmap and strips, live. Keys come from one table (drive_keys.h), listed under
// Help > Keys; Help > Briefing explains Bug1 and Bug2.
//
// Every run is stored in the database while it is recorded (SimSession); "Open in Workbench"
// shows it in the main window. The window has its own connection to the database file (or a
// private in-memory database when none is given).
#pragma once

#include <QMainWindow>

#include <memory>

#include "app/gui/sim/sim_session.h"
#include "base/error.h"
#include "nav/navigator.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QSplitter;
class QStackedWidget;

namespace tactile::workspace {
class Workspace;
}

namespace tactile::gui {

class RunSession;
class SignalBarsView;
class StatusPictureView;
class TimelineView;
class ExperimentPanel;
class NavigatorStripView;
class NavigatorTrackModel;

class SimWindow : public QMainWindow {
  Q_OBJECT

 public:
  enum class Light { Idle, Moving, Blocked };

  // `dbPath` empty: runs go to a private in-memory database (lost on close).
  explicit SimWindow(const QString& dbPath, QWidget* parent = nullptr);
  ~SimWindow() override;
  // Whether the database opened (else the error is shown and runs are not stored).
  Status databaseStatus() const { return dbStatus_; }
  QString databasePath() const { return dbPath_; }

  SimSession* session() const { return session_; }
  StatusPictureView* picture() const { return picture_; }
  SignalBarsView* bars() const { return bars_; }
  TimelineView* timeline() const { return timeline_; }
  // The data panel's navigator strips (shown for autonomous runs).
  NavigatorTrackModel* navigatorTrack() const { return navTrack_; }
  RunSession* dataSession() const { return dataSession_; }

  // ---- the run controls ----
  void setMode(SimMode mode);
  SimMode mode() const;
  // A built-in scene name, a scene file or random:N:SEED.
  void setScene(const QString& spec);
  QString scene() const { return sceneSpec_; }
  void setSubject(const QString& subject);
  void setSeed(int seed);
  void setTimeLimitSeconds(double seconds);
  void setStepsPerSecond(double rate);  // 0: as fast as possible
  // Autonomous mode: the stored model the navigator classifies contacts with, or an empty name
  // for the Bug2 baseline that treats the skin as a bumper. Lists the database's models again.
  void setNavigatorModel(const QString& model);
  // The navigator's status source: a stored model (`model`), the simulator's truth (the ceiling,
  // as `tactile navigate --status truth`) or the bumper baseline.
  void setNavigatorSource(nav::StatusSource source, const QString& model = QString());
  nav::StatusSource navigatorSource() const;
  // The stored models offered, and an empty name for the bumper baseline.
  QStringList navigatorModels() const;
  ExperimentPanel* experimentPanel() const { return experiment_; }
  // Starts a new run from the controls (the previous one, if running, ends as gave-up); the run
  // waits, paused, for the first drive key or Go. Errors are also shown in the window.
  Status startRun();
  // Starts a run and replays a run file's (v, omega) commands, one a step, at the step rate.
  Status replayCommands(const QString& runFile);
  void giveUp();
  void togglePause();

  // ---- what the window shows (tests) ----
  Light light() const;
  QString commandText() const;
  QString stateText() const;
  bool dataPanelShown() const;
  void setDataPanelShown(bool shown);
  // Reads the run so far into the data panel now (it also follows on a timer while shown).
  void refreshDataPanel();

  // Handles a key of the key table (simKeys()); false for other keys.
  bool handleKey(int key);
  // Help: the Bug1 and Bug2 briefing; the key table.
  void showBriefing();
  void showKeys();

 signals:
  // "Open in Workbench": the main window opens the stored run.
  void openRunRequested(const QString& runName);

 protected:
  void keyPressEvent(QKeyEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildUi();
  void buildMenus();
  void updateState();
  void updateControls();
  void showOutcome(RunOutcome outcome);

 public:
  // The warning shown before an autonomous run whose model lacks groups (empty: none).
  const QString& navigatorWarning() const { return navigatorWarning_; }

 private:
  void reloadModels();
  Status makeNavigator(SimSetup& setup);
  void chooseSceneFile();
  void saveRunCsv();
  void showError(const QString& message);

  QString dbPath_;
  Status dbStatus_;
  std::unique_ptr<workspace::Workspace> workspace_;
  SimSession* session_ = nullptr;
  RunSession* dataSession_ = nullptr;
  StatusPictureView* picture_ = nullptr;
  SignalBarsView* bars_ = nullptr;
  TimelineView* timeline_ = nullptr;
  NavigatorTrackModel* navTrack_ = nullptr;
  NavigatorStripView* navStrips_ = nullptr;
  QWidget* dataPanel_ = nullptr;
  QSplitter* splitter_ = nullptr;
  QLabel* lightLabel_ = nullptr;
  QLabel* commandLabel_ = nullptr;
  QLabel* stateLabel_ = nullptr;
  QLabel* errorLabel_ = nullptr;
  QLabel* outcomeLabel_ = nullptr;
  QString navigatorWarning_;  // the chosen model's missing groups, shown when a run starts
  QComboBox* modeBox_ = nullptr;
  QComboBox* modelBox_ = nullptr;
  QComboBox* controlBox_ = nullptr;  // plan drive, or the thesis strategies (wall following)
  ExperimentPanel* experiment_ = nullptr;
  QWidget* experimentBox_ = nullptr;
  QLabel* sceneLabel_ = nullptr;
  QLineEdit* subjectEdit_ = nullptr;
  QSpinBox* seedBox_ = nullptr;
  QDoubleSpinBox* limitBox_ = nullptr;
  QDoubleSpinBox* rateBox_ = nullptr;
  QPushButton* startButton_ = nullptr;
  QPushButton* pauseButton_ = nullptr;
  QPushButton* stepButton_ = nullptr;
  QPushButton* giveUpButton_ = nullptr;
  QPushButton* dataButton_ = nullptr;
  QPushButton* openButton_ = nullptr;
  QTimer* dataTimer_ = nullptr;
  QString sceneSpec_ = QStringLiteral("practice");
  std::size_t shownSteps_ = 0;
  bool shownFinished_ = false;
};

}  // namespace tactile::gui
