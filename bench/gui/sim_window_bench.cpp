// The simulator window, measured through the real widgets on the offscreen platform:
// - simulated steps per second unthrottled (step rate 0) with the data panel open: the run loop,
//   the status picture, the signal bars, storing every step in the database while it is recorded
//   and the data panel re-reading the run so far four times a second;
// - the same number of steps through the run loop alone (no window, no database), the baseline;
// - key to robot motion: a drive key press until the status picture has been repainted with the
//   robot moved.
//
//   QT_QPA_PLATFORM=offscreen build/bench/gui/tactile_sim_window_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

#include <cstring>

#include "app/gui/runs/run_session_model.h"
#include "app/gui/sim/sim_session.h"
#include "app/gui/sim/sim_window.h"
#include "app/gui/sim/status_picture_view.h"
#include "sim/recorder.h"
#include "sim/scene_source.h"
#include "sim/simulator.h"
#include "sim/world.h"

namespace {

using tactile::gui::SimWindow;

// Steps of the baseline; the window's runs take state.range(0) steps, long enough for the data
// panel to re-read the run several times (it does every 250 ms while it is open).
constexpr std::size_t kSteps = 20000;
// A slow circle in room1: contacts, blocked steps and free driving.
constexpr tactile::sim::Command kDrive{60.0, 0.15};

void BM_SimWindowStepsDataPanelOpen(benchmark::State& state) {
  QTemporaryDir dir;
  SimWindow window(dir.filePath(QStringLiteral("bench.db")));
  window.resize(1400, 900);
  window.setScene(QStringLiteral("room1"));
  window.setStepsPerSecond(0);
  window.setDataPanelShown(true);
  window.show();
  std::size_t total = 0;
  double seconds = 0.0;
  int refreshes = 0;
  QObject::connect(window.dataSession(), &tactile::gui::RunSession::runOpened, &window,
                   [&refreshes] { ++refreshes; });
  for (auto _ : state) {
    if (!window.startRun().ok()) {
      state.SkipWithError("cannot start a run");
      return;
    }
    tactile::gui::SimSession* s = window.session();
    s->setCommandScript(
        std::vector<tactile::sim::Command>(static_cast<std::size_t>(state.range(0)), kDrive));
    QElapsedTimer clock;
    clock.start();
    s->setPaused(false);
    while (s->scriptLeft() > 0 && !s->hasEnded())
      QCoreApplication::processEvents(QEventLoop::AllEvents);
    seconds += clock.nsecsElapsed() * 1e-9;
    total += s->stepCount();
    state.counters["stored_steps"] = static_cast<double>(s->storedSteps());
  }
  state.counters["steps_per_s"] = seconds > 0.0 ? static_cast<double>(total) / seconds : 0.0;
  state.counters["data_panel_steps"] = static_cast<double>(window.dataSession()->stepCount());
  state.counters["data_panel_reads"] = refreshes;
}

void BM_BaselineRunLoopAlone(benchmark::State& state) {
  auto scene = tactile::sim::loadScene("room1");
  auto world = std::make_shared<const tactile::sim::World>(std::move(scene.value()));
  tactile::sim::RunOptions options;
  options.maxSteps = tactile::sim::kMaxStepsPerRun;
  std::size_t total = 0;
  double seconds = 0.0;
  for (auto _ : state) {
    QElapsedTimer clock;
    clock.start();
    auto loop = tactile::sim::RunLoop::start(world, "room1", "bench", options);
    for (std::size_t k = 0; k < kSteps; ++k)
      loop.value()->step(kDrive);
    benchmark::DoNotOptimize(loop.value()->recorder().run().x.data());
    seconds += clock.nsecsElapsed() * 1e-9;
    total += kSteps;
  }
  state.counters["steps_per_s"] = seconds > 0.0 ? static_cast<double>(total) / seconds : 0.0;
}

void BM_KeyToRobotMotion(benchmark::State& state) {
  QTemporaryDir dir;
  SimWindow window(dir.filePath(QStringLiteral("keys.db")));
  window.resize(1400, 900);
  window.setScene(QStringLiteral("room1"));
  window.setStepsPerSecond(10);
  window.show();
  if (!window.startRun().ok()) {
    state.SkipWithError("cannot start a run");
    return;
  }
  QCoreApplication::processEvents();
  // Forward at 20 units/s, then turn left and straight again by turns: every key moves the robot
  // (or is blocked by a wall).
  QTest::keyClick(&window, Qt::Key_Up);
  const int keys[] = {Qt::Key_A, Qt::Key_D};
  int i = 0;
  for (auto _ : state) {
    const double xBefore = window.session()->simulator()->pose().x;
    const double thetaBefore = window.session()->simulator()->pose().theta;
    // The key event, then the paint the event loop would do next.
    QTest::keyClick(&window, static_cast<Qt::Key>(keys[i++ % 2]));
    window.picture()->repaint();
    const auto& pose = window.session()->simulator()->pose();
    if (pose.x == xBefore && pose.theta == thetaBefore && !window.session()->simulator()->blocked())
      state.SkipWithError("the key did not move the robot");
  }
}

BENCHMARK(BM_SimWindowStepsDataPanelOpen)
    ->Arg(20000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK(BM_BaselineRunLoopAlone)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_KeyToRobotMotion)->Unit(benchmark::kMillisecond)->Iterations(200)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QTemporaryDir settingsDir;
  QSettings::setDefaultFormat(QSettings::IniFormat);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
  QCoreApplication::setOrganizationName(QStringLiteral("TactileWorkbenchBench"));
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
