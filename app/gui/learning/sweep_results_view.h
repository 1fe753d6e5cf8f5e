// A sweep's results (thesis 4.3-4.4): every cell in a sortable table, filtered by group, and for
// the selected cell its confusion matrix (counts and row percent, coloured), its one-vs-rest and
// per-class correct rates (thesis table 4.19 layout, beside each group's best cell) and its
// contact-pattern error table (thesis table 4.39); rate against floor and against order (figures
// 4.13 and 4.14) and run time against error with the Pareto front, the selected cell ringed. Cells
// stream in while a sweep runs: a table row each, the figures redrawn at most every 250 ms.
#pragma once

#include <QWidget>

#include <cstdint>
#include <optional>

#include "analysis/sweep.h"

class QComboBox;
class QLabel;
class QSplitter;
class QShowEvent;
class QSortFilterProxyModel;
class QTabWidget;
class QTableView;
class QTimer;

namespace tactile::gui {

class SweepCellsModel;
class SweepPlot;
class TableView;

class SweepResultsView : public QWidget {
  Q_OBJECT

 public:
  explicit SweepResultsView(QWidget* parent = nullptr);

  void setSweep(std::int64_t sweepId, const analysis::SweepResult& sweep);
  // A newly finished cell of the shown sweep (cheap: one table row; the visible figure is redrawn
  // at most every 250 ms, hidden ones when their tab is shown).
  void addCell(const analysis::SweepCellResult& cell);
  // The names of the models stored from this sweep's cells (the title lists them).
  void setStoredModels(const QStringList& names);

  const analysis::SweepResult& sweep() const { return sweep_; }
  // Index into sweep().cells of the selected cell, -1 when none.
  int selectedCell() const { return selected_; }
  void selectCell(int cellIndex);
  // Selects the group's best cell (analysis::betterCell, as the report); none: no change.
  void selectBestCell(SensorGroup group);
  // Shows only one group's cells and figures (nullopt: all).
  void setGroupFilter(std::optional<SensorGroup> group);
  // Cells of one decision mode only (nullopt: all). The rate figures always hold one decision:
  // this one, else the selected cell's.
  void setDecisionFilter(std::optional<analysis::DecisionMode> decision);

  // Parts, for tests and the results window.
  QLabel* title() const { return title_; }
  QTableView* cellsView() const { return cellsView_; }
  SweepCellsModel* cellsModel() const { return cells_; }
  QTabWidget* tabs() const { return tabs_; }
  TableView* confusionCounts() const { return counts_; }
  TableView* confusionPercent() const { return percent_; }
  TableView* classRates() const { return rates_; }
  TableView* cellOneVsRest() const { return cellOneVsRest_; }  // the selected cell, table 4.19
  TableView* oneVsRest() const { return oneVsRest_; }          // each group's best cell
  // True while a figure redraw waits for the stream of cells to pause.
  bool figuresPending() const;
  TableView* patterns() const { return patterns_; }
  SweepPlot* rateFloorPlot() const { return floorPlot_; }
  SweepPlot* rateOrderPlot() const { return orderPlot_; }
  SweepPlot* timeErrorPlot() const { return timePlot_; }

 signals:
  void cellSelected(int cellIndex);

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  void refreshFigures();
  void scrollToSelected();
  void refreshCellDetails();
  void refreshTitle();
  void widenTableToTestSteps();

  std::int64_t sweepId_ = 0;
  QStringList storedModels_;
  analysis::SweepResult sweep_;
  int selected_ = -1;
  std::optional<SensorGroup> group_;
  std::optional<analysis::DecisionMode> decision_;
  bool figuresStale_ = true;

  QLabel* title_ = nullptr;
  QSplitter* splitter_ = nullptr;
  QComboBox* groupBox_ = nullptr;
  QComboBox* decisionBox_ = nullptr;
  SweepCellsModel* cells_ = nullptr;
  QSortFilterProxyModel* filtered_ = nullptr;
  QTableView* cellsView_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  QLabel* cellTitle_ = nullptr;
  TableView* counts_ = nullptr;
  TableView* percent_ = nullptr;
  TableView* rates_ = nullptr;
  TableView* cellOneVsRest_ = nullptr;
  TableView* oneVsRest_ = nullptr;
  TableView* patterns_ = nullptr;
  SweepPlot* floorPlot_ = nullptr;
  SweepPlot* orderPlot_ = nullptr;
  SweepPlot* timePlot_ = nullptr;
  QTimer* refreshTimer_ = nullptr;
};

}  // namespace tactile::gui
