#include "app/gui/runs/run_list_model.h"

#include <QLocale>
#include <QStringList>

#include <algorithm>

#include "workspace/workspace.h"

namespace tactile::gui {

RunListModel::RunListModel(QObject* parent) : QAbstractTableModel(parent) {}

Status RunListModel::reload(workspace::Workspace* workspace, std::int64_t labelSetId) {
  beginResetModel();
  runs_.clear();
  coverage_.clear();
  Status status = Status::success();
  if (workspace != nullptr) {
    auto runs = workspace->runStore().list();
    if (runs) {
      runs_ = std::move(runs.value());
      std::sort(
          runs_.begin(), runs_.end(),
          [](const storage::RunInfo& a, const storage::RunInfo& b) { return a.name < b.name; });
    } else {
      status = runs.error();
    }
  }
  endResetModel();
  if (!status) return status;
  return reloadCoverage(workspace, labelSetId);
}

Status RunListModel::reloadAssignments(workspace::Workspace* workspace) {
  assignments_.clear();
  Status status = Status::success();
  if (workspace != nullptr) {
    auto all = workspace->labelStore().assignments();
    if (all) {
      for (storage::Assignment& a : all.value())
        assignments_[a.runId].push_back(std::move(a));
    } else {
      status = all.error();
    }
  }
  if (!runs_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
  return status;
}

QString RunListModel::stateText(storage::AssignmentState state) {
  switch (state) {
    case storage::AssignmentState::Todo:
      return tr("to do");
    case storage::AssignmentState::Labelled:
      return tr("labelled");
    case storage::AssignmentState::Reviewed:
      return tr("reviewed");
  }
  return {};
}

Status RunListModel::reloadCoverage(workspace::Workspace* workspace, std::int64_t labelSetId) {
  coverage_.clear();
  modelCoverage_.clear();
  Status status = Status::success();
  if (workspace != nullptr && labelSetId != 0) {
    auto coverage = workspace->labelCoverage(labelSetId);
    if (coverage) {
      for (const auto& [id, percent] : coverage.value())
        coverage_[id] = percent;
    } else {
      status = coverage.error();
    }
    if (auto byModel = workspace->modelLabelCoverage(labelSetId); byModel) {
      for (const auto& [id, percent] : byModel.value())
        modelCoverage_[id] = percent;
    }
  }
  if (!runs_.empty()) emit dataChanged(index(0, Coverage), index(rowCount() - 1, Coverage));
  if (status) status = reloadAssignments(workspace);
  return status;
}

int RunListModel::rowOf(const std::string& name) const {
  for (std::size_t i = 0; i < runs_.size(); ++i)
    if (runs_[i].name == name) return static_cast<int>(i);
  return -1;
}

int RunListModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(runs_.size());
}

int RunListModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant RunListModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const storage::RunInfo& r = runs_[static_cast<std::size_t>(index.row())];
  const auto coverage = coverage_.find(r.id);
  const double covered = coverage == coverage_.end() ? 0.0 : coverage->second;
  if (role == Qt::DisplayRole) {
    switch (index.column()) {
      case Name:
        return QString::fromStdString(r.name);
      case Scene:
        return QString::fromStdString(r.scene);
      case Subject:
        return QString::fromStdString(r.subject);
      case Steps:
        return QLocale().toString(static_cast<qlonglong>(r.stepCount));
      case Outcome:
        return QString::fromStdString(r.outcome);
      case Coverage: {
        const auto model = modelCoverage_.find(r.id);
        if (model == modelCoverage_.end() || model->second <= 0.0)
          return QStringLiteral("%1 %").arg(covered, 0, 'f', 0);
        return tr("%1 % (model %2 %)").arg(covered, 0, 'f', 0).arg(model->second, 0, 'f', 0);
      }
      case Assigned: {
        QStringList parts;
        if (const auto it = assignments_.find(r.id); it != assignments_.end()) {
          for (const storage::Assignment& a : it->second) {
            QString who = QString::fromStdString(a.annotator);
            if (a.group) {
              const std::string_view g = groupInfo(*a.group).shortName;
              who += QStringLiteral(" (%1)").arg(
                  QString::fromUtf8(g.data(), static_cast<int>(g.size())));
            }
            parts << QStringLiteral("%1: %2").arg(who, stateText(a.state));
          }
        }
        return parts.join(QStringLiteral("; "));
      }
      default:
        return {};
    }
  }
  if (role == kAssigneesRole) {
    QStringList who;
    if (const auto it = assignments_.find(r.id); it != assignments_.end()) {
      for (const storage::Assignment& a : it->second)
        who << QString::fromStdString(a.annotator);
    }
    return who;
  }
  // Sorting by number, not by the formatted text.
  if (role == Qt::UserRole) {
    switch (index.column()) {
      case Steps:
        return static_cast<qlonglong>(r.stepCount);
      case Coverage:
        return covered;
      default:
        return data(index, Qt::DisplayRole);
    }
  }
  if (role == Qt::TextAlignmentRole && (index.column() == Steps || index.column() == Coverage))
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  if (role == Qt::ToolTipRole && index.column() == Assigned) return data(index, Qt::DisplayRole);
  if (role == Qt::ToolTipRole && index.column() == Coverage) {
    const auto model = modelCoverage_.find(r.id);
    const double byModel = model == modelCoverage_.end() ? 0.0 : model->second;
    return tr("Steps x groups labelled in the current set: %1 % by people, %2 % by a model")
        .arg(covered - byModel, 0, 'f', 1)
        .arg(byModel, 0, 'f', 1);
  }
  if (role == Qt::ToolTipRole && index.column() == Name)
    return tr("%1\nimported from %2")
        .arg(QString::fromStdString(r.name), QString::fromStdString(r.sourceFile));
  return {};
}

QVariant RunListModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Name:
      return tr("Run");
    case Scene:
      return tr("Scene");
    case Subject:
      return tr("Subject");
    case Steps:
      return tr("Steps");
    case Outcome:
      return tr("Outcome");
    case Coverage:
      return tr("Labelled");
    case Assigned:
      return tr("Assigned");
    default:
      return {};
  }
}

}  // namespace tactile::gui
