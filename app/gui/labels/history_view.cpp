#include "app/gui/labels/history_view.h"

#include <QDateTime>
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

enum Column { kRevision, kAnnotator, kTime, kChange, kColumns };

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
  table_->setHorizontalHeaderLabels(
      {tr("Revision"), tr("Annotator"), tr("Time (UTC)"), tr("Edit")});
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(kChange, QHeaderView::Stretch);
  table_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
  table_->setTextElideMode(Qt::ElideRight);
  layout->addWidget(summary_);
  layout->addWidget(table_, 1);
  connect(labels_, &LabelModel::labelsChanged, this, &HistoryView::refresh);
  connect(labels_, &LabelModel::labelSetChanged, this, &HistoryView::refresh);
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    const QTableWidgetItem* item = table_->item(row, kChange);
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
  const QString set = QString::fromStdString(labels_->setName());
  if (revisions.empty()) {
    summary_->setText(tr("No edit of these labels is recorded yet."));
  } else if (revisions.size() == 1) {
    summary_->setText(tr("One edit of set '%1' on this run.").arg(set));
  } else {
    summary_->setText(
        tr("%1 edits of set '%2' on this run, newest first.").arg(revisions.size()).arg(set));
  }
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
    put(kAnnotator, r.annotator.empty() ? tr("(none)") : QString::fromStdString(r.annotator));
    // The time of day; the date too when it is not today.
    const QString time = QString::fromStdString(r.time).replace('T', ' ').remove('Z');
    const QString today = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyy-MM-dd"));
    put(kTime, time.startsWith(today) ? time.mid(11) : time.left(16));
    const std::string_view group = groupInfo(r.group).shortName;
    QTableWidgetItem* change =
        put(kChange, tr("%1 %2-%3: %4 (%5)")
                         .arg(QString::fromUtf8(group.data(), static_cast<int>(group.size())))
                         .arg(r.firstStep)
                         .arg(r.lastStep)
                         .arg(r.cls ? className(*r.cls) : tr("cleared or several"))
                         .arg(actionText(r.action)));
    change->setData(Qt::UserRole, static_cast<qlonglong>(r.firstStep));
    change->setData(Qt::UserRole + 1, static_cast<qlonglong>(r.lastStep));
    if (r.cls) change->setForeground(classColor(*r.cls).darker(130));
    QStringList before;
    for (const storage::LabelSegment& s : r.replaced) {
      before << tr("%1 %2-%3 by %4")
                    .arg(className(s.cls))
                    .arg(s.firstStep)
                    .arg(s.lastStep)
                    .arg(s.annotator.empty() ? tr("(none)") : QString::fromStdString(s.annotator));
    }
    const QString tip =
        QString::fromStdString(r.time) + QStringLiteral("\n") +
        (before.isEmpty() ? tr("The steps were unlabelled before.")
                          : tr("Before: %1").arg(before.join(QStringLiteral("; "))));
    for (int c = 0; c < kColumns; ++c)
      table_->item(row, c)->setToolTip(tip);
  }
}

}  // namespace tactile::gui
