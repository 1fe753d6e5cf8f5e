// The runs dock's content: a filter box over the database's runs (name, scene, subject, steps,
// outcome, labelled share, assignments), sortable by any column, and "Assigned to me". Choosing a
// row opens that run; its context menu assigns it or moves the user's assignment on.
#pragma once

#include <QWidget>

#include <string>

class QCheckBox;
class QLineEdit;
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
  // The user's annotator name, for "Assigned to me".
  void setAnnotator(const QString& name);
  void setAssignedToMeOnly(bool on);
  // Rows shown after the filters (for tests).
  int visibleRows() const;

 signals:
  void runChosen(const QString& name);
  void filterChanged(const QString& text);
  // From the context menu: "assign" (to someone), or "todo", "labelled", "reviewed" (the user's
  // own assignment of the run).
  void assignmentRequested(const QString& run, const QString& action);

 private:
  RunListModel* model_;
  QLineEdit* filter_;
  QCheckBox* mine_;
  class Proxy;
  Proxy* proxy_;
  QTableView* table_;
};

}  // namespace tactile::gui
