// The workbench on a long run (default 1,000,000 steps), measured through the real main window on
// the offscreen platform: opening the run to a first full paint, moving the cursor one step with
// every view updated (also while a sweep runs on every core), zooming the timelines to the whole
// run, cancelling a running sweep, and the memory the process holds.
//
//   QT_QPA_PLATFORM=offscreen build/bench/gui/tactile_gui_bench --benchmark_repetitions=5
//
// The run is simulator-shaped synthetic data (storage/synthetic_run.h) stored once in a database
// under the temporary folder (TACTILE_BENCH_STEPS and TACTILE_BENCH_DB override size and place;
// TACTILE_BENCH_DB may be a PostgreSQL address, of a database made by `tactile db create`).
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>

#include "app/gui/learning/sweep_worker.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/route_view.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"
#include "sim/recorder.h"
#include "sim/scene_source.h"
#include "sim/world.h"
#include "storage/run_database.h"
#include "storage/synthetic_run.h"

namespace {

using tactile::gui::MainWindow;

std::int64_t benchSteps() {
  const char* env = std::getenv("TACTILE_BENCH_STEPS");
  return env != nullptr ? std::max<std::int64_t>(1000, std::atoll(env)) : 1'000'000;
}

QString benchDatabase() {
  if (const char* env = std::getenv("TACTILE_BENCH_DB")) return QString::fromLocal8Bit(env);
  return QDir::temp().filePath(QStringLiteral("tactile-gui-bench-%1.db").arg(benchSteps()));
}

// Resident and peak resident memory of this process in MiB (Linux /proc).
double memoryMiB(const char* key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(key, 0) == 0) return std::atof(line.c_str() + std::strlen(key)) / 1024.0;
  }
  return 0.0;
}

// Made in a child process (this program with --make-db), so that the memory it takes to build
// the run never counts towards the workbench's.
bool onServer() {
  return tactile::storage::isServerAddress(benchDatabase().toStdString());
}

void makeDatabase() {
  const QString path = benchDatabase();
  if (onServer()) {
    // A server database is filled in place (it must exist; `tactile db create` makes its tables).
    auto db = tactile::storage::RunDatabase::open(path.toStdString());
    if (!db) {
      std::fprintf(stderr, "%s\n", db.errorText().c_str());
      std::abort();
    }
    tactile::RunData run =
        tactile::storage::makeSyntheticRun(static_cast<std::size_t>(benchSteps()), 7);
    const auto out = db.value()->runs().importRun(run, "long");
    if (out.status != tactile::storage::ImportStatus::Imported) {
      std::fprintf(stderr, "%s\n", out.message.c_str());
      std::abort();
    }
    return;
  }
  std::fprintf(stderr, "creating %s (%lld steps)...\n", qPrintable(path),
               static_cast<long long>(benchSteps()));
  const QString partial = path + QStringLiteral(".partial");
  QFile::remove(partial);
  {
    auto db = tactile::storage::RunDatabase::open(partial.toStdString());
    if (!db) std::abort();
    tactile::RunData run =
        tactile::storage::makeSyntheticRun(static_cast<std::size_t>(benchSteps()), 7);
    const auto out = db.value()->runs().importRun(run, "long");
    if (out.status != tactile::storage::ImportStatus::Imported) {
      std::fprintf(stderr, "%s\n", out.message.c_str());
      std::abort();
    }
  }
  QFile::rename(partial, path);
}

bool databaseReady() {
  if (!onServer()) return QFileInfo::exists(benchDatabase());
  auto db = tactile::storage::RunDatabase::open(benchDatabase().toStdString(),
                                                tactile::storage::OpenMode::ReadOnly);
  return db && db.value()->runs().find("long").ok();
}

void ensureDatabase(const char* program) {
  if (databaseReady()) return;
  if (QProcess::execute(QString::fromLocal8Bit(program), {QStringLiteral("--make-db")}) != 0 ||
      !databaseReady()) {
    std::fprintf(stderr, "cannot create %s\n", qPrintable(benchDatabase()));
    std::exit(1);
  }
}

// Lets queued replots and paint requests run, as the event loop would between two key presses.
void settle() {
  QCoreApplication::sendPostedEvents();
  QCoreApplication::processEvents();
}

double baselineMiB = 0.0;   // before the window exists
double firstOpenMiB = 0.0;  // after opening the database and its first run

MainWindow* window() {
  static MainWindow* w = [] {
    baselineMiB = memoryMiB("VmRSS:");
    auto* made = new MainWindow;
    made->resize(1600, 1000);
    made->show();
    if (!made->openDatabase(benchDatabase()).ok()) std::abort();
    settle();
    firstOpenMiB = memoryMiB("VmRSS:");
    return made;
  }();
  return w;
}

void BM_OpenRunToFirstPaint(benchmark::State& state) {
  MainWindow* w = window();
  for (auto _ : state) {
    if (!w->openRun(QStringLiteral("long")).ok()) state.SkipWithError("open failed");
    settle();
    benchmark::DoNotOptimize(w->grab());
  }
  state.counters["rss_before_window_mib"] = baselineMiB;
  state.counters["rss_first_open_mib"] = firstOpenMiB;
  state.counters["rss_mib"] = memoryMiB("VmRSS:");
  state.counters["peak_rss_mib"] = memoryMiB("VmHWM:");
}

void BM_CursorOneStep(benchmark::State& state) {
  MainWindow* w = window();
  tactile::gui::RunSession* s = w->session();
  w->timeline()->showWholeRun();
  s->setCurrentStep(s->stepCount() / 2);
  settle();
  std::int64_t direction = 1;
  for (auto _ : state) {
    s->setCurrentStep(s->currentStep() + direction);
    settle();
    direction = -direction;
  }
}

// The same with the route view following the robot in its close-up (it redraws the visible part of
// the route on every move instead of reusing a cached picture).
void BM_CursorOneStepCloseUp(benchmark::State& state) {
  MainWindow* w = window();
  w->route()->setWholeScene(false);
  settle();
  BM_CursorOneStep(state);
  w->route()->setWholeScene(true);
}

void BM_ZoomTimelinesToWholeRun(benchmark::State& state) {
  MainWindow* w = window();
  tactile::gui::TimelineView* t = w->timeline();
  const std::int64_t mid = w->session()->stepCount() / 2;
  for (auto _ : state) {
    state.PauseTiming();
    t->setVisibleRange({mid - 500, mid + 500});
    settle();
    state.ResumeTiming();
    t->showWholeRun();
    settle();
    benchmark::DoNotOptimize(t->grab());
  }
}

// ---- during a sweep ----
// Three short simulated wall-following runs labelled from their truth (set "truth") are added to
// the benchmark database once; a sweep over them runs on a worker thread, on every core, through
// the same worker as the train-and-sweep dialog, while the main window's cursor moves.
const char* const kSweepRuns[] = {"sweep_room1", "sweep_room2", "sweep_room3"};

void ensureSweepRuns() {
  auto db = tactile::storage::RunDatabase::open(benchDatabase().toStdString());
  if (!db) std::abort();
  for (const char* name : kSweepRuns) {
    if (db.value()->runs().find(name)) continue;
    const std::string scene = std::string(name).substr(6);
    auto loaded = tactile::sim::loadScene(scene);
    if (!loaded) std::abort();
    auto world = std::make_shared<const tactile::sim::World>(std::move(loaded.value()));
    tactile::sim::RunOptions options;
    options.maxSteps = 1500;
    options.stopAtGoal = false;
    auto run = tactile::sim::simulateRun(world, scene, options);
    if (!run) std::abort();
    if (db.value()->runs().importRun(run.value().run, name).status !=
        tactile::storage::ImportStatus::Imported)
      std::abort();
    auto info = db.value()->runs().find(name);
    if (!info || !db.value()->labels().autolabel(info->id, "truth")) std::abort();
  }
}

// Every group, orders 1..64, four forms, three floors: far longer than any measurement.
tactile::workspace::SweepRequest bigSweep() {
  tactile::workspace::SweepRequest request;
  request.labelSet = "truth";
  request.trainRuns = {kSweepRuns[0], kSweepRuns[1]};
  request.testRuns = {kSweepRuns[2]};
  request.name = "bench sweep";
  // Fits that run to the iteration limit with several restarts: every cell takes long enough that
  // the cores stay busy for the whole measurement and a cancel meets fits in mid-run.
  request.grid.restarts = 4;
  request.grid.maxIterations = 400;
  request.grid.tolerance = 1e-12;
  return request;
}

// Waits in the event loop until the worker's job is over.
void waitUntilIdle(tactile::gui::SweepWorker& worker) {
  while (worker.isRunning()) {
    QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
  }
}

void BM_CursorOneStepDuringSweep(benchmark::State& state) {
  MainWindow* w = window();
  ensureSweepRuns();
  tactile::gui::SweepWorker worker;
  if (!worker.startSweep(benchDatabase(), bigSweep())) {
    state.SkipWithError("the sweep did not start");
    return;
  }
  QSignalSpy cells(&worker, &tactile::gui::SweepWorker::cellFinished);
  // Measured once the fits are under way on every core.
  while (cells.count() == 0 && worker.isRunning())
    cells.wait(50);
  tactile::gui::RunSession* s = w->session();
  w->timeline()->showWholeRun();
  s->setCurrentStep(s->stepCount() / 2);
  settle();
  std::int64_t direction = 1;
  double worstMs = 0.0;
  for (auto _ : state) {
    QElapsedTimer clock;
    clock.start();
    s->setCurrentStep(s->currentStep() + direction);
    settle();
    worstMs = std::max(worstMs, static_cast<double>(clock.nsecsElapsed()) / 1e6);
    direction = -direction;
  }
  state.counters["worst_ms"] = worstMs;
  state.counters["sweep_running"] = worker.isRunning() ? 1 : 0;
  worker.cancel();
  waitUntilIdle(worker);
}

// From Cancel to the worker's finished signal, with fits running on every core.
void BM_CancelRunningSweep(benchmark::State& state) {
  window();
  ensureSweepRuns();
  for (auto _ : state) {
    state.PauseTiming();
    tactile::gui::SweepWorker worker;
    QSignalSpy cells(&worker, &tactile::gui::SweepWorker::cellFinished);
    QSignalSpy finished(&worker, &tactile::gui::SweepWorker::finished);
    if (!worker.startSweep(benchDatabase(), bigSweep())) std::abort();
    while (cells.count() == 0 && worker.isRunning())
      cells.wait(50);
    state.ResumeTiming();
    worker.cancel();
    while (finished.count() == 0)
      finished.wait(10);
    state.PauseTiming();
    const auto result = finished.first().at(0).value<tactile::gui::LearningJobResult>();
    state.counters["cells_kept"] = static_cast<double>(result.cells);
    if (!result.cancelled) state.SkipWithError("the sweep was not cancelled");
    state.ResumeTiming();
  }
}

// The baseline: what a viewer that loads whole runs would spend before drawing anything (every
// step's 88 sensor values decoded into memory). Registered last: it leaves the process holding
// the run's memory.
void BM_BaselineLoadWholeRun(benchmark::State& state) {
  auto db = tactile::storage::RunDatabase::open(benchDatabase().toStdString(),
                                                tactile::storage::OpenMode::ReadOnly);
  if (!db) {
    state.SkipWithError("cannot open the database");
    return;
  }
  auto info = db.value()->runs().find("long");
  for (auto _ : state) {
    auto run = db.value()->runs().load(info->id);
    benchmark::DoNotOptimize(run.ok());
    state.counters["run_mib"] =
        run.ok() ? static_cast<double>(run->sensors.size() * sizeof(double)) / (1 << 20) : 0.0;
  }
  state.counters["peak_rss_mib"] = memoryMiB("VmHWM:");
}

BENCHMARK(BM_OpenRunToFirstPaint)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(BM_CursorOneStep)->Unit(benchmark::kMillisecond)->Iterations(200)->UseRealTime();
BENCHMARK(BM_CursorOneStepCloseUp)->Unit(benchmark::kMillisecond)->Iterations(200)->UseRealTime();
BENCHMARK(BM_ZoomTimelinesToWholeRun)->Unit(benchmark::kMillisecond)->Iterations(10)->UseRealTime();
BENCHMARK(BM_CursorOneStepDuringSweep)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(200)
    ->UseRealTime();
BENCHMARK(BM_CancelRunningSweep)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(BM_BaselineLoadWholeRun)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  if (argc == 2 && std::strcmp(argv[1], "--make-db") == 0) {
    makeDatabase();
    return 0;
  }
  QApplication app(argc, argv);
  // Settings go to a private folder so the benchmark never touches a user's.
  QTemporaryDir settingsDir;
  QSettings::setDefaultFormat(QSettings::IniFormat);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
  QCoreApplication::setOrganizationName(QStringLiteral("TactileWorkbenchBench"));
  ensureDatabase(argv[0]);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
