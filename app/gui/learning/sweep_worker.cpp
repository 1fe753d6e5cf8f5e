#include "app/gui/learning/sweep_worker.h"

#include <QMutexLocker>
#include <QtConcurrent/QtConcurrentRun>

#include <memory>
#include <utility>

namespace tactile::gui {

namespace {

// Progress signals at most this often (a sweep reports after every EM iteration of every fit).
constexpr qint64 kReportIntervalMs = 100;

Result<std::unique_ptr<workspace::Workspace>> openForWork(const QString& path) {
  storage::OpenOptions options;
  options.mode = storage::OpenMode::ReadWrite;
  return workspace::Workspace::open(path.toStdString(), options);
}

}  // namespace

SweepWorker::SweepWorker(QObject* parent) : QObject(parent) {}

SweepWorker::~SweepWorker() {
  cancelled_.store(true);
  future_.waitForFinished();
}

void SweepWorker::cancel() {
  cancelled_.store(true);
}

void SweepWorker::waitForFinished() {
  future_.waitForFinished();
}

void SweepWorker::report(qint64 done, qint64 total) {
  const qint64 now = clock_.elapsed();
  {
    QMutexLocker lock(&progressMutex_);
    if (done == lastDone_ && now - lastReportMs_ < kReportIntervalMs) return;
    lastDone_ = done;
    lastReportMs_ = now;
  }
  const double elapsed = static_cast<double>(now) / 1000.0;
  const double left = done > 0 && total >= done
                          ? elapsed * static_cast<double>(total - done) / static_cast<double>(done)
                          : -1.0;
  QMetaObject::invokeMethod(
      this, [this, done, total, left] { emit progressed(done, total, left); },
      Qt::QueuedConnection);
}

ProgressFn SweepWorker::progressCallback() {
  return [this](std::size_t done, std::size_t total) {
    report(static_cast<qint64>(done), static_cast<qint64>(total));
    return !cancelled_.load();
  };
}

bool SweepWorker::launch(std::function<LearningJobResult()> job) {
  if (running_) return false;
  running_ = true;
  cancelled_.store(false);
  lastDone_ = -1;
  lastReportMs_ = 0;
  clock_.start();
  future_ = QtConcurrent::run([this, job = std::move(job)] {
    LearningJobResult result = job();
    result.seconds = static_cast<double>(clock_.elapsed()) / 1000.0;
    QMetaObject::invokeMethod(
        this,
        [this, result = std::move(result)] {
          running_ = false;
          emit finished(result);
        },
        Qt::QueuedConnection);
  });
  return true;
}

bool SweepWorker::startSweep(const QString& databasePath, const workspace::SweepRequest& request) {
  return launch([this, databasePath, request] {
    LearningJobResult out;
    out.kind = LearningJobResult::Kind::Sweep;
    auto ws = openForWork(databasePath);
    if (!ws) {
      out.error = QString::fromStdString(ws.errorText());
      return out;
    }
    std::size_t finishedCells = 0;
    auto onCell = [this, &finishedCells](const analysis::SweepCellResult& cell) {
      ++finishedCells;
      QMetaObject::invokeMethod(
          this, [this, cell] { emit cellFinished(cell); }, Qt::QueuedConnection);
    };
    auto outcome = ws.value()->sweep(request, onCell, progressCallback());
    out.cells = finishedCells;
    if (!outcome) {
      out.error = QString::fromStdString(outcome.errorText());
      return out;
    }
    out.sweepId = outcome->sweepId;
    out.cancelled = outcome->result.cancelled;
    out.ok = !out.cancelled;
    return out;
  });
}

LearningJobResult SweepWorker::trainingJob(LearningJobResult::Kind kind,
                                           const QString& databasePath,
                                           const TrainFunction& train) {
  LearningJobResult out;
  out.kind = kind;
  auto ws = openForWork(databasePath);
  if (!ws) {
    out.error = QString::fromStdString(ws.errorText());
    return out;
  }
  auto outcome = train(*ws.value(), progressCallback());
  if (!outcome) {
    out.cancelled = cancelled_.load();
    if (!out.cancelled) out.error = QString::fromStdString(outcome.errorText());
    return out;
  }
  out.ok = true;
  out.modelName = QString::fromStdString(outcome->modelName);
  out.groups = outcome->groups;
  if (outcome->modelId == 0)
    out.unstored = std::make_shared<workspace::TrainOutcome>(std::move(outcome.value()));
  return out;
}

bool SweepWorker::startTrain(const QString& databasePath, const workspace::TrainRequest& request) {
  return launch([this, databasePath, request] {
    return trainingJob(LearningJobResult::Kind::Train, databasePath,
                       [&request](workspace::Workspace& ws, const ProgressFn& progress) {
                         return ws.train(request, progress);
                       });
  });
}

bool SweepWorker::startCellModel(const QString& databasePath, std::int64_t sweepId,
                                 std::size_t cellIndex, const QString& modelName, bool store) {
  return launch([this, databasePath, sweepId, cellIndex, modelName, store] {
    LearningJobResult out = trainingJob(
        LearningJobResult::Kind::CellModel, databasePath,
        [&](workspace::Workspace& ws, const ProgressFn& progress) {
          return ws.trainSweepCell(sweepId, cellIndex, modelName.toStdString(), progress, store);
        });
    out.sweepId = sweepId;
    return out;
  });
}

}  // namespace tactile::gui
