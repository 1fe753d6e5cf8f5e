// The runs dock's content: a filter box over the database's runs (name, scene, subject, steps,
// outcome, labelled share), sortable by any column. Choosing a row opens that run.
#pragma once

#include <QWidget>

#include <string>

class QLineEdit;
class QSortFilterProxyModel;
class QTableView;

namespace tactile::gui {

class RunListModel;

class RunListView : public QWidget {
  Q_OBJECT

 public:
  RunListView(RunListModel* model, QWidget* parent = nullptr);

  QString filterText() const;
  void setFilterText(const QString& text);
  // Highlights a run's row without opening it.
  void selectRun(const std::string& name);
  QTableView* table() const { return table_; }

 signals:
  void runChosen(const QString& name);
  void filterChanged(const QString& text);

 private:
  RunListModel* model_;
  QLineEdit* filter_;
  QSortFilterProxyModel* proxy_;
  QTableView* table_;
};

}  // namespace tactile::gui
