// The database's runs as a table: name, scene, subject, steps, outcome, how much of each run the
// current label set covers, and who the run is assigned to in which state.
#pragma once

#include <QAbstractTableModel>

#include <cstdint>
#include <map>
#include <vector>

#include "base/error.h"
#include "storage/run_database.h"

namespace tactile::workspace {
class Workspace;
}

namespace tactile::gui {

class RunListModel : public QAbstractTableModel {
  Q_OBJECT

 public:
  enum Column { Name, Scene, Subject, Steps, Outcome, Coverage, Assigned, ColumnCount };
  // data() role of any column: the annotators the row's run (or a group of it) is assigned to.
  static constexpr int kAssigneesRole = Qt::UserRole + 1;

  explicit RunListModel(QObject* parent = nullptr);

  // Re-reads the runs of the workspace (null: empty) and the coverage of the given set (0: none).
  Status reload(workspace::Workspace* workspace, std::int64_t labelSetId);
  // Re-reads only the coverage column (and the assignments).
  Status reloadCoverage(workspace::Workspace* workspace, std::int64_t labelSetId);
  // Re-reads only the assignments.
  Status reloadAssignments(workspace::Workspace* workspace);
  // "to do", "labelled", "reviewed" in the interface's language.
  static QString stateText(storage::AssignmentState state);

  const storage::RunInfo& run(int row) const { return runs_[static_cast<std::size_t>(row)]; }
  // Whether any run is assigned to anyone (the view shows the Assigned column only then).
  bool hasAssignments() const { return !assignments_.empty(); }
  // The row of a run, or -1.
  int rowOf(const std::string& name) const;

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation,
                      int role = Qt::DisplayRole) const override;

 private:
  std::vector<storage::RunInfo> runs_;
  std::map<std::int64_t, double> coverage_;       // percent by run id
  std::map<std::int64_t, double> modelCoverage_;  // of it, labelled by a model
  std::map<std::int64_t, std::vector<storage::Assignment>> assignments_;  // by run id
};

}  // namespace tactile::gui
