// Train and sweep: a researcher picks a label set, the training and test runs, the groups, the
// methods and the grid (orders, covariance forms, variance floors), the features and the seeds,
// then trains one model or runs a sweep in the background. A progress bar with the time left and
// Cancel follow the work; finished cells stream into a sortable table. The work runs through the
// same Workspace calls as `tactile train` and `tactile sweep`, so both store the same numbers.
#pragma once

#include <QDialog>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/error.h"
#include "workspace/workspace.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSortFilterProxyModel;
class QSpinBox;
class QStackedWidget;
class QTableView;
class QTableWidget;

namespace tactile::gui {

class SweepCellsModel;
class SweepWorker;
struct LearningJobResult;

class TrainingDialog : public QDialog {
  Q_OBJECT

 public:
  TrainingDialog(workspace::Workspace& workspace, QString databasePath, QWidget* parent = nullptr);
  ~TrainingDialog() override;
  // Closing remembers the label set and the grid for the next opening.
  void done(int result) override;
  // The plan's estimate of the sweep's seconds (-1: no stored cell to time it by).
  double plannedSeconds() const { return plannedSeconds_; }

  // Re-reads label sets and runs; keeps the chosen set when it still exists.
  void reload();
  void setLabelSet(const QString& name);

  // The request the form describes, or what is wrong with it.
  Result<workspace::SweepRequest> sweepRequest() const;
  // A training with the first value of every grid list.
  Result<workspace::TrainRequest> trainRequest() const;

  // Role of a run in the split.
  enum class RunRole { Train, Test, Unused };
  void setRunRole(const QString& run, RunRole role);
  // Fills the grid fields: comma-separated lists as in the CLI.
  void setGrid(const QString& orders, const QString& floors, const QString& seeds);
  void setGroupsChecked(const std::vector<SensorGroup>& groups);
  void setFormsChecked(const std::vector<analysis::CovarianceForm>& forms);

  // Asked before a trained model is stored when a group scored 0 or had no test data (the text
  // names them); true stores it. Default: a question box. Tests set their own answer.
  void setStoreQuestion(std::function<bool(const QString&)> ask) { askToStore_ = std::move(ask); }

  SweepWorker* worker() const { return worker_; }
  SweepCellsModel* cellsModel() const { return cells_; }
  QProgressBar* progressBar() const { return progress_; }
  QLabel* statusLabel() const { return status_; }
  QTableView* cellsView() const { return cellsView_; }
  // The plan under the form: the number of cells and the time they should take, or what is
  // wrong with the form; follows every edit.
  QLabel* planLabel() const { return plan_; }
  // A training's result: one row per group (shown instead of the cells after Train model).
  QTableWidget* trainResultView() const { return trainResult_; }
  // Whether the form (set, runs, grid) can be edited: not while a job runs.
  bool formEditable() const;
  // After Plan for workers: the commands that fill the planned sweep, to copy.
  QPlainTextEdit* workerCommands() const { return commands_; }

 public slots:
  void startSweep();
  // Stores the sweep with every cell pending for `tactile sweep work` processes or a Slurm job
  // array (Workspace::planSweep, as `tactile sweep plan`) and shows their commands.
  void planForWorkers();
  void startTrain();
  void cancel();

 signals:
  // A sweep stored cells (finished or cancelled); the main window opens its results.
  void sweepStored(qint64 sweepId);
  // A sweep was planned for workers; the main window opens its results, which fill as they land.
  void sweepPlanned(qint64 sweepId);
  void modelTrained(const QString& name);
  // Any job is over (ok, cancelled or failed).
  void jobFinished();

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildUi();
  void fillRuns();
  void setBusy(bool busy);
  void onProgress(qint64 done, qint64 total, double secondsLeft);
  void onFinished(const LearningJobResult& result);
  std::vector<std::string> runsWithRole(RunRole role) const;
  Result<analysis::SweepGrid> grid() const;
  void showError(const QString& message);
  void refreshPlan();
  void refreshTiming();
  // Counts the labelled contact steps of the marked runs (when the runs or the label set change).
  void refreshRows();
  void rememberForm() const;
  void restoreForm();
  void showTrainResult(const LearningJobResult& result);

  workspace::Workspace& workspace_;
  QString databasePath_;
  workspace::TrainRequest pendingTrain_;  // the running training (stored after it, if asked)
  std::function<bool(const QString&)> askToStore_;
  SweepWorker* worker_ = nullptr;
  SweepCellsModel* cells_ = nullptr;
  QSortFilterProxyModel* sorted_ = nullptr;

  QComboBox* labelSet_ = nullptr;
  QTableWidget* runs_ = nullptr;
  QComboBox* split_ = nullptr;
  std::vector<QCheckBox*> groups_;
  QCheckBox* gaussian_ = nullptr;
  QCheckBox* gmm_ = nullptr;
  QCheckBox* gbt_ = nullptr;
  QLineEdit* trees_ = nullptr;  // boosted trees' settings, comma-separated lists
  QLineEdit* depths_ = nullptr;
  QLineEdit* learningRates_ = nullptr;
  QLineEdit* minChildWeights_ = nullptr;
  QWidget* treeRow_ = nullptr;
  std::vector<QCheckBox*> forms_;
  std::vector<QCheckBox*> features_;
  std::vector<QCheckBox*> decisions_;  // step, online, offline
  QLineEdit* orders_ = nullptr;
  QLineEdit* floors_ = nullptr;
  QLineEdit* seeds_ = nullptr;
  QLineEdit* name_ = nullptr;
  QSpinBox* threads_ = nullptr;
  QCheckBox* groupDefaults_ = nullptr;  // Train model: each group's defaults, or the lists' firsts
  QDoubleSpinBox* emissionWeight_ = nullptr;  // Train model: 0 = each group's default
  QPushButton* sweepButton_ = nullptr;
  QPushButton* planButton_ = nullptr;
  QPlainTextEdit* commands_ = nullptr;
  QPushButton* copyCommands_ = nullptr;
  QPushButton* trainButton_ = nullptr;
  QPushButton* cancelButton_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_ = nullptr;
  QTableView* cellsView_ = nullptr;
  QWidget* form_ = nullptr;
  QLabel* plan_ = nullptr;
  bool statusIsError_ = false;  // the status shows a validation or job error
  // The cost model of the plan's estimate: seconds per unit of work (rows x components x the
  // covariance's cost per row), calibrated on the stored sweeps' cells (-1: none stored).
  double secondsPerUnit_ = -1;
  double plannedSeconds_ = -1;
  int timedCells_ = 0;  // the stored cells it was calibrated on
  // Labelled contact steps per group in the marked training and test runs.
  std::array<std::size_t, kGroupCount> trainRows_{};
  std::array<std::size_t, kGroupCount> testRows_{};
  QLabel* unscorable_ = nullptr;     // the groups the test runs cannot score
  QPushButton* leaveOut_ = nullptr;  // unticks them
  std::vector<SensorGroup> unscorableGroups_;
  QStackedWidget* resultStack_ = nullptr;
  QTableWidget* trainResult_ = nullptr;
};

}  // namespace tactile::gui
