// The workbench on a long run (default 1,000,000 steps), measured through the real main window on
// the offscreen platform: opening the run to a first full paint, moving the cursor one step with
// every view updated, zooming the timelines to the whole run, and the memory the process holds.
//
//   QT_QPA_PLATFORM=offscreen build/bench/gui/tactile_gui_bench --benchmark_repetitions=5
//
// The run is simulator-shaped synthetic data (storage/synthetic_run.h) stored once in a database
// under the temporary folder (TACTILE_BENCH_STEPS and TACTILE_BENCH_DB override size and place).
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>

#include "app/gui/main_window.h"
#include "app/gui/runs/route_view.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"
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
void makeDatabase() {
  const QString path = benchDatabase();
  std::fprintf(stderr, "creating %s (%lld steps)...\n", qPrintable(path),
               static_cast<long long>(benchSteps()));
  const QString partial = path + QStringLiteral(".partial");
  QFile::remove(partial);
  {
    auto db = tactile::storage::RunDatabase::open(partial.toStdString());
    if (!db) std::abort();
    tactile::RunData run =
        tactile::storage::makeSyntheticRun(static_cast<std::size_t>(benchSteps()), 7);
    const auto out = db.value()->importRun(run, "long");
    if (out.status != tactile::storage::ImportStatus::Imported) {
      std::fprintf(stderr, "%s\n", out.message.c_str());
      std::abort();
    }
  }
  QFile::rename(partial, path);
}

void ensureDatabase(const char* program) {
  if (QFileInfo::exists(benchDatabase())) return;
  if (QProcess::execute(QString::fromLocal8Bit(program), {QStringLiteral("--make-db")}) != 0 ||
      !QFileInfo::exists(benchDatabase())) {
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
  auto info = db.value()->findRun("long");
  for (auto _ : state) {
    auto run = db.value()->loadRun(info->id);
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
