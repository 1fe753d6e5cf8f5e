#include "app/gui/learning/sweep_results_view.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QScrollBar>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <initializer_list>
#include <utility>

#include "analysis/report.h"
#include "analysis/sweep_summary.h"
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
  void setDecision(std::optional<analysis::DecisionMode> decision) {
    decision_ = decision;
    invalidateFilter();
  }

 protected:
  bool filterAcceptsRow(int row, const QModelIndex&) const override {
    const auto* cells = static_cast<const SweepCellsModel*>(sourceModel());
    const analysis::SweepCell& c = cells->cell(row).cell;
    return (!group_ || c.group == *group_) && (!decision_ || c.decision == *decision_);
  }

 private:
  std::optional<SensorGroup> group_;
  std::optional<analysis::DecisionMode> decision_;
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
  // Blue and orange (Okabe-Ito), told apart by colour-blind readers, unlike green and red.
  return t == p ? QColor(0, 114, 178, alpha) : QColor(230, 159, 0, alpha);
}

QString describe(const analysis::SweepCell& c) {
  auto s = [](std::string_view v) {
    return QString::fromUtf8(v.data(), static_cast<qsizetype>(v.size()));
  };
  const QString group = s(groupInfo(c.group).shortName);
  const QString floor = QString::number(c.varianceFloor, 'g', 4);
  const QString features = s(analysis::featureKindName(c.features));
  const QString seed = QString::number(c.seed);
  const QString decision = s(analysis::decisionModeName(c.decision));
  if (c.method == analysis::ClassifierMethod::Gmm)
    return SweepResultsView::tr(
               "Group %1, GMM %2, order %3, variance floor %4, %5 features, seed %6, %7 "
               "decision")
        .arg(group, s(analysis::covarianceFormName(c.form)), QString::number(c.order), floor,
             features, seed, decision);
  if (c.method == analysis::ClassifierMethod::Gbt) {
    return SweepResultsView::tr(
               "Group %1, boosted trees: %2 trees, depth %3, rate %4, min child weight %5, %6 "
               "features, seed %7, %8 decision")
        .arg(group, QString::number(c.trees), QString::number(c.depth),
             QString::number(c.learningRate, 'g', 4), QString::number(c.minChildWeight, 'g', 4),
             features, seed, decision);
  }
  return SweepResultsView::tr("Group %1, %2, variance floor %3, %4 features, seed %5, %6 decision")
      .arg(group, s(analysis::classifierMethodName(c.method)), floor, features, seed, decision);
}

}  // namespace

SweepResultsView::SweepResultsView(QWidget* parent) : QWidget(parent) {
  title_ = new QLabel(tr("No sweep"));
  title_->setObjectName(QStringLiteral("sweepTitle"));
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

  decisionBox_ = new QComboBox;
  decisionBox_->setObjectName(QStringLiteral("decisionFilter"));
  decisionBox_->setToolTip(
      tr("step: the per-step argmax; online: the forward filter (causal); offline: "
         "forward-backward over the whole contact. Cells that differ only in it share one fit."));
  connect(decisionBox_, &QComboBox::currentIndexChanged, this, [this] {
    const int d = decisionBox_->currentData().toInt();
    setDecisionFilter(
        d < 0 ? std::nullopt
              : std::optional<analysis::DecisionMode>(static_cast<analysis::DecisionMode>(d)));
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
  cellsView_->verticalHeader()->setDefaultSectionSize(cellsView_->fontMetrics().height() + 8);
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
  filterRow->addWidget(new QLabel(tr("Decision:")));
  filterRow->addWidget(decisionBox_);
  filterRow->addStretch();
  leftLayout->addLayout(filterRow);
  leftLayout->addWidget(cellsView_, 1);

  cellTitle_ = new QLabel;
  cellTitle_->setObjectName(QStringLiteral("cellTitle"));
  cellTitle_->setWordWrap(true);
  // Small tables as tall as their rows, one under the other.
  auto page = [](std::initializer_list<TableView*> tables) {
    auto* w = new QWidget;
    auto* layout = new QVBoxLayout(w);
    for (TableView* t : tables) {
      t->setFitHeight(true);
      layout->addWidget(t);
    }
    layout->addStretch(1);
    return w;
  };
  counts_ = new TableView;
  percent_ = new TableView;
  QWidget* confusion = page({counts_, percent_});
  cellOneVsRest_ = new TableView;
  rates_ = new TableView;
  oneVsRest_ = new TableView;
  QWidget* ratesPage = page({cellOneVsRest_, rates_, oneVsRest_});
  patterns_ = new TableView;
  floorPlot_ = new SweepPlot;
  orderPlot_ = new SweepPlot;
  timePlot_ = new SweepPlot;
  for (SweepPlot* plot : {floorPlot_, orderPlot_, timePlot_})
    connect(plot, &SweepPlot::cellClicked, this, &SweepResultsView::selectCell);

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

  // While cells stream in, the figures are redrawn at most this often.
  refreshTimer_ = new QTimer(this);
  refreshTimer_->setSingleShot(true);
  refreshTimer_->setInterval(250);
  connect(refreshTimer_, &QTimer::timeout, this, [this] {
    if (figuresStale_) refreshFigures();
  });

  auto* right = new QWidget;
  auto* rightLayout = new QVBoxLayout(right);
  rightLayout->setContentsMargins(0, 0, 0, 0);
  rightLayout->addWidget(cellTitle_);
  rightLayout->addWidget(tabs_, 1);

  splitter_ = new QSplitter(Qt::Horizontal);
  splitter_->addWidget(left);
  splitter_->addWidget(right);
  splitter_->setStretchFactor(0, 1);
  splitter_->setStretchFactor(1, 1);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(title_);
  layout->addWidget(splitter_, 1);
  refreshFigures();
  refreshCellDetails();
}

void SweepResultsView::widenTableToTestSteps() {
  // The table shows its columns up to the test steps whole (they say whether a score can be
  // trusted), as long as the details keep at least a third of the width.
  int needed = 2 * cellsView_->frameWidth() + cellsView_->verticalScrollBar()->sizeHint().width();
  for (int c = 0; c <= SweepCellsModel::TestSteps; ++c)
    needed += cellsView_->horizontalHeader()->sectionSize(c);
  const QList<int> sizes = splitter_->sizes();
  if (sizes.size() != 2) return;
  const int total = sizes[0] + sizes[1];
  const int left = std::min(needed, total * 2 / 3);
  if (sizes[0] < left) splitter_->setSizes({left, total - left});
}

void SweepResultsView::setStoredModels(const QStringList& names) {
  storedModels_ = names;
  refreshTitle();
}

void SweepResultsView::setSweep(std::int64_t sweepId, const analysis::SweepResult& sweep) {
  if (sweepId != sweepId_) storedModels_.clear();
  sweepId_ = sweepId;
  sweep_ = sweep;
  selected_ = -1;
  refreshTimer_->stop();
  cells_->setCells(sweep_.cells);
  for (const auto& [column, shown] : SweepCellsModel::settingsColumns(sweep_.grid.methods))
    cellsView_->setColumnHidden(column, !shown);
  if (isVisible()) QTimer::singleShot(0, this, [this] { widenTableToTestSteps(); });
  {
    // The decision modes the sweep scored, in the grid's order.
    const QSignalBlocker block(decisionBox_);
    decisionBox_->clear();
    decisionBox_->addItem(tr("All decisions"), -1);
    for (analysis::DecisionMode d : analysis::kDecisionModes) {
      const bool scored = std::any_of(sweep_.cells.begin(), sweep_.cells.end(),
                                      [d](const auto& r) { return r.cell.decision == d; }) ||
                          std::find(sweep_.grid.decisions.begin(), sweep_.grid.decisions.end(),
                                    d) != sweep_.grid.decisions.end();
      if (scored) {
        const std::string_view name = analysis::decisionModeName(d);
        decisionBox_->addItem(QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())),
                              static_cast<int>(d));
      }
    }
    decision_.reset();
    static_cast<GroupFilter*>(filtered_)->setDecision(std::nullopt);
  }
  refreshTitle();
  // The best cell of the shown group (or of all) first.
  int best = -1;
  for (const std::size_t i : analysis::bestCells(sweep_)) {
    if (group_ && sweep_.cells[i].cell.group != *group_) continue;
    if (best < 0 ||
        analysis::betterCell(sweep_.cells[i], sweep_.cells[static_cast<std::size_t>(best)]))
      best = static_cast<int>(i);
  }
  refreshFigures();
  if (best >= 0) {
    selectCell(best);
  } else {
    for (SweepPlot* plot : {floorPlot_, orderPlot_, timePlot_})
      plot->markCell(-1);
    refreshCellDetails();
  }
}

void SweepResultsView::addCell(const analysis::SweepCellResult& cell) {
  sweep_.cells.push_back(cell);
  cells_->addCell(cell);
  figuresStale_ = true;
  refreshTitle();
  if (selected_ < 0 && cell.ok) selectCell(static_cast<int>(sweep_.cells.size()) - 1);
  // The figures and the best cells' table are redrawn when the stream pauses (or every 250 ms)
  // if one is in view; hidden ones when their tab is shown.
  const QWidget* current = tabs_->currentWidget();
  const bool figureInView = current == floorPlot_ || current == orderPlot_ ||
                            current == timePlot_ || current == oneVsRest_->parentWidget();
  if (figureInView && figuresStale_ && !refreshTimer_->isActive()) refreshTimer_->start();
}

bool SweepResultsView::figuresPending() const {
  return refreshTimer_->isActive();
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
  scrollToSelected();
}

void SweepResultsView::setDecisionFilter(std::optional<analysis::DecisionMode> decision) {
  decision_ = decision;
  static_cast<GroupFilter*>(filtered_)->setDecision(decision);
  const int index = decisionBox_->findData(decision ? static_cast<int>(*decision) : -1);
  if (index >= 0 && index != decisionBox_->currentIndex()) {
    const QSignalBlocker block(decisionBox_);
    decisionBox_->setCurrentIndex(index);
  }
  // The best cell among those shown.
  const auto shown = [this](const analysis::SweepCell& c) {
    return (!group_ || c.group == *group_) && (!decision_ || c.decision == *decision_);
  };
  if (selected_ < 0 || !shown(sweep_.cells[static_cast<std::size_t>(selected_)].cell)) {
    int best = -1;
    for (std::size_t i = 0; i < sweep_.cells.size(); ++i) {
      const analysis::SweepCellResult& r = sweep_.cells[i];
      if (!r.ok || !shown(r.cell)) continue;
      if (best < 0 || analysis::betterCell(r, sweep_.cells[static_cast<std::size_t>(best)]))
        best = static_cast<int>(i);
    }
    if (best >= 0) selectCell(best);
  }
  refreshFigures();
  scrollToSelected();
}

void SweepResultsView::selectBestCell(SensorGroup group) {
  for (const std::size_t i : analysis::bestCells(sweep_)) {
    if (sweep_.cells[i].cell.group == group) {
      selectCell(static_cast<int>(i));
      return;
    }
  }
}

void SweepResultsView::selectCell(int cellIndex) {
  if (cellIndex < 0 || cellIndex >= static_cast<int>(sweep_.cells.size())) return;
  const std::optional<SensorGroup> previousGroup =
      selected_ >= 0 ? std::optional(sweep_.cells[static_cast<std::size_t>(selected_)].cell.group)
                     : std::nullopt;
  const std::optional<analysis::DecisionMode> previousDecision =
      selected_ >= 0
          ? std::optional(sweep_.cells[static_cast<std::size_t>(selected_)].cell.decision)
          : std::nullopt;
  selected_ = cellIndex;
  const QModelIndex shown = filtered_->mapFromSource(cells_->index(cellIndex, 0));
  if (shown.isValid() && cellsView_->currentIndex().row() != shown.row()) {
    const QSignalBlocker block(cellsView_->selectionModel());
    cellsView_->selectionModel()->setCurrentIndex(
        shown, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  }
  scrollToSelected();
  // Without a group filter the rate figures hold the selected cell's group.
  const bool groupChanged =
      previousGroup != sweep_.cells[static_cast<std::size_t>(cellIndex)].cell.group;
  const bool decisionChanged =
      previousDecision != sweep_.cells[static_cast<std::size_t>(cellIndex)].cell.decision;
  if ((!group_ && groupChanged) || (!decision_ && decisionChanged)) refreshFigures();
  for (SweepPlot* plot : {floorPlot_, orderPlot_, timePlot_})
    plot->markCell(cellIndex);
  refreshCellDetails();
  emit cellSelected(cellIndex);
}

void SweepResultsView::scrollToSelected() {
  if (selected_ < 0) return;
  const QModelIndex shown = filtered_->mapFromSource(cells_->index(selected_, 0));
  if (shown.isValid()) cellsView_->scrollTo(shown, QAbstractItemView::PositionAtCenter);
}

void SweepResultsView::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  // A view scrolled before it had a size scrolls again once it has one.
  QTimer::singleShot(0, this, [this] {
    scrollToSelected();
    widenTableToTestSteps();
  });
}

void SweepResultsView::refreshTitle() {
  if (sweepId_ == 0 && sweep_.cells.empty() && !sweep_.cancelled) {
    title_->setText(tr("No sweep"));
    return;
  }
  std::size_t fitted = 0;
  for (const analysis::SweepCellResult& r : sweep_.cells)
    fitted += r.ok ? 1 : 0;
  // A sweep fits and scores its cells and keeps their numbers; it stores no model itself. A cell
  // that could not be fitted (a group without training rows) is not a failed job of a worker,
  // which the status bar counts: the two words differ.
  QString text = tr("Sweep %1: %2 cells stored, %3 fitted, %4 could not be fitted")
                     .arg(sweepId_)
                     .arg(sweep_.cells.size())
                     .arg(fitted)
                     .arg(sweep_.cells.size() - fitted);
  text +=
      QStringLiteral("; ") +
      (storedModels_.isEmpty()
           ? tr("no model of it is stored (Store Model of Cell stores one)")
           : tr("stored models of its cells: %1").arg(storedModels_.join(QStringLiteral(", "))));
  if (sweep_.cancelled) text += QLatin1Char(' ') + tr("(cancelled: the finished cells)");
  title_->setText(text);
}

void SweepResultsView::refreshFigures() {
  refreshTimer_->stop();
  // Rate figures hold one group: the filtered one, else the selected cell's (all groups' series
  // at once would be a thicket of lines). Time against error shows every group.
  std::optional<SensorGroup> rateGroup = group_;
  if (!rateGroup && selected_ >= 0)
    rateGroup = sweep_.cells[static_cast<std::size_t>(selected_)].cell.group;
  // One decision mode too: the same fit scored by two decisions would be two points at one x.
  std::optional<analysis::DecisionMode> rateDecision = decision_;
  if (!rateDecision && selected_ >= 0)
    rateDecision = sweep_.cells[static_cast<std::size_t>(selected_)].cell.decision;
  analysis::SweepResult shown;
  shown.grid = sweep_.grid;
  std::vector<int> origin;  // index in sweep_.cells of each cell of `shown`
  for (std::size_t i = 0; i < sweep_.cells.size(); ++i) {
    if (rateGroup && sweep_.cells[i].cell.group != *rateGroup) continue;
    if (rateDecision && sweep_.cells[i].cell.decision != *rateDecision) continue;
    shown.cells.push_back(sweep_.cells[i]);
    origin.push_back(static_cast<int>(i));
  }
  floorPlot_->showRates(analysis::rateSeries(shown, analysis::SweptVariable::Floor),
                        analysis::SweptVariable::Floor, origin);
  orderPlot_->showRates(analysis::rateSeries(shown, analysis::SweptVariable::Order),
                        analysis::SweptVariable::Order, origin);
  timePlot_->showTimeError(sweep_, group_);
  // Thesis table 4.19: one row per group, from each group's best cell (as the report).
  std::vector<std::pair<SensorGroup, std::vector<analysis::BinaryConfusion>>> groups;
  for (const std::size_t i : analysis::bestCells(sweep_)) {
    const analysis::SweepCellResult& r = sweep_.cells[i];
    groups.emplace_back(r.cell.group, analysis::binaryConfusions(r.confusion, r.classes));
  }
  if (groups.empty()) {
    oneVsRest_->setMessage(tr("No cell is fitted yet."));
  } else {
    analysis::Table t = analysis::oneVsRestRateTable(groups);
    t.title = tr("Precision per class, one-vs-rest, % - each group's best cell").toStdString();
    oneVsRest_->setTable(t);
  }
  figuresStale_ = false;
}

void SweepResultsView::refreshCellDetails() {
  if (selected_ < 0) {
    cellTitle_->setText(sweep_.cells.empty() ? tr("No cells yet.") : tr("Select a cell."));
    for (TableView* t : {counts_, percent_, cellOneVsRest_, rates_, patterns_})
      t->setMessage(QString());
    return;
  }
  const analysis::SweepCellResult& r = sweep_.cells[static_cast<std::size_t>(selected_)];
  cellTitle_->setText(tr("Cell %1: %2").arg(selected_).arg(describe(r.cell)));
  QString why;
  if (!r.ok) {
    why = tr("This cell could not be fitted: %1").arg(QString::fromStdString(r.reason));
  } else if (r.confusion.total() == 0) {
    why = tr("This cell was not scored: the test runs have no labelled rows of its group.");
  }
  if (!why.isEmpty()) {
    counts_->setMessage(why);
    for (TableView* t : {percent_, cellOneVsRest_, rates_})
      t->setMessage(QString());
    patterns_->setMessage(why);
    return;
  }
  const analysis::ConfusionMatrix& m = r.confusion;
  counts_->setTable(analysis::confusionTable(m, false, tr("Confusion (counts)").toStdString()),
                    [&m](int row, int column) { return confusionColour(m, row, column); });
  percent_->setTable(analysis::confusionTable(m, true, tr("Confusion (row percent)").toStdString()),
                     [&m](int row, int column) { return confusionColour(m, row, column); });
  analysis::Table own =
      analysis::oneVsRestRateTable({{r.cell.group, analysis::binaryConfusions(m, r.classes)}});
  own.title = tr("Precision per class, one-vs-rest (of the steps predicted a class, the share "
                 "that are it), % - this cell")
                  .toStdString();
  cellOneVsRest_->setTable(own);
  rates_->setTable(analysis::classRateTable(
      {{std::string(groupInfo(r.cell.group).shortName), r.metrics}},
      tr("Correct rate per class of this cell (of the steps of a class, the "
         "share predicted as it), %")
          .toStdString()));
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
