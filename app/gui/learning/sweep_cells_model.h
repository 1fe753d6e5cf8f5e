// The cells of a sweep as a table: one row per cell with its settings (the decision mode among
// them: cells that differ only in it share one fit), its test steps beside its scores ("too few"
// where a class has fewer than kMinTestSteps), times, growing as cells finish. Display text is
// formatted; Qt::UserRole holds the raw number (or text) of each column, so a QSortFilterProxyModel
// with sort role UserRole sorts numerically.
#pragma once

#include <QAbstractTableModel>

#include <utility>
#include <vector>

#include "analysis/sweep.h"

namespace tactile::gui {

class SweepCellsModel : public QAbstractTableModel {
  Q_OBJECT

 public:
  // The scores first: they are what a researcher reads a sweep for.
  enum Column {
    Group,
    Method,
    Form,
    Order,
    Floor,
    Trees,  // boosted trees' settings; empty for the mixtures
    Decision,
    BalancedAccuracy,
    TestSteps,
    Accuracy,
    MacroF1,
    LogLikelihood,
    FitSeconds,
    PredictSeconds,
    Iterations,
    Converged,
    Features,
    Seed,
    Status,
    ColumnCount
  };

  explicit SweepCellsModel(QObject* parent = nullptr);

  // Which settings' columns a view of a sweep with these methods shows: (column, shown) for the
  // covariance, order and floor (only with the mixtures) and the trees' column (only with boosted
  // trees).
  static std::vector<std::pair<int, bool>> settingsColumns(
      const std::vector<analysis::ClassifierMethod>& methods);

  void setCells(std::vector<analysis::SweepCellResult> cells);
  void addCell(const analysis::SweepCellResult& cell);
  void clear();
  const std::vector<analysis::SweepCellResult>& cells() const { return cells_; }
  const analysis::SweepCellResult& cell(int row) const { return cells_.at(row); }

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation,
                      int role = Qt::DisplayRole) const override;

 private:
  std::vector<analysis::SweepCellResult> cells_;
};

}  // namespace tactile::gui
