// One report table (analysis::Table, the same tables `tactile report` prints) in a widget: its
// title, a sortable table with numbers right-aligned and sorted as numbers, and Export CSV, which
// writes exactly the CSV the report writes. An optional hook colours cells.
#pragma once

#include <QColor>
#include <QWidget>

#include <functional>
#include <optional>

#include "analysis/report.h"
#include "base/error.h"

class QLabel;
class QPushButton;
class QStandardItemModel;
class QTableView;

namespace tactile::gui {

class TableView : public QWidget {
  Q_OBJECT

 public:
  // Background of a body cell (row, column of the table), or none.
  using CellColour = std::function<std::optional<QColor>(int row, int column)>;

  explicit TableView(QWidget* parent = nullptr);

  void setTable(const analysis::Table& table, CellColour colour = {});
  const analysis::Table& table() const { return table_; }
  // Shown instead of a table (no data, a failed cell); nothing to export then.
  void setMessage(const QString& message);

  // As tall as its rows (a small table in a page with others) instead of filling the space.
  void setFitHeight(bool fit);

  QTableView* view() const { return view_; }
  // The text and background shown in a body cell, in the table's own row order (for tests).
  QString cellText(int row, int column) const;
  std::optional<QColor> cellBackground(int row, int column) const;

  // Writes table().render(Csv) to `path` (atomically).
  Status exportCsv(const QString& path) const;

 private:
  void chooseCsvFile();

  analysis::Table table_;
  QLabel* title_ = nullptr;
  QPushButton* exportButton_ = nullptr;
  QTableView* view_ = nullptr;
  QStandardItemModel* model_ = nullptr;
};

}  // namespace tactile::gui
