// The History dock: every edit of the current label set on the open run, newest first (who, when,
// which group and steps, the class given, what kind of edit), so annotators who share a database
// see who changed what. A double click goes to the edit's first step and selects its steps.
#pragma once

#include <QWidget>

class QLabel;
class QTableWidget;

namespace tactile::gui {

class LabelModel;
class RunSession;

class HistoryView : public QWidget {
  Q_OBJECT

 public:
  HistoryView(RunSession* session, LabelModel* labels, QWidget* parent = nullptr);

  // Rows shown (for tests).
  int rowCount() const;

 public slots:
  // Reads the history again (after every reload of the labels).
  void refresh();

 private:
  RunSession* session_;
  LabelModel* labels_;
  QLabel* summary_;
  QTableWidget* table_;
};

}  // namespace tactile::gui
