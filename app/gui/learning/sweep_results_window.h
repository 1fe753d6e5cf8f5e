// A stored sweep's results in a window of their own (beside the runs, or on a second screen): the
// results views, and the actions on them: export the report (HTML or Markdown, with the plots),
// and train the selected cell's model to store it or write it to a model file. While the sweep
// has cells pending or running (workers fill it, in this process or any other), the window asks
// for its status every second (Workspace::sweepStatus, as `tactile sweep status`), shows the
// counts and the time left, and adds the cells stored since.
#pragma once

#include <QMainWindow>

#include <cstdint>
#include <set>
#include <string>

#include "analysis/sweep.h"
#include "base/error.h"

namespace tactile::workspace {
class Workspace;
}

class QLabel;
class QTimer;

namespace tactile::gui {

class SweepResultsView;
class SweepWorker;
struct LearningJobResult;

class SweepResultsWindow : public QMainWindow {
  Q_OBJECT

 public:
  SweepResultsWindow(workspace::Workspace& workspace, QString databasePath,
                     QWidget* parent = nullptr);
  ~SweepResultsWindow() override;

  // Loads a stored sweep (its cells so far) and shows it.
  Status showSweep(std::int64_t sweepId);
  // A cell finished by a sweep that is still running: shown at once when it is this window's sweep.
  void addCell(std::int64_t sweepId, const analysis::SweepCellResult& cell);
  // Reads the sweep's status and the cells stored since the last look (the timer's work).
  void refreshStatus();

  std::int64_t sweepId() const { return sweepId_; }
  const analysis::SweepResult& sweep() const { return sweep_; }
  SweepResultsView* view() const { return view_; }
  SweepWorker* worker() const { return worker_; }
  // Done, running, pending and failed cells and the time left; what went wrong.
  QLabel* statusLabel() const { return status_; }
  // Whether the window is following a sweep that workers are still filling.
  bool following() const;

  // Writes the sweep's report (style chosen by the suffix: .html, .htm, .md, .csv, .txt).
  Status exportReport(const QString& path);
  // Trains the selected cell's model in the background and stores it under `name` (empty:
  // automatic); when `file` is not empty the model is also written there.
  bool trainSelectedCell(const QString& name, const QString& file = {});

 signals:
  void modelStored(const QString& name);

 protected:
  void showEvent(QShowEvent* event) override;
  void hideEvent(QHideEvent* event) override;

 private:
  void showCell(const analysis::SweepCellResult& cell);
  void updateTitle(const std::string& name, const std::string& state);
  void chooseReportFile();
  void chooseModelFile();
  // The name Store Model of Cell gives the selected cell's model when none is typed.
  QString automaticModelName() const;
  void onModelTrained(const LearningJobResult& result);

  workspace::Workspace& workspace_;
  QString databasePath_;
  std::int64_t sweepId_ = 0;
  analysis::SweepResult sweep_;
  nlohmann::json configuration_;
  SweepResultsView* view_ = nullptr;
  SweepWorker* worker_ = nullptr;
  QString pendingModelFile_;
  QStringList storedModels_;  // stored from this sweep since it was shown
  QLabel* status_ = nullptr;
  QTimer* poll_ = nullptr;
  std::set<std::string> shownCells_;  // the settings of the cells shown (their JSON)
  std::string shownState_;
};

}  // namespace tactile::gui
