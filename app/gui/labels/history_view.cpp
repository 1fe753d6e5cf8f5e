#include "app/gui/labels/history_view.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include "app/gui/common/plot_style.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/runs/run_session_model.h"
#include "workspace/workspace.h"

namespace tactile::gui {

namespace {

enum Column { kRevision, kTime, kAnnotator, kGroup, kSteps, kClass, kAction, kColumns };

QString actionText(const std::string& action) {
  if (action == "set") return HistoryView::tr("labelled");
  if (action == "change") return HistoryView::tr("moved");
  if (action == "delete") return HistoryView::tr("deleted");
  if (action == "undo") return HistoryView::tr("undone");
  if (action == "redo") return HistoryView::tr("redone");
  if (action == "import") return HistoryView::tr("imported");
  if (action == "truth") return HistoryView::tr("from truth");
  if (action == "restore") return HistoryView::tr("restored");
  return QString::fromStdString(action);
}

}  // namespace

HistoryView::HistoryView(RunSession* session, LabelModel* labels, QWidget* parent)
    : QWidget(parent), session_(session), labels_(labels) {
  auto* layout = new QVBoxLayout(this);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  table_ = new QTableWidget(0, kColumns, this);
  table_->setObjectName(QStringLiteral("historyTable"));
  table_->setHorizontalHeaderLabels({tr("Revision"), tr("Time (UTC)"), tr("Annotator"), tr("Group"),
                                     tr("Steps"), tr("Class"), tr("Edit")});
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  layout->addWidget(summary_);
  layout->addWidget(table_, 1);
  connect(labels_, &LabelModel::labelsChanged, this, &HistoryView::refresh);
  connect(labels_, &LabelModel::labelSetChanged, this, &HistoryView::refresh);
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    const QTableWidgetItem* item = table_->item(row, kSteps);
    if (item == nullptr) return;
    const qint64 first = item->data(Qt::UserRole).toLongLong();
    const qint64 last = item->data(Qt::UserRole + 1).toLongLong();
    session_->setCurrentStep(first);
    session_->setSelection(first, last);
  });
  refresh();
}

int HistoryView::rowCount() const {
  return table_->rowCount();
}

void HistoryView::refresh() {
  table_->setRowCount(0);
  workspace::Workspace* ws = labels_->workspace();
  if (ws == nullptr || !labels_->hasSet() || labels_->runId() == 0) {
    summary_->setText(tr("Open a label set and a run to see who changed its labels."));
    return;
  }
  auto history = ws->labelStore().history(labels_->setId(), labels_->runId());
  if (!history) {
    summary_->setText(QString::fromStdString(history.errorText()));
    return;
  }
  const auto& revisions = history.value();
  summary_->setText(revisions.empty() ? tr("No edit of these labels is recorded yet.")
                                      : tr("%n edit(s) of set '%1' on this run, newest first.",
                                           nullptr, static_cast<int>(revisions.size()))
                                            .arg(QString::fromStdString(labels_->setName())));
  table_->setRowCount(static_cast<int>(revisions.size()));
  int row = 0;
  for (auto it = revisions.rbegin(); it != revisions.rend(); ++it, ++row) {
    const storage::LabelRevision& r = *it;
    auto put = [&](int column, const QString& text) {
      auto* item = new QTableWidgetItem(text);
      table_->setItem(row, column, item);
      return item;
    };
    put(kRevision, QString::number(r.revision));
    put(kTime, QString::fromStdString(r.time).replace('T', ' ').remove('Z'));
    put(kAnnotator, r.annotator.empty() ? tr("(none)") : QString::fromStdString(r.annotator));
    const std::string_view group = groupInfo(r.group).shortName;
    put(kGroup, QString::fromUtf8(group.data(), static_cast<int>(group.size())));
    QTableWidgetItem* steps = put(kSteps, QStringLiteral("%1-%2").arg(r.firstStep).arg(r.lastStep));
    steps->setData(Qt::UserRole, static_cast<qlonglong>(r.firstStep));
    steps->setData(Qt::UserRole + 1, static_cast<qlonglong>(r.lastStep));
    QTableWidgetItem* cls = put(kClass, r.cls ? className(*r.cls) : tr("(cleared or several)"));
    if (r.cls) cls->setForeground(classColor(*r.cls).darker(130));
    put(kAction, actionText(r.action));
    QStringList before;
    for (const storage::LabelSegment& s : r.replaced) {
      before << tr("%1 %2-%3 by %4")
                    .arg(className(s.cls))
                    .arg(s.firstStep)
                    .arg(s.lastStep)
                    .arg(s.annotator.empty() ? tr("(none)") : QString::fromStdString(s.annotator));
    }
    const QString tip = before.isEmpty() ? tr("The steps were unlabelled before.")
                                         : tr("Before: %1").arg(before.join(QStringLiteral("; ")));
    for (int c = 0; c < kColumns; ++c)
      table_->item(row, c)->setToolTip(tip);
  }
}

}  // namespace tactile::gui
