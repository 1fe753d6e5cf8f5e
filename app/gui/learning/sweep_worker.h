// Trains a model, runs a sweep or trains a sweep cell's model on a pool thread, through the same
// Workspace calls as `tactile train` and `tactile sweep`. The worker opens its own connection to
// the database (SQLite's WAL lets the GUI's connection keep reading meanwhile), so the GUI thread
// stays free: scrubbing a run answers while a sweep runs.
//
// Progress arrives as queued signals with an estimate of the time left; cells arrive one by one
// as they finish (each is stored before it is reported). Cancel stops running fits within one EM
// iteration; a cancelled sweep keeps its finished cells.
#pragma once

#include <QElapsedTimer>
#include <QFuture>
#include <QMutex>
#include <QObject>
#include <QString>

#include <atomic>
#include <cstdint>
#include <functional>

#include "analysis/sweep.h"
#include "workspace/workspace.h"

namespace tactile::gui {

struct LearningJobResult {
  enum class Kind { Sweep, Train, CellModel };
  Kind kind = Kind::Sweep;
  bool ok = false;
  bool cancelled = false;
  QString error;             // when !ok and not cancelled
  std::int64_t sweepId = 0;  // sweeps (also set for a failed or cancelled sweep once created)
  std::size_t cells = 0;     // finished cells of a sweep
  QString modelName;         // trainings
  std::vector<workspace::GroupTrainReport> groups;  // trainings
  // A training run with TrainRequest::store false: the outcome, for the dialog to store.
  std::shared_ptr<workspace::TrainOutcome> unstored;
  double seconds = 0.0;
};

class SweepWorker : public QObject {
  Q_OBJECT

 public:
  explicit SweepWorker(QObject* parent = nullptr);
  // Cancels a running job and waits for it.
  ~SweepWorker() override;

  // Each returns false (and starts nothing) while another job runs.
  bool startSweep(const QString& databasePath, const workspace::SweepRequest& request);
  bool startTrain(const QString& databasePath, const workspace::TrainRequest& request);
  // Trains a sweep cell's model; stored under `modelName` (empty: automatic) when `store`, else
  // only handed back (LearningJobResult::unstored), for a model file.
  bool startCellModel(const QString& databasePath, std::int64_t sweepId, std::size_t cellIndex,
                      const QString& modelName, bool store = true);

  bool isRunning() const { return running_; }
  // Blocks until the job is over (tests and shutdown); its signals are still queued.
  void waitForFinished();

 public slots:
  void cancel();

 signals:
  // done / total are cells (sweeps) or groups x iterations (trainings); secondsLeft < 0 while
  // unknown.
  void progressed(qint64 done, qint64 total, double secondsLeft);
  void cellFinished(const tactile::analysis::SweepCellResult& cell);
  void finished(const tactile::gui::LearningJobResult& result);

 private:
  bool launch(std::function<LearningJobResult()> job);
  // A training of any kind on the worker thread: opens the database, runs `train`, fills the
  // result.
  using TrainFunction =
      std::function<Result<workspace::TrainOutcome>(workspace::Workspace&, const ProgressFn&)>;
  LearningJobResult trainingJob(LearningJobResult::Kind kind, const QString& databasePath,
                                const TrainFunction& train);
  ProgressFn progressCallback();
  void report(qint64 done, qint64 total);

  QFuture<void> future_;
  bool running_ = false;
  std::atomic<bool> cancelled_{false};
  QElapsedTimer clock_;
  QMutex progressMutex_;
  qint64 lastDone_ = -1;
  qint64 lastReportMs_ = 0;
};

}  // namespace tactile::gui

Q_DECLARE_METATYPE(tactile::analysis::SweepCellResult)
Q_DECLARE_METATYPE(tactile::gui::LearningJobResult)
