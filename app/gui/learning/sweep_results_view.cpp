#include "app/gui/learning/sweep_results_view.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>

#include <map>
#include <utility>

#include "analysis/report.h"
#include "app/gui/learning/sweep_cells_model.h"
#include "app/gui/learning/sweep_plots.h"
#include "app/gui/learning/table_view.h"

namespace tactile::gui {

namespace {

// Rows of one group only (or all), sorted by the raw numbers in Qt::UserRole.
class GroupFilter : public QSortFilterProxyModel {
 public:
  using QSortFilterProxyModel::QSortFilterProxyModel;
  void setGroup(std::optional<SensorGroup> group) {
    group_ = group;
    invalidateFilter();
  }

 protected:
  bool filterAcceptsRow(int row, const QModelIndex&) const override {
    if (!group_) return true;
    const auto* cells = static_cast<const SweepCellsModel*>(sourceModel());
    return cells->cell(row).cell.group == *group_;
  }

 private:
  std::optional<SensorGroup> group_;
};

// Background of a confusion cell by its row percent: the diagonal in green, the rest in red,
// stronger with the share.
std::optional<QColor> confusionColour(const analysis::ConfusionMatrix& m, int row, int column) {
  std::vector<ContactClass> truths;
  for (ContactClass c : m.activeClasses())
    if (m.trueCount(c) > 0) truths.push_back(c);
  const std::vector<ContactClass> predicted = m.activeClasses();
  if (row < 0 || row >= static_cast<int>(truths.size())) return std::nullopt;
  if (column < 1 || column > static_cast<int>(predicted.size())) return std::nullopt;
  const ContactClass t = truths[static_cast<std::size_t>(row)];
  const ContactClass p = predicted[static_cast<std::size_t>(column - 1)];
  const double share = m.percent(t, p).value_or(0.0) / 100.0;
  if (share <= 0.0) return std::nullopt;
  const int alpha = static_cast<int>(40 + 180 * share);
  return t == p ? QColor(46, 160, 67, alpha) : QColor(214, 39, 40, alpha);
}

// The better of two cells of one group: higher balanced accuracy, then fewer components, then a
// faster fit (as the report's best-cells table).
bool better(const analysis::SweepCellResult& a, const analysis::SweepCellResult& b) {
  if (a.metrics.balancedAccuracy != b.metrics.balancedAccuracy)
    return a.metrics.balancedAccuracy > b.metrics.balancedAccuracy;
  if (a.cell.order != b.cell.order) return a.cell.order < b.cell.order;
  return a.fitSeconds < b.fitSeconds;
}

QString describe(const analysis::SweepCell& c) {
  auto s = [](std::string_view v) {
    return QString::fromUtf8(v.data(), static_cast<qsizetype>(v.size()));
  };
  QString text =
      QObject::tr("Group %1, %2")
          .arg(s(groupInfo(c.group).shortName), s(analysis::classifierMethodName(c.method)));
  if (c.method == analysis::ClassifierMethod::Gmm)
    text +=
        QStringLiteral(" %1, order %2").arg(s(analysis::covarianceFormName(c.form))).arg(c.order);
  text += QObject::tr(", variance floor %1, %2 features, seed %3")
              .arg(c.varianceFloor)
              .arg(s(analysis::featureKindName(c.features)))
              .arg(c.seed);
  return text;
}

}  // namespace

SweepResultsView::SweepResultsView(QWidget* parent) : QWidget(parent) {
  title_ = new QLabel(tr("No sweep"));
  QFont big = title_->font();
  big.setPointSizeF(big.pointSizeF() * 1.2);
  big.setBold(true);
  title_->setFont(big);

  groupBox_ = new QComboBox;
  groupBox_->setObjectName(QStringLiteral("groupFilter"));
  groupBox_->addItem(tr("All groups"), -1);
  for (const GroupInfo& g : kSensorGroups)
    groupBox_->addItem(
        QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size())),
        groupIndex(g.group));
  connect(groupBox_, &QComboBox::currentIndexChanged, this, [this] {
    const int g = groupBox_->currentData().toInt();
    setGroupFilter(
        g < 0 ? std::nullopt
              : std::optional<SensorGroup>(kSensorGroups[static_cast<std::size_t>(g)].group));
  });

  cells_ = new SweepCellsModel(this);
  auto* filter = new GroupFilter(this);
  filter->setSourceModel(cells_);
  filter->setSortRole(Qt::UserRole);
  filtered_ = filter;
  cellsView_ = new QTableView;
  cellsView_->setObjectName(QStringLiteral("sweepCells"));
  cellsView_->setModel(filtered_);
  cellsView_->setSortingEnabled(true);
  cellsView_->sortByColumn(SweepCellsModel::BalancedAccuracy, Qt::DescendingOrder);
  cellsView_->setSelectionBehavior(QAbstractItemView::SelectRows);
  cellsView_->setSelectionMode(QAbstractItemView::SingleSelection);
  cellsView_->verticalHeader()->hide();
  cellsView_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  connect(cellsView_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
          [this](const QModelIndex& current) {
            if (!current.isValid()) return;
            const int row = filtered_->mapToSource(current).row();
            if (row != selected_) selectCell(row);
          });

  auto* left = new QWidget;
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  auto* filterRow = new QHBoxLayout;
  filterRow->addWidget(new QLabel(tr("Group:")));
  filterRow->addWidget(groupBox_);
  filterRow->addStretch();
  leftLayout->addLayout(filterRow);
  leftLayout->addWidget(cellsView_, 1);

  cellTitle_ = new QLabel;
  cellTitle_->setWordWrap(true);
  counts_ = new TableView;
  percent_ = new TableView;
  auto* confusion = new QWidget;
  auto* confusionLayout = new QVBoxLayout(confusion);
  confusionLayout->addWidget(counts_);
  confusionLayout->addWidget(percent_);
  rates_ = new TableView;
  oneVsRest_ = new TableView;
  auto* ratesPage = new QWidget;
  auto* ratesLayout = new QVBoxLayout(ratesPage);
  ratesLayout->addWidget(oneVsRest_);
  ratesLayout->addWidget(rates_);
  patterns_ = new TableView;
  floorPlot_ = new SweepPlot;
  orderPlot_ = new SweepPlot;
  timePlot_ = new SweepPlot;
  connect(timePlot_, &SweepPlot::cellClicked, this, &SweepResultsView::selectCell);

  tabs_ = new QTabWidget;
  tabs_->addTab(confusion, tr("Confusion"));
  tabs_->addTab(ratesPage, tr("Class rates"));
  tabs_->addTab(floorPlot_, tr("Rate vs floor"));
  tabs_->addTab(orderPlot_, tr("Rate vs order"));
  tabs_->addTab(timePlot_, tr("Time vs error"));
  tabs_->addTab(patterns_, tr("Contact patterns"));
  connect(tabs_, &QTabWidget::currentChanged, this, [this] {
    if (figuresStale_) refreshFigures();
  });

  auto* right = new QWidget;
  auto* rightLayout = new QVBoxLayout(right);
  rightLayout->setContentsMargins(0, 0, 0, 0);
  rightLayout->addWidget(cellTitle_);
  rightLayout->addWidget(tabs_, 1);

  auto* splitter = new QSplitter(Qt::Horizontal);
  splitter->addWidget(left);
  splitter->addWidget(right);
  splitter->setStretchFactor(0, 1);
  splitter->setStretchFactor(1, 1);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(title_);
  layout->addWidget(splitter, 1);
  refreshCellDetails();
}

void SweepResultsView::setSweep(std::int64_t sweepId, const analysis::SweepResult& sweep) {
  sweepId_ = sweepId;
  sweep_ = sweep;
  selected_ = -1;
  cells_->setCells(sweep_.cells);
  refreshTitle();
  refreshFigures();
  // The best cell of the shown group (or of all) first.
  int best = -1;
  for (std::size_t i = 0; i < sweep_.cells.size(); ++i) {
    const analysis::SweepCellResult& r = sweep_.cells[i];
    if (!r.ok || (group_ && r.cell.group != *group_)) continue;
    if (best < 0 || better(r, sweep_.cells[static_cast<std::size_t>(best)]))
      best = static_cast<int>(i);
  }
  if (best >= 0) {
    selectCell(best);
  } else {
    refreshCellDetails();
  }
}

void SweepResultsView::addCell(const analysis::SweepCellResult& cell) {
  sweep_.cells.push_back(cell);
  cells_->addCell(cell);
  figuresStale_ = true;
  refreshTitle();
  if (selected_ < 0 && cell.ok) selectCell(static_cast<int>(sweep_.cells.size()) - 1);
  // Only the visible figure is redrawn now; the others when their tab is shown.
  if (tabs_->currentWidget() == floorPlot_ || tabs_->currentWidget() == orderPlot_ ||
      tabs_->currentWidget() == timePlot_)
    refreshFigures();
}

void SweepResultsView::setGroupFilter(std::optional<SensorGroup> group) {
  group_ = group;
  static_cast<GroupFilter*>(filtered_)->setGroup(group);
  const int index = groupBox_->findData(group ? groupIndex(*group) : -1);
  if (index != groupBox_->currentIndex()) {
    const QSignalBlocker block(groupBox_);
    groupBox_->setCurrentIndex(index);
  }
  refreshFigures();
  if (group &&
      (selected_ < 0 || sweep_.cells[static_cast<std::size_t>(selected_)].cell.group != *group))
    selectBestCell(*group);
}

void SweepResultsView::selectBestCell(SensorGroup group) {
  int best = -1;
  for (std::size_t i = 0; i < sweep_.cells.size(); ++i) {
    const analysis::SweepCellResult& r = sweep_.cells[i];
    if (!r.ok || r.cell.group != group) continue;
    if (best < 0 || better(r, sweep_.cells[static_cast<std::size_t>(best)]))
      best = static_cast<int>(i);
  }
  if (best >= 0) selectCell(best);
}

void SweepResultsView::selectCell(int cellIndex) {
  if (cellIndex < 0 || cellIndex >= static_cast<int>(sweep_.cells.size())) return;
  const std::optional<SensorGroup> previousGroup =
      selected_ >= 0 ? std::optional(sweep_.cells[static_cast<std::size_t>(selected_)].cell.group)
                     : std::nullopt;
  selected_ = cellIndex;
  const QModelIndex source = cells_->index(cellIndex, 0);
  const QModelIndex shown = filtered_->mapFromSource(source);
  if (shown.isValid() && cellsView_->currentIndex().row() != shown.row()) {
    const QSignalBlocker block(cellsView_->selectionModel());
    cellsView_->selectionModel()->setCurrentIndex(
        shown, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    cellsView_->scrollTo(shown);
  }
  const bool groupChanged =
      previousGroup != sweep_.cells[static_cast<std::size_t>(cellIndex)].cell.group;
  if (!group_ && groupChanged) refreshFigures();
  refreshCellDetails();
  emit cellSelected(cellIndex);
}

void SweepResultsView::refreshTitle() {
  std::size_t ok = 0;
  for (const analysis::SweepCellResult& r : sweep_.cells)
    ok += r.ok ? 1 : 0;
  QString text =
      tr("Sweep %1: %2 cells, %3 with a model").arg(sweepId_).arg(sweep_.cells.size()).arg(ok);
  if (sweep_.cancelled) text += QLatin1Char(' ') + tr("(cancelled: the finished cells)");
  title_->setText(text);
}

void SweepResultsView::refreshFigures() {
  // Rate figures hold one group: the filtered one, else the selected cell's (all groups' series
  // at once would be a thicket of lines). Time against error shows every group.
  std::optional<SensorGroup> rateGroup = group_;
  if (!rateGroup && selected_ >= 0)
    rateGroup = sweep_.cells[static_cast<std::size_t>(selected_)].cell.group;
  analysis::SweepResult shown;
  shown.grid = sweep_.grid;
  for (const analysis::SweepCellResult& r : sweep_.cells)
    if (!rateGroup || r.cell.group == *rateGroup) shown.cells.push_back(r);
  floorPlot_->showRates(analysis::rateSeries(shown, analysis::SweptVariable::Floor),
                        analysis::SweptVariable::Floor);
  orderPlot_->showRates(analysis::rateSeries(shown, analysis::SweptVariable::Order),
                        analysis::SweptVariable::Order);
  timePlot_->showTimeError(sweep_, group_);
  // Thesis table 4.19: one row per group, from each group's best cell.
  std::map<int, const analysis::SweepCellResult*> best;
  for (const analysis::SweepCellResult& r : sweep_.cells) {
    if (!r.ok) continue;
    const analysis::SweepCellResult*& b = best[groupIndex(r.cell.group)];
    if (b == nullptr || better(r, *b)) b = &r;
  }
  std::vector<std::pair<SensorGroup, std::vector<analysis::BinaryConfusion>>> groups;
  for (const auto& [g, r] : best)
    groups.emplace_back(r->cell.group, analysis::binaryConfusions(r->confusion, r->classes));
  if (groups.empty()) {
    oneVsRest_->setMessage(tr("No cell has a model yet."));
  } else {
    analysis::Table t = analysis::oneVsRestRateTable(groups);
    t.title += " " + tr("- each group's best cell").toStdString();
    oneVsRest_->setTable(t);
  }
  figuresStale_ = false;
}

void SweepResultsView::refreshCellDetails() {
  if (selected_ < 0) {
    cellTitle_->setText(sweep_.cells.empty() ? tr("No cells yet.") : tr("Select a cell."));
    counts_->setMessage(QString());
    percent_->setMessage(QString());
    rates_->setMessage(QString());
    patterns_->setMessage(QString());
    return;
  }
  const analysis::SweepCellResult& r = sweep_.cells[static_cast<std::size_t>(selected_)];
  cellTitle_->setText(tr("Cell %1: %2").arg(selected_).arg(describe(r.cell)));
  if (!r.ok) {
    const QString why = tr("This cell has no model: %1").arg(QString::fromStdString(r.reason));
    counts_->setMessage(why);
    percent_->setMessage(QString());
    rates_->setMessage(why);
    patterns_->setMessage(why);
    return;
  }
  const analysis::ConfusionMatrix& m = r.confusion;
  counts_->setTable(analysis::confusionTable(m, false, tr("Confusion (counts)").toStdString()),
                    [&m](int row, int column) { return confusionColour(m, row, column); });
  percent_->setTable(analysis::confusionTable(m, true, tr("Confusion (row percent)").toStdString()),
                     [&m](int row, int column) { return confusionColour(m, row, column); });
  rates_->setTable(
      analysis::classRateTable({{std::string(groupInfo(r.cell.group).shortName), r.metrics}},
                               tr("Per-class correct rate of this cell (%)").toStdString()));
  if (r.patterns.rows.empty()) {
    patterns_->setMessage(tr("No contact patterns were kept for this cell."));
  } else {
    patterns_->setTable(analysis::contactPatternTable(r.patterns), [&r](int row, int) {
      const analysis::ContactPatternRow& p = r.patterns.rows[static_cast<std::size_t>(row)];
      return p.errors() > 0 ? std::optional<QColor>(QColor(214, 39, 40, 50)) : std::nullopt;
    });
  }
}

}  // namespace tactile::gui
