// One run in the simulator window: the scene, the run loop of sim/ (the same stepping as
// `tactile simulate`), the driver (the person's held command, or an autonomous driver), the step
// clock, and the run stored in the workspace's database while it is recorded (workspace
// RunRecording). Qt Core only; the window's views read its state after each `stepped` signal.
//
// The protocol (thesis 3.1): practice mode may show the whole scene; experiment mode draws start
// and goal from a seed, hides the scene, has a time limit (simulated time: steps x dt) and needs
// the subject's name. The outcome (`success`, `gave-up`, `timeout`) and the subject go into the
// run's metadata together with `mode`, `driver` and, in experiment mode, `seed` and `time_limit`.
//
// Autonomous mode: a driver (the chapter-5 navigator) drives from the start `tactile navigate
// --seeds SEED` uses (nav::drawStart), under the time limit; `seed`, `time_limit` and, for the
// navigator, `status_source` are recorded, and every step carries the navigator's strategy and
// status as the x_ columns `tactile navigate` writes (nav/navigate.h).
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "base/error.h"
#include "run/run.h"
#include "sim/driver.h"
#include "sim/recorder.h"
#include "sim/scene.h"

namespace tactile::workspace {
class Workspace;
class RunRecording;
}  // namespace tactile::workspace

namespace tactile::nav {
class Navigator;
}

namespace tactile::gui {

enum class SimMode { Practice, Experiment, Autonomous };
QString simModeName(SimMode mode);   // "practice", "experiment", "autonomous" (metadata values)
QString simModeTitle(SimMode mode);  // the same, translated (what the window shows)

struct SimSetup {
  SimMode mode = SimMode::Practice;
  // A built-in scene name, a scene JSON file or random:N:SEED.
  QString scene = QStringLiteral("practice");
  QString subject;         // needed in experiment mode; recorded as `subject`
  std::uint64_t seed = 1;  // experiment mode: start and goal are drawn from it; autonomous: start
  double timeLimitSeconds = 600.0;  // experiment mode, simulated seconds
  double dtSeconds = 0.1;
  // Autonomous mode: the driver (its name() is recorded as `driver` and `subject`).
  std::shared_ptr<sim::Driver> driver;
  QString runName;  // empty: "<mode>_<scene>[_<subject>]", made unique
};

class SimSession : public QObject {
  Q_OBJECT

 public:
  // Steps are written to the database at the latest this long after they were taken, or when
  // this many wait (a killed window loses at most that much).
  static constexpr int kFlushMilliseconds = 100;
  static constexpr std::size_t kFlushSteps = 256;
  static constexpr double kDefaultStepsPerSecond = 10.0;  // real time at dt 0.1

  explicit SimSession(QObject* parent = nullptr);
  ~SimSession() override;

  // The database runs are stored in (not owned; must outlive the run).
  void setWorkspace(workspace::Workspace* workspace);
  workspace::Workspace* workspace() const { return workspace_; }

  // Ends a run in progress (gave-up; a run without a step is dropped from the database) and
  // starts a new one, paused until setPaused(false) or a drive key. On a failure before the
  // scene and start are set up nothing changes.
  Status start(const SimSetup& setup);
  bool isStarted() const { return loop_ != nullptr; }
  const SimSetup& setup() const { return setup_; }
  SimMode mode() const { return setup_.mode; }
  // Whether the whole scene may be shown (not in experiment mode).
  bool mayShowScene() const { return setup_.mode != SimMode::Experiment; }

  // ---- the person's command (manual modes) ----
  const sim::Command& command() const { return command_; }
  // Sets the command; while the run goes on (not paused) it takes a step at once with it and
  // restarts the step clock, so a key moves the robot within the frame it was pressed in.
  void setCommand(const sim::Command& command);

  // Commands taken one a step before the person's own (a recorded run's, replayed); the run
  // pauses when they run out. Cleared by start().
  void setCommandScript(std::vector<sim::Command> commands);
  std::size_t scriptLeft() const { return script_.size() - scriptPos_; }

  // ---- the clock ----
  // Steps per second of real time; 0 steps as fast as the machine allows.
  void setStepsPerSecond(double rate);
  double stepsPerSecond() const { return rate_; }
  bool isPaused() const { return paused_; }
  void setPaused(bool paused);
  // One step now (paused or not); false when no run goes on.
  bool stepOnce();
  // Up to `steps` steps now, without the clock, then stores them (tests, screenshots); returns
  // the steps taken.
  std::size_t advance(std::size_t steps);

  // ---- ending ----
  // The person gives up: the run ends with `gave-up`.
  void giveUp();
  // Ends the run with `outcome` unless it has ended.
  void endRun(RunOutcome outcome);
  bool hasEnded() const;
  std::optional<RunOutcome> outcome() const;

  // ---- state for the views ----
  const sim::Simulator* simulator() const;
  const sim::Scene* scene() const;
  // The run so far (all of it once ended).
  const RunData* run() const;
  std::size_t stepCount() const;
  double goalDistance() const;
  double elapsedSeconds() const;
  // Experiment mode: simulated seconds left; nullopt without a limit.
  std::optional<double> timeLeftSeconds() const;
  // The stored run's name (empty before start or without a database).
  QString runName() const;
  // Steps already written to the database.
  std::size_t storedSteps() const;
  QString lastError() const { return lastError_; }

 signals:
  void started();
  void stepped();  // after a step or a batch of steps
  void pausedChanged(bool paused);
  void runEnded(tactile::RunOutcome outcome);
  void errorOccurred(const QString& message);

 private:
  void tick();
  bool stepInternal();
  void flush(bool force);
  void finishStored();
  void restartClock();
  void discardEmptyRun();

  workspace::Workspace* workspace_ = nullptr;
  SimSetup setup_;
  const nav::Navigator* navigator_ = nullptr;  // setup_.driver when it is the navigator
  // setup_.driver when it is a navigator on the simulator's truth: fed the truth every step, as
  // `tactile navigate --status truth` feeds it.
  nav::Navigator* truthFed_ = nullptr;
  std::unique_ptr<sim::RunLoop> loop_;
  std::unique_ptr<workspace::RunRecording> recording_;
  RunData finished_;  // the whole run once it has ended
  bool hasFinished_ = false;
  sim::Command command_;
  std::vector<sim::Command> script_;
  std::size_t scriptPos_ = 0;
  double rate_ = kDefaultStepsPerSecond;
  bool paused_ = true;
  QTimer timer_;
  QElapsedTimer sinceFlush_;
  QString lastError_;
};

}  // namespace tactile::gui
