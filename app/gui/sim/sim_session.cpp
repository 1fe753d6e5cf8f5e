#include "app/gui/sim/sim_session.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <utility>

#include "nav/navigate.h"
#include "nav/navigator.h"
#include "run/builtin_scenes.h"
#include "sim/scene_source.h"
#include "sim/start_goal.h"
#include "sim/world.h"
#include "workspace/run_recording.h"
#include "workspace/workspace.h"

namespace tactile::gui {

QString simModeName(SimMode mode) {
  switch (mode) {
    case SimMode::Practice:
      return QStringLiteral("practice");
    case SimMode::Experiment:
      return QStringLiteral("experiment");
    case SimMode::Autonomous:
      return QStringLiteral("autonomous");
  }
  return {};
}

QString simModeTitle(SimMode mode) {
  switch (mode) {
    case SimMode::Practice:
      return SimSession::tr("practice");
    case SimMode::Experiment:
      return SimSession::tr("experiment");
    case SimMode::Autonomous:
      return SimSession::tr("autonomous");
  }
  return {};
}

namespace {

// What a run name may hold (docs/file-formats.md: no comma or line break); other characters of
// a subject's or scene's name are kept.
QString namePart(QString text) {
  for (QChar& c : text) {
    if (c == QLatin1Char(',') || c == QLatin1Char('/') || c == QLatin1Char('\\') || c.isSpace() ||
        c.category() == QChar::Other_Control)
      c = QLatin1Char('-');
  }
  return text;
}

}  // namespace

SimSession::SimSession(QObject* parent) : QObject(parent) {
  timer_.setTimerType(Qt::PreciseTimer);
  connect(&timer_, &QTimer::timeout, this, &SimSession::tick);
}

SimSession::~SimSession() {
  // A window closed mid-run keeps what it recorded; the run stays `unknown` as after a crash
  // unless it had ended. A run without a step is not kept.
  if (loop_ && !hasFinished_) {
    if (stepCount() == 0) {
      discardEmptyRun();
    } else {
      flush(true);
    }
  }
}

void SimSession::discardEmptyRun() {
  if (!recording_ || workspace_ == nullptr || recording_->storedSteps() != 0) return;
  (void)workspace_->runStore().remove(recording_->runId());
  recording_.reset();
}

void SimSession::setWorkspace(workspace::Workspace* workspace) {
  workspace_ = workspace;
}

Status SimSession::start(const SimSetup& setup) {
  const std::string spec = setup.scene.toStdString();
  if (setup.mode == SimMode::Experiment && setup.subject.trimmed().isEmpty()) {
    return Error(tr("An experiment run needs the subject's name.").toStdString());
  }
  if (setup.subject.contains(QLatin1Char('\n')) || setup.subject.contains(QLatin1Char('\r'))) {
    return Error(tr("A subject's name must be one line.").toStdString());
  }
  if (setup.mode == SimMode::Autonomous && !setup.driver) {
    return Error(tr("Autonomous mode needs a driver.").toStdString());
  }
  if (!(setup.dtSeconds > 0.0 && setup.dtSeconds <= 1.0)) {
    return Error(tr("The step length must be in (0, 1] seconds.").toStdString());
  }
  Result<sim::Scene> loaded = sim::loadScene(spec);
  if (!loaded) return loaded.error();
  sim::Scene scene = std::move(loaded.value());
  // Seed 0: the scene's own start and goal.
  if (setup.mode == SimMode::Experiment && setup.seed != 0) {
    Result<sim::Scene> drawn = sim::drawStartGoal(scene, setup.seed);
    if (!drawn) return drawn.error();
    scene = std::move(drawn.value());
  }
  if (setup.mode == SimMode::Autonomous) {
    // The navigator starts where `tactile navigate --seeds SEED` starts it (nav::drawStart), so a
    // seed tried on the command line can be watched here.
    scene.start = nav::drawStart(std::make_shared<const sim::World>(scene), setup.seed);
  }
  // Built-in scenes and random:N:SEED are recorded by what was typed, files by their scene name
  // (as `tactile simulate` records them); the scene's JSON is stored with the run either way.
  const bool byName = spec.starts_with("random:") || builtinSceneJson(spec).has_value();
  const std::string sceneValue = byName ? spec : scene.name;
  auto world = std::make_shared<const sim::World>(scene);

  sim::RunOptions options;
  options.config.dtSeconds = setup.dtSeconds;
  options.seed = setup.seed;
  options.maxSteps = sim::kMaxStepsPerRun;
  if (setup.mode == SimMode::Experiment || setup.mode == SimMode::Autonomous) {
    if (!(setup.timeLimitSeconds > 0.0))
      return Error(tr("The time limit must be positive.").toStdString());
    options.maxSteps = static_cast<std::size_t>(
        std::clamp(std::ceil(setup.timeLimitSeconds / setup.dtSeconds - 1e-9), 1.0,
                   static_cast<double>(sim::kMaxStepsPerRun)));
  }
  const std::string driverName =
      setup.mode == SimMode::Autonomous ? setup.driver->name() : std::string("manual");
  const std::string subject =
      setup.subject.trimmed().isEmpty() ? driverName : setup.subject.trimmed().toStdString();
  Result<std::unique_ptr<sim::RunLoop>> begunLoop =
      sim::RunLoop::start(world, sceneValue, subject, options);
  if (!begunLoop) return begunLoop.error();
  std::unique_ptr<sim::RunLoop> loop = std::move(begunLoop.value());
  sim::Recorder& recorder = loop->recorder();
  recorder.setMeta("mode", simModeName(setup.mode).toStdString());
  recorder.setMeta("driver", driverName);
  if (setup.mode != SimMode::Practice) recorder.setMeta("seed", std::to_string(setup.seed));
  const auto* navigator = setup.mode == SimMode::Autonomous
                              ? dynamic_cast<const nav::Navigator*>(setup.driver.get())
                              : nullptr;
  if (navigator != nullptr) {
    // The navigator's state per step, as `tactile navigate` records it.
    recorder.setMeta("status_source",
                     std::string(nav::statusSourceName(navigator->config().source)));
    recorder.setExtraColumns(nav::navigatorColumns());
  }
  if (setup.mode != SimMode::Practice) {
    recorder.setMeta("time_limit", sim::formatNumber(setup.timeLimitSeconds));
  }

  // The run so far ends here: given up, or dropped from the database when it has no step.
  if (loop_ && !hasFinished_) {
    if (stepCount() == 0) {
      discardEmptyRun();
      timer_.stop();
      loop_.reset();
    } else {
      endRun(RunOutcome::GaveUp);
    }
  }

  std::unique_ptr<workspace::RunRecording> recording;
  if (workspace_ != nullptr) {
    QString base = setup.runName;
    if (base.isEmpty()) {
      const QString sceneName = namePart(QString::fromStdString(byName ? spec : scene.name));
      base = simModeName(setup.mode) + QLatin1Char('_') + sceneName;
      if (!setup.subject.trimmed().isEmpty())
        base += QLatin1Char('_') + namePart(setup.subject.trimmed());
    }
    Result<std::string> name = workspace::freeRunName(*workspace_, base.toStdString());
    if (!name) return name.error();
    const std::string sceneJson = sim::sceneToJson(world->scene());
    storage::SceneResolver resolver =
        [sceneValue, sceneJson](const std::string& value) -> std::optional<std::string> {
      if (value == sceneValue) return sceneJson;
      return std::nullopt;
    };
    if (byName && spec.starts_with("random:")) {
      resolver = [](const std::string& value) { return sim::proceduralSceneJson(value); };
    }
    Result<std::unique_ptr<workspace::RunRecording>> begun =
        workspace::RunRecording::begin(*workspace_, name.value(), recorder.run(), true, resolver);
    if (!begun) return begun.error();
    recording = std::move(begun.value());
  }

  timer_.stop();
  setup_ = setup;
  navigator_ = navigator;
  truthFed_ = navigator != nullptr && navigator->config().source == nav::StatusSource::Truth
                  ? dynamic_cast<nav::Navigator*>(setup_.driver.get())
                  : nullptr;
  loop_ = std::move(loop);
  recording_ = std::move(recording);
  finished_ = RunData();
  hasFinished_ = false;
  command_ = {};
  script_.clear();
  scriptPos_ = 0;
  lastError_.clear();
  sinceFlush_.start();
  const bool wasPaused = paused_;
  paused_ = true;
  emit started();
  emit stepped();
  if (!wasPaused) emit pausedChanged(true);
  return Status::success();
}

void SimSession::setCommand(const sim::Command& command) {
  command_ = command;
  if (loop_ && !hasFinished_ && !paused_) {
    // The key shows at once: one step now, and the clock starts over from this step.
    stepInternal();
    flush(false);
    emit stepped();
    restartClock();
  }
}

void SimSession::setCommandScript(std::vector<sim::Command> commands) {
  script_ = std::move(commands);
  scriptPos_ = 0;
}

void SimSession::setStepsPerSecond(double rate) {
  rate_ = std::max(0.0, rate);
  restartClock();
}

void SimSession::setPaused(bool paused) {
  if (paused == paused_) return;
  if (!paused && (!loop_ || hasFinished_)) return;
  paused_ = paused;
  if (paused_) {
    timer_.stop();
    flush(true);
  } else {
    restartClock();
  }
  emit pausedChanged(paused_);
}

void SimSession::restartClock() {
  if (paused_ || !loop_ || hasFinished_) {
    timer_.stop();
    return;
  }
  timer_.start(rate_ > 0.0 ? std::max(1, static_cast<int>(std::lround(1000.0 / rate_))) : 0);
}

bool SimSession::stepOnce() {
  if (!loop_ || hasFinished_) return false;
  const bool took = stepInternal();
  flush(false);
  emit stepped();
  return took;
}

std::size_t SimSession::advance(std::size_t steps) {
  std::size_t taken = 0;
  while (taken < steps && loop_ && !hasFinished_ && stepInternal())
    ++taken;
  flush(true);
  emit stepped();
  return taken;
}

void SimSession::tick() {
  if (!loop_ || hasFinished_ || paused_) {
    timer_.stop();
    return;
  }
  if (rate_ > 0.0) {
    stepInternal();
  } else {
    // As fast as possible, in slices of about 10 ms so the window stays responsive.
    QElapsedTimer slice;
    slice.start();
    while (!hasFinished_ && !paused_ && slice.elapsed() < 10 && stepInternal()) {
    }
  }
  flush(false);
  emit stepped();
}

bool SimSession::stepInternal() {
  if (!loop_ || hasFinished_) return false;
  std::optional<RunOutcome> ended;
  if (setup_.mode == SimMode::Autonomous) {
    if (truthFed_ != nullptr) {
      nav::Observation observation;
      static_cast<sim::Observation&>(observation) = loop_->observation();
      observation.truth = &loop_->simulator().truth();
      const sim::Command command = truthFed_->step(observation);
      ended = loop_->step(command, *truthFed_);
    } else {
      ended = loop_->step(*setup_.driver);
    }
    sim::Recorder& recorder = loop_->recorder();
    if (navigator_ != nullptr) nav::appendNavigatorState(*navigator_, recorder.extraValues());
    command_ = {recorder.run().v.back(), recorder.run().omega.back()};
  } else {
    const bool scripted = scriptPos_ < script_.size();
    if (scripted) command_ = script_[scriptPos_++];
    ended = loop_->step(command_);
    if (scripted && scriptPos_ == script_.size() && !ended) setPaused(true);
  }
  if (ended) endRun(*ended);
  return true;
}

void SimSession::flush(bool force) {
  if (!recording_ || recording_->finished() || !loop_ || hasFinished_) return;
  const RunData& run = loop_->recorder().run();
  const std::size_t waiting = run.stepCount() - recording_->storedSteps();
  if (waiting == 0) return;
  if (!force && waiting < kFlushSteps && sinceFlush_.elapsed() < kFlushMilliseconds) return;
  Status written = recording_->append(run);
  sinceFlush_.restart();
  if (!written) {
    lastError_ = QString::fromStdString(written.errorText());
    emit errorOccurred(lastError_);
  }
}

void SimSession::giveUp() {
  endRun(RunOutcome::GaveUp);
}

void SimSession::endRun(RunOutcome outcome) {
  if (!loop_ || hasFinished_) return;
  loop_->end(outcome);
  timer_.stop();
  finishStored();
  const bool wasPaused = paused_;
  paused_ = true;
  if (!wasPaused) emit pausedChanged(true);
  emit stepped();
  emit runEnded(outcome);
}

void SimSession::finishStored() {
  hasFinished_ = true;
  finished_ = loop_->take();  // outcome set, truth smoothed as `tactile simulate` smooths it
  if (!recording_) return;
  Status done = recording_->finish(finished_);
  if (!done) {
    lastError_ = QString::fromStdString(done.errorText());
    emit errorOccurred(lastError_);
  }
}

bool SimSession::hasEnded() const {
  return hasFinished_;
}

std::optional<RunOutcome> SimSession::outcome() const {
  return loop_ ? loop_->outcome() : std::nullopt;
}

const sim::Simulator* SimSession::simulator() const {
  return loop_ ? &loop_->simulator() : nullptr;
}

const sim::Scene* SimSession::scene() const {
  return loop_ ? &loop_->simulator().world().scene() : nullptr;
}

const RunData* SimSession::run() const {
  if (!loop_) return nullptr;
  return hasFinished_ ? &finished_ : &loop_->recorder().run();
}

std::size_t SimSession::stepCount() const {
  const RunData* r = run();
  return r != nullptr ? r->stepCount() : 0;
}

double SimSession::goalDistance() const {
  return loop_ ? loop_->goalDistance() : 0.0;
}

double SimSession::elapsedSeconds() const {
  return static_cast<double>(stepCount()) * setup_.dtSeconds;
}

std::optional<double> SimSession::timeLeftSeconds() const {
  if (!loop_ || setup_.mode == SimMode::Practice) return std::nullopt;
  return std::max(
      0.0, static_cast<double>(loop_->options().maxSteps) * setup_.dtSeconds - elapsedSeconds());
}

QString SimSession::runName() const {
  return recording_ ? QString::fromStdString(recording_->name()) : QString();
}

std::size_t SimSession::storedSteps() const {
  return recording_ ? recording_->storedSteps() : 0;
}

}  // namespace tactile::gui
