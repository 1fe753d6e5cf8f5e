#include "app/gui/runs/run_list_view.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QMenu>
#include <QSortFilterProxyModel>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QVBoxLayout>

#include "app/gui/runs/run_list_model.h"

namespace tactile::gui {
namespace {

// Run names of one corpus share their beginning ("room2_0000", "room3_0000") and differ towards
// the end: a name too long for its column loses its beginning, never the part that tells it apart.
class NameDelegate : public QStyledItemDelegate {
 public:
  using QStyledItemDelegate::QStyledItemDelegate;

 protected:
  void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override {
    QStyledItemDelegate::initStyleOption(option, index);
    option->textElideMode = Qt::ElideLeft;
  }
};

}  // namespace

// The text filter, and with "Assigned to me" only the runs assigned to the user.
class RunListView::Proxy : public QSortFilterProxyModel {
 public:
  using QSortFilterProxyModel::QSortFilterProxyModel;
  QString annotator;
  bool mineOnly = false;
  void refilter() { invalidateFilter(); }

 protected:
  bool filterAcceptsRow(int row, const QModelIndex& parent) const override {
    if (mineOnly) {
      const QStringList who =
          sourceModel()->index(row, 0, parent).data(RunListModel::kAssigneesRole).toStringList();
      if (annotator.isEmpty() || !who.contains(annotator)) return false;
    }
    return QSortFilterProxyModel::filterAcceptsRow(row, parent);
  }
};

RunListView::RunListView(RunListModel* model, QWidget* parent) : QWidget(parent), model_(model) {
  setObjectName(QStringLiteral("runList"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  filter_ = new QLineEdit(this);
  filter_->setObjectName(QStringLiteral("runFilter"));
  filter_->setPlaceholderText(tr("Filter runs by name, scene, subject or outcome"));
  filter_->setClearButtonEnabled(true);
  mine_ = new QCheckBox(tr("Assigned to me"), this);
  mine_->setObjectName(QStringLiteral("assignedToMe"));
  mine_->setToolTip(tr("Only the runs assigned to the annotator named in Preferences"));
  proxy_ = new Proxy(this);
  proxy_->setSourceModel(model_);
  proxy_->setFilterCaseSensitivity(Qt::CaseInsensitive);
  proxy_->setFilterKeyColumn(-1);
  proxy_->setSortRole(Qt::UserRole);
  table_ = new QTableView(this);
  table_->setObjectName(QStringLiteral("runTable"));
  table_->setModel(proxy_);
  table_->setSortingEnabled(true);
  table_->sortByColumn(0, Qt::AscendingOrder);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
  // Columns as wide as their content; the run's name takes what is left and is shortened in the
  // middle in a narrow dock, so the outcome and the labelled share are never cut off.
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  // Who a run is assigned to shares the rest with the name (both shortened, never hidden).
  table_->horizontalHeader()->setSectionResizeMode(RunListModel::Assigned, QHeaderView::Stretch);
  table_->horizontalHeader()->setStretchLastSection(false);
  table_->horizontalHeader()->setMinimumSectionSize(
      fontMetrics().horizontalAdvance(QLatin1Char('M')) * 4);
  table_->setTextElideMode(Qt::ElideMiddle);
  table_->setItemDelegateForColumn(RunListModel::Name, new NameDelegate(table_));
  // Without any assignment the Assigned column would only take width from the run's name.
  const auto showAssigned = [this] {
    table_->setColumnHidden(RunListModel::Assigned,
                            !model_->hasAssignments() && !mine_->isChecked());
  };
  connect(model_, &QAbstractItemModel::modelReset, this, showAssigned);
  connect(model_, &QAbstractItemModel::dataChanged, this, showAssigned);
  connect(mine_, &QCheckBox::toggled, this, showAssigned);
  showAssigned();
  table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  table_->setAlternatingRowColors(true);
  auto* top = new QHBoxLayout;
  top->addWidget(filter_, 1);
  top->addWidget(mine_);
  layout->addLayout(top);
  layout->addWidget(table_);
  connect(mine_, &QCheckBox::toggled, this, &RunListView::setAssignedToMeOnly);
  table_->setContextMenuPolicy(Qt::CustomContextMenu);
  connect(table_, &QWidget::customContextMenuRequested, this, [this](const QPoint& at) {
    const QModelIndex index = table_->indexAt(at);
    if (!index.isValid()) return;
    const QString run = QString::fromStdString(model_->run(proxy_->mapToSource(index).row()).name);
    QMenu menu(this);
    menu.addAction(tr("Assign to..."), this,
                   [this, run] { emit assignmentRequested(run, "assign"); });
    menu.addSeparator();
    menu.addAction(tr("My Assignment: To Do"), this,
                   [this, run] { emit assignmentRequested(run, "todo"); });
    menu.addAction(tr("My Assignment: Labelled"), this,
                   [this, run] { emit assignmentRequested(run, "labelled"); });
    menu.addAction(tr("My Assignment: Reviewed"), this,
                   [this, run] { emit assignmentRequested(run, "reviewed"); });
    menu.exec(table_->viewport()->mapToGlobal(at));
  });

  // Spaces around what was typed or pasted are never part of a run's name.
  connect(filter_, &QLineEdit::textChanged, this, [this](const QString& text) {
    proxy_->setFilterFixedString(text.trimmed());
    emit filterChanged(text);
  });
  auto choose = [this](const QModelIndex& index) {
    if (!index.isValid()) return;
    const QModelIndex source = proxy_->mapToSource(index);
    emit runChosen(QString::fromStdString(model_->run(source.row()).name));
  };
  connect(table_, &QTableView::activated, this, choose);
  connect(table_, &QTableView::clicked, this, choose);
}

void RunListView::setAnnotator(const QString& name) {
  proxy_->annotator = name;
  proxy_->refilter();
}

void RunListView::setAssignedToMeOnly(bool on) {
  if (mine_->isChecked() != on) mine_->setChecked(on);
  proxy_->mineOnly = on;
  proxy_->refilter();
}

int RunListView::visibleRows() const {
  return proxy_->rowCount();
}

QString RunListView::filterText() const {
  return filter_->text();
}

void RunListView::setFilterText(const QString& text) {
  filter_->setText(text);
}

void RunListView::selectRun(const std::string& name) {
  const int row = model_->rowOf(name);
  if (row < 0) return;
  const QModelIndex index = proxy_->mapFromSource(model_->index(row, 0));
  if (!index.isValid()) return;
  table_->selectionModel()->select(index,
                                   QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  table_->scrollTo(index);
}

}  // namespace tactile::gui
