// The sweep results views: one table row per cell sorted by balanced accuracy, the selected cell's
// confusion read back equal to the cell's and coloured by share, its one-vs-rest row equal to the
// core's, cells streaming in without a redraw per cell, the figures drawing exactly the core's
// series and Pareto front, clicks selecting cells, CSV and image exports, and the empty, failed
// and cancelled states.
#include <qcustomplot.h>
#include <QComboBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QSet>
#include <QSortFilterProxyModel>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>

#include "analysis/report.h"
#include "analysis/sweep.h"
#include "app/gui/learning/sweep_cells_model.h"
#include "app/gui/learning/sweep_plots.h"
#include "app/gui/learning/sweep_results_view.h"
#include "app/gui/learning/table_view.h"
#include "tests/analysis/learn_test_data.h"

using namespace tactile;
using tactile::gui::SweepPlot;
using tactile::gui::SweepResultsView;

namespace {

// A real sweep over synthetic labelled runs (noisy enough that cells differ): 2 groups x 3 orders
// x 2 forms x 2 floors.
analysis::SweepResult makeSweep() {
  static const RunData a = testdata::makeLabelledRun(1200, 21, 0.9);
  static const RunData b = testdata::makeLabelledRun(800, 22, 0.9);
  const std::vector<analysis::LabelledRun> train{{&a, analysis::labelsFromTruth(a)}};
  const std::vector<analysis::LabelledRun> test{{&b, analysis::labelsFromTruth(b)}};
  analysis::SweepGrid g;
  g.groups = {SensorGroup::Right, SensorGroup::FrontLeftCorner};
  g.orders = {1, 2, 4};
  g.forms = {analysis::CovarianceForm::NodalDiag, analysis::CovarianceForm::GrandFull};
  g.varianceFloors = {0.01, 0.1};
  g.maxIterations = 30;
  return analysis::runSweep(train, test, g);
}

const analysis::SweepResult& sweepOnce() {
  static const analysis::SweepResult sweep = makeSweep();
  return sweep;
}

double shownScore(const QTableView* view, int row) {
  const QAbstractItemModel* m = view->model();
  return m->data(m->index(row, gui::SweepCellsModel::BalancedAccuracy), Qt::UserRole).toDouble();
}

double timeOf(const analysis::SweepCellResult& r) {
  return std::max(r.fitSeconds + r.predictSeconds, 1e-6);
}

double errorOf(const analysis::SweepCellResult& r) {
  return 100.0 - 100.0 * r.metrics.balancedAccuracy;
}

// The cells of one group, and the index in the whole sweep of each.
analysis::SweepResult ofGroup(const analysis::SweepResult& sweep, SensorGroup group,
                              std::vector<int>* origin) {
  analysis::SweepResult out;
  out.grid = sweep.grid;
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    if (sweep.cells[i].cell.group != group) continue;
    out.cells.push_back(sweep.cells[i]);
    origin->push_back(static_cast<int>(i));
  }
  return out;
}

// Checks a rate figure against the core's series: one graph per series, named by its label,
// with a point per finite mean, and no more graphs than those and the ring of the selected cell.
void checkRates(const SweepPlot* plot, const std::vector<analysis::RateSeries>& series) {
  QCOMPARE(plot->plot()->graphCount(), static_cast<int>(series.size()) + 1);
  QCOMPARE(plot->seriesCount(), static_cast<int>(series.size()));
  for (std::size_t k = 0; k < series.size(); ++k) {
    const QCPGraph* graph = plot->plot()->graph(static_cast<int>(k));
    QCOMPARE(graph->name(), QString::fromStdString(series[k].label));
    const auto finite = std::count_if(series[k].mean.begin(), series[k].mean.end(),
                                      [](double v) { return std::isfinite(v); });
    QCOMPARE(graph->dataCount(), static_cast<int>(finite));
    // The means themselves, in order (x is spread a little sideways; the values are not).
    int j = 0;
    for (double mean : series[k].mean) {
      if (!std::isfinite(mean)) continue;
      QCOMPARE((graph->data()->constBegin() + j)->value, mean);
      ++j;
    }
  }
}

}  // namespace

class SweepResultsViewTest : public QObject {
  Q_OBJECT

 private slots:
  void timeAxisLabelsEveryDecadeInMsWithoutCollisions();
  void tableHasEveryCellSortedByBalancedAccuracy();
  void selectedCellShowsItsConfusion();
  void classRatesAreTheCoreTables();
  void cellsStreamInWithoutARedrawEach();
  void figuresDrawTheCoreSeriesAndFront();
  void clicksOnFiguresSelectCells();
  void groupFilterShowsOneGroup();
  void exportsWriteTheReportCsvAndImages();
  void tableViewSortsNumbersAsNumbers();
  void failedCellShowsItsReason();
  void plotsZoomHoverAndKeepTickLabelsApart();
  void emptyAndCancelledSweeps();
  void decisionModesHaveAColumnAFilterAndOneFigureEach();
  void testStepsShowCountsAndTooFew();
};

void SweepResultsViewTest::tableHasEveryCellSortedByBalancedAccuracy() {
  const analysis::SweepResult& sweep = sweepOnce();
  SweepResultsView view;
  view.setSweep(7, sweep);
  QCOMPARE(view.cellsView()->model()->rowCount(), static_cast<int>(sweep.cells.size()));
  // The scores differ, so the order below is a real sort, not the grid's order.
  double lowest = 1.0, highest = 0.0;
  for (const analysis::SweepCellResult& c : sweep.cells) {
    lowest = std::min(lowest, c.metrics.balancedAccuracy);
    highest = std::max(highest, c.metrics.balancedAccuracy);
  }
  QVERIFY(highest > lowest);
  for (int row = 1; row < view.cellsView()->model()->rowCount(); ++row)
    QVERIFY(shownScore(view.cellsView(), row) <= shownScore(view.cellsView(), row - 1));
  QCOMPARE(shownScore(view.cellsView(), 0), 100.0 * highest);
  // The best cell (the core's rule) is selected first, and it is the table's selected row.
  int best = -1;
  for (std::size_t i : analysis::bestCells(sweep))
    if (best < 0 ||
        analysis::betterCell(sweep.cells[i], sweep.cells[static_cast<std::size_t>(best)]))
      best = static_cast<int>(i);
  QCOMPARE(view.selectedCell(), best);
  QCOMPARE(sweep.cells[static_cast<std::size_t>(view.selectedCell())].metrics.balancedAccuracy,
           highest);
  const auto* proxy = static_cast<const QSortFilterProxyModel*>(view.cellsView()->model());
  QCOMPARE(proxy->mapToSource(view.cellsView()->currentIndex()).row(), best);
  QCOMPARE(shownScore(view.cellsView(), view.cellsView()->currentIndex().row()), 100.0 * highest);
  QVERIFY(view.title()->text().contains(QStringLiteral("Sweep 7")));
}

void SweepResultsViewTest::selectedCellShowsItsConfusion() {
  const analysis::SweepResult& sweep = sweepOnce();
  SweepResultsView view;
  view.setSweep(1, sweep);
  // The worst cell, which surely errs, and two others.
  int worst = 0;
  for (std::size_t i = 0; i < sweep.cells.size(); ++i)
    if (sweep.cells[i].metrics.balancedAccuracy <
        sweep.cells[static_cast<std::size_t>(worst)].metrics.balancedAccuracy)
      worst = static_cast<int>(i);
  QVERIFY(sweep.cells[static_cast<std::size_t>(worst)].metrics.balancedAccuracy < 1.0);
  int greens = 0, reds = 0;
  for (int index : {worst, 5, static_cast<int>(sweep.cells.size()) - 1}) {
    const analysis::SweepCellResult& cell = sweep.cells[static_cast<std::size_t>(index)];
    QVERIFY(cell.ok);
    view.selectCell(index);
    QCOMPARE(view.selectedCell(), index);
    // Rows are the true classes, columns 1.. the predicted ones, as the core's table.
    const std::vector<ContactClass> predicted = cell.confusion.activeClasses();
    int row = 0;
    for (ContactClass t : predicted) {
      if (cell.confusion.trueCount(t) == 0) continue;
      for (std::size_t c = 0; c < predicted.size(); ++c) {
        const int column = static_cast<int>(c) + 1;
        const std::size_t count = cell.confusion.count(t, predicted[c]);
        QCOMPARE(view.confusionCounts()->cellText(row, column).toULongLong(),
                 static_cast<qulonglong>(count));
        // Coloured by share: the diagonal green, errors red, nothing where there is none.
        const std::optional<QColor> bg = view.confusionPercent()->cellBackground(row, column);
        if (count == 0) {
          QVERIFY(!bg);
        } else if (predicted[c] == t) {
          QVERIFY(bg && bg->green() > bg->red());
          ++greens;
        } else {
          QVERIFY(bg && bg->red() > bg->green());
          ++reds;
        }
      }
      ++row;
    }
    QCOMPARE(row, static_cast<int>(view.confusionCounts()->table().rows.size()));
    QVERIFY(row > 0);
  }
  QVERIFY(greens > 0);
  QVERIFY(reds > 0);
  // A stronger share is a stronger colour.
  view.selectCell(worst);
  const analysis::ConfusionMatrix& m = sweep.cells[static_cast<std::size_t>(worst)].confusion;
  const std::vector<ContactClass> classes = m.activeClasses();
  std::vector<ContactClass> truths;  // the table's rows
  for (ContactClass c : classes)
    if (m.trueCount(c) > 0) truths.push_back(c);
  struct Shade {
    double percent;
    int row, column;
  };
  std::vector<Shade> diagonal;
  for (std::size_t r = 0; r < truths.size(); ++r) {
    const auto column = std::find(classes.begin(), classes.end(), truths[r]) - classes.begin();
    const double p = m.percent(truths[r], truths[r]).value_or(0.0);
    if (p > 0) diagonal.push_back({p, static_cast<int>(r), static_cast<int>(column) + 1});
  }
  std::sort(diagonal.begin(), diagonal.end(),
            [](const Shade& a, const Shade& b) { return a.percent < b.percent; });
  QVERIFY(diagonal.size() >= 2);
  QVERIFY(diagonal.front().percent < diagonal.back().percent);
  QVERIFY(view.confusionPercent()
              ->cellBackground(diagonal.back().row, diagonal.back().column)
              ->alpha() > view.confusionPercent()
                              ->cellBackground(diagonal.front().row, diagonal.front().column)
                              ->alpha());
  // Clicking a row selects its cell.
  QSignalSpy selected(&view, &SweepResultsView::cellSelected);
  const int row = 3;
  view.cellsView()->selectRow(row);
  const auto* proxy = static_cast<const QSortFilterProxyModel*>(view.cellsView()->model());
  const int expected = proxy->mapToSource(proxy->index(row, 0)).row();
  QCOMPARE(view.selectedCell(), expected);
  QCOMPARE(selected.count(), 1);
  QCOMPARE(selected.at(0).at(0).toInt(), expected);
  // Pattern rows are the cell's.
  const analysis::SweepCellResult& chosen = sweep.cells[static_cast<std::size_t>(expected)];
  QVERIFY(!chosen.patterns.rows.empty());
  QCOMPARE(view.patterns()->table().render(analysis::TableStyle::Csv),
           analysis::contactPatternTable(chosen.patterns).render(analysis::TableStyle::Csv));
}

void SweepResultsViewTest::classRatesAreTheCoreTables() {
  const analysis::SweepResult& sweep = sweepOnce();
  SweepResultsView view;
  view.setSweep(1, sweep);
  view.selectCell(4);
  const analysis::SweepCellResult& cell = sweep.cells[4];
  // Table 4.19's layout for the selected cell: one row, the core's numbers.
  const analysis::Table own = analysis::oneVsRestRateTable(
      {{cell.cell.group, analysis::binaryConfusions(cell.confusion, cell.classes)}});
  QCOMPARE(view.cellOneVsRest()->table().header, own.header);
  QCOMPARE(view.cellOneVsRest()->table().rows, own.rows);
  // And each group's best cell, as the report.
  std::vector<std::pair<SensorGroup, std::vector<analysis::BinaryConfusion>>> groups;
  for (std::size_t i : analysis::bestCells(sweep))
    groups.emplace_back(
        sweep.cells[i].cell.group,
        analysis::binaryConfusions(sweep.cells[i].confusion, sweep.cells[i].classes));
  QCOMPARE(groups.size(), std::size_t{2});
  QCOMPARE(view.oneVsRest()->table().rows, analysis::oneVsRestRateTable(groups).rows);
  // The per-class rates of the cell.
  const analysis::Table rates = analysis::classRateTable(
      {{std::string(groupInfo(cell.cell.group).shortName), cell.metrics}}, "");
  QCOMPARE(view.classRates()->table().rows, rates.rows);
  // Another group's cell: its own row.
  int other = -1;
  for (std::size_t i = 0; i < sweep.cells.size() && other < 0; ++i)
    if (sweep.cells[i].cell.group != cell.cell.group) other = static_cast<int>(i);
  QVERIFY(other >= 0);
  view.selectCell(other);
  const analysis::SweepCellResult& o = sweep.cells[static_cast<std::size_t>(other)];
  QCOMPARE(view.cellOneVsRest()->table().rows,
           analysis::oneVsRestRateTable(
               {{o.cell.group, analysis::binaryConfusions(o.confusion, o.classes)}})
               .rows);
  QVERIFY(view.cellOneVsRest()->table().rows != own.rows);
}

void SweepResultsViewTest::cellsStreamInWithoutARedrawEach() {
  const analysis::SweepResult& sweep = sweepOnce();
  analysis::SweepResult empty;
  empty.grid = sweep.grid;
  SweepResultsView view;
  view.setSweep(3, empty);
  QCOMPARE(view.cellsView()->model()->rowCount(), 0);
  QCOMPARE(view.selectedCell(), -1);
  view.tabs()->setCurrentWidget(view.timeErrorPlot());
  QCOMPARE(view.timeErrorPlot()->pointCount(), 0);
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    view.addCell(sweep.cells[i]);
    QCOMPARE(view.cellsView()->model()->rowCount(), static_cast<int>(i + 1));
  }
  QCOMPARE(view.selectedCell(), 0);  // the first cell with a model
  // The visible figure waits for the stream to pause (at most 250 ms), then shows every cell.
  QVERIFY(view.figuresPending());
  QVERIFY(view.timeErrorPlot()->pointCount() < static_cast<int>(sweep.cells.size()));
  QTRY_VERIFY(!view.figuresPending());
  QCOMPARE(view.timeErrorPlot()->pointCount(), static_cast<int>(sweep.cells.size()));
  QCOMPARE(view.timeErrorPlot()->frontCount(),
           static_cast<int>(analysis::paretoFront(sweep).size()));
  // Figures on hidden tabs wait until they are shown: drawn once, for the first cell (selected
  // then), and in full when their tab is.
  SweepResultsView hidden;
  hidden.setSweep(3, empty);
  QCOMPARE(hidden.tabs()->currentIndex(), 0);
  for (const analysis::SweepCellResult& c : sweep.cells)
    hidden.addCell(c);
  QVERIFY(!hidden.figuresPending());
  QCOMPARE(hidden.rateOrderPlot()->pointCount(), 1);
  QCOMPARE(hidden.timeErrorPlot()->pointCount(), 1);
  hidden.tabs()->setCurrentWidget(hidden.rateOrderPlot());
  std::vector<int> origin;
  checkRates(hidden.rateOrderPlot(),
             analysis::rateSeries(ofGroup(sweep, sweep.cells[0].cell.group, &origin),
                                  analysis::SweptVariable::Order));
  QCOMPARE(hidden.timeErrorPlot()->pointCount(), static_cast<int>(sweep.cells.size()));
}

// Regression: swept floors 0.004 and 0.005 printed as "0.0040.005"; the ring of a point at 0 was
// cut in half; the figures neither zoomed nor told a point's values.
void SweepResultsViewTest::plotsZoomHoverAndKeepTickLabelsApart() {
  SweepPlot plot;
  plot.resize(520, 320);
  plot.show();
  QVERIFY(QTest::qWaitForWindowExposed(&plot));
  analysis::RateSeries s;
  s.label = "F gmm nodal-diag order 1";
  s.x = {0.003, 0.004, 0.005, 0.01, 0.1, 1.0};
  s.mean = {0, 60, 70, 80, 90, 100};
  s.min = s.mean;
  s.max = s.mean;
  s.cells = {0, 1, 2, 3, 4, 5};
  plot.showRates({s}, analysis::SweptVariable::Floor);
  plot.plot()->replot();
  QCPAxis* x = plot.plot()->xAxis;
  const QVector<double> ticks = x->tickVector();
  const QVector<QString> labels = x->tickVectorLabels();
  QVERIFY(ticks.size() >= 3);
  QVERIFY(ticks.size() < 6);  // the close ones do not all fit at this width
  const QFontMetrics metrics(x->tickLabelFont());
  for (qsizetype i = 1; i < ticks.size(); ++i) {
    const double gap = x->coordToPixel(ticks[i]) - x->coordToPixel(ticks[i - 1]);
    const double needed =
        (metrics.horizontalAdvance(labels[i]) + metrics.horizontalAdvance(labels[i - 1])) / 2.0;
    QVERIFY2(gap >= needed, qPrintable(labels[i - 1] + QStringLiteral(" / ") + labels[i]));
  }
  // The ring around a point at 0 % is drawn whole, outside the axes if need be.
  plot.markCell(0);
  QCOMPARE(plot.markGraph()->dataCount(), 1);
  QVERIFY(plot.markRing()->visible());
  QVERIFY(!plot.markRing()->clipToAxisRect());
  QCOMPARE(plot.markRing()->position->value(), 0.0);
  // Hovering a point tells its values and cell.
  const QPoint point(qRound(x->coordToPixel(0.01)), qRound(plot.plot()->yAxis->coordToPixel(80)));
  const QString tip = plot.tipAt(plot.plot()->mapTo(&plot, point));
  QVERIFY2(tip.contains(QStringLiteral("cell 3")) && tip.contains(QStringLiteral("80.0")),
           qPrintable(tip));
  QVERIFY(plot.tipAt(QPoint(2, 2)).isEmpty());
  // Guards the hover that reported where a point was drawn (0.03073) instead of its value
  // (0.03): two series at the same floors are drawn apart, and each tells the floor itself.
  {
    analysis::RateSeries a = s, b = s;
    a.x = b.x = {0.01, 0.03, 0.1};
    a.mean = a.min = a.max = {50, 60, 70};
    b.mean = b.min = b.max = {20, 30, 40};
    a.cells = {0, 1, 2};
    b.cells = {3, 4, 5};
    b.label = "F gmm nodal-diag order 2";
    SweepPlot two;
    two.resize(520, 320);
    two.show();
    QVERIFY(QTest::qWaitForWindowExposed(&two));
    two.showRates({a, b}, analysis::SweptVariable::Floor);
    two.plot()->replot();
    auto* graph = two.plot()->graph(0);
    const double drawnAt = (graph->data()->constBegin() + 1)->key;
    QVERIFY(drawnAt != 0.03);  // drawn a little beside the value
    const QPoint at(qRound(two.plot()->xAxis->coordToPixel(drawnAt)),
                    qRound(two.plot()->yAxis->coordToPixel(60)));
    const QString hover = two.tipAt(two.plot()->mapTo(&two, at));
    QVERIFY2(hover.contains(QStringLiteral("Variance floor: 0.03\n")), qPrintable(hover));
  }
  // The wheel zooms, a double click shows it all again.
  QVERIFY(plot.plot()->interactions().testFlag(QCP::iRangeZoom));
  QVERIFY(plot.plot()->interactions().testFlag(QCP::iRangeDrag));
  const QCPRange before = plot.plot()->yAxis->range();
  plot.plot()->yAxis->scaleRange(0.5);
  QVERIFY(plot.plot()->yAxis->range().size() < before.size());
  plot.resetView();
  QCOMPARE(plot.plot()->yAxis->range().size(), before.size());
}

void SweepResultsViewTest::figuresDrawTheCoreSeriesAndFront() {
  const analysis::SweepResult& sweep = sweepOnce();
  SweepResultsView view;
  view.setSweep(1, sweep);
  // The rate figures hold the selected cell's group.
  const SensorGroup shownGroup =
      sweep.cells[static_cast<std::size_t>(view.selectedCell())].cell.group;
  std::vector<int> origin;
  const analysis::SweepResult group = ofGroup(sweep, shownGroup, &origin);
  const auto floorSeries = analysis::rateSeries(group, analysis::SweptVariable::Floor);
  const auto orderSeries = analysis::rateSeries(group, analysis::SweptVariable::Order);
  QVERIFY(!floorSeries.empty());
  QVERIFY(floorSeries.size() != orderSeries.size());
  checkRates(view.rateFloorPlot(), floorSeries);
  checkRates(view.rateOrderPlot(), orderSeries);
  QCOMPARE(view.rateFloorPlot()->plot()->xAxis->scaleType(), QCPAxis::stLogarithmic);
  QCOMPARE(view.rateOrderPlot()->plot()->xAxis->scaleType(), QCPAxis::stLogarithmic);
  QCOMPARE(view.rateFloorPlot()->plot()->xAxis->label(), QStringLiteral("Variance floor"));
  QCOMPARE(view.rateOrderPlot()->plot()->xAxis->label(), QStringLiteral("Model order"));
  QCOMPARE(view.rateFloorPlot()->plot()->yAxis->label(),
           QStringLiteral("Correct rate per class (%)"));
  QVERIFY(view.rateFloorPlot()->plot()->legend->visible());
  // Every series has its error bars (min..max about the mean).
  int bars = 0;
  for (int i = 0; i < view.rateFloorPlot()->plot()->plottableCount(); ++i)
    bars += qobject_cast<QCPErrorBars*>(view.rateFloorPlot()->plot()->plottable(i)) ? 1 : 0;
  QCOMPARE(bars, static_cast<int>(floorSeries.size()));

  // Time against error: every scored cell once, the front as the core computes it.
  const std::vector<std::size_t> front = analysis::paretoFront(sweep);
  QVERIFY(!front.empty());
  const QCPGraph* frontGraph = view.timeErrorPlot()->frontGraph();
  QVERIFY(frontGraph != nullptr);
  QCOMPARE(frontGraph->dataCount(), static_cast<int>(front.size()));
  for (std::size_t k = 0; k < front.size(); ++k) {
    const auto point = frontGraph->data()->constBegin() + static_cast<int>(k);
    QCOMPARE(point->key, timeOf(sweep.cells[front[k]]));
    QCOMPARE(point->value, errorOf(sweep.cells[front[k]]));
  }
  QCOMPARE(frontGraph->lineStyle(), QCPGraph::lsStepLeft);
  std::size_t scored = 0;
  for (const auto& c : sweep.cells)
    scored += c.ok && c.confusion.total() > 0 ? 1 : 0;
  QCOMPARE(view.timeErrorPlot()->pointCount(), static_cast<int>(scored));
  QCOMPARE(view.timeErrorPlot()->seriesCount(), 2);  // one colour per group
  // The selected cell is ringed on every figure.
  const analysis::SweepCellResult& selected =
      sweep.cells[static_cast<std::size_t>(view.selectedCell())];
  const QCPGraph* ring = view.timeErrorPlot()->markGraph();
  QCOMPARE(ring->dataCount(), 1);
  QCOMPARE(ring->data()->constBegin()->key, timeOf(selected));
  QCOMPARE(ring->data()->constBegin()->value, errorOf(selected));
  QCOMPARE(view.rateFloorPlot()->markGraph()->dataCount(), 1);
  QCOMPARE(view.rateOrderPlot()->markGraph()->dataCount(), 1);
}

void SweepResultsViewTest::clicksOnFiguresSelectCells() {
  const analysis::SweepResult& sweep = sweepOnce();
  SweepResultsView view;
  view.setSweep(1, sweep);
  // A click on a front point selects that cell.
  const std::vector<std::size_t> front = analysis::paretoFront(sweep);
  QCustomPlot* time = view.timeErrorPlot()->plot();
  QSignalSpy selected(&view, &SweepResultsView::cellSelected);
  emit time->plottableClick(view.timeErrorPlot()->frontGraph(), 0, nullptr);
  QCOMPARE(view.selectedCell(), static_cast<int>(front.front()));
  QCOMPARE(selected.count(), 1);
  // A click on a rate point selects the cell it stands for (indices of the whole sweep).
  const SensorGroup shownGroup = sweep.cells[front.front()].cell.group;
  std::vector<int> origin;
  const auto series =
      analysis::rateSeries(ofGroup(sweep, shownGroup, &origin), analysis::SweptVariable::Order);
  const analysis::RateSeries& last = series.back();
  QCustomPlot* order = view.rateOrderPlot()->plot();
  emit order->plottableClick(order->graph(static_cast<int>(series.size()) - 1), 1, nullptr);
  const int expected = origin[last.cells[1]];
  QCOMPARE(view.selectedCell(), expected);
  QCOMPARE(sweep.cells[static_cast<std::size_t>(expected)].cell.order, static_cast<int>(last.x[1]));
  // The ring follows: it sits on the clicked point.
  const QCPGraph* ring = view.rateOrderPlot()->markGraph();
  QCOMPARE(ring->dataCount(), 1);
  QCOMPARE(ring->data()->constBegin()->value, last.mean[1]);
}

void SweepResultsViewTest::groupFilterShowsOneGroup() {
  const analysis::SweepResult& sweep = sweepOnce();
  SweepResultsView view;
  view.setSweep(1, sweep);
  auto* box = view.findChild<QComboBox*>(QStringLiteral("groupFilter"));
  QVERIFY(box != nullptr);
  box->setCurrentIndex(box->findData(groupIndex(SensorGroup::Right)));
  int right = 0;
  for (const auto& c : sweep.cells)
    right += c.cell.group == SensorGroup::Right ? 1 : 0;
  QVERIFY(right > 0 && right < static_cast<int>(sweep.cells.size()));
  QCOMPARE(view.cellsView()->model()->rowCount(), right);
  // The group's best cell is selected and the figures are the group's.
  std::size_t best = sweep.cells.size();
  for (std::size_t i : analysis::bestCells(sweep))
    if (sweep.cells[i].cell.group == SensorGroup::Right) best = i;
  QCOMPARE(view.selectedCell(), static_cast<int>(best));
  QCOMPARE(view.timeErrorPlot()->frontCount(),
           static_cast<int>(analysis::paretoFront(sweep, SensorGroup::Right).size()));
  QCOMPARE(view.timeErrorPlot()->pointCount(), right);
  std::vector<int> origin;
  checkRates(view.rateFloorPlot(), analysis::rateSeries(ofGroup(sweep, SensorGroup::Right, &origin),
                                                        analysis::SweptVariable::Floor));
  view.setGroupFilter(std::nullopt);
  QCOMPARE(box->currentData().toInt(), -1);
  QCOMPARE(view.cellsView()->model()->rowCount(), static_cast<int>(sweep.cells.size()));
  view.selectBestCell(SensorGroup::FrontLeftCorner);
  QCOMPARE(sweep.cells[static_cast<std::size_t>(view.selectedCell())].cell.group,
           SensorGroup::FrontLeftCorner);
}

void SweepResultsViewTest::exportsWriteTheReportCsvAndImages() {
  const analysis::SweepResult& sweep = sweepOnce();
  SweepResultsView view;
  view.resize(1200, 800);
  view.setSweep(1, sweep);
  QTemporaryDir dir;
  for (const gui::TableView* table : {view.confusionCounts(), view.oneVsRest()}) {
    const QString csv = dir.filePath(QStringLiteral("table.csv"));
    QVERIFY(table->exportCsv(csv).ok());
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const std::string written = file.readAll().toStdString();
    QVERIFY(written.find(',') != std::string::npos);
    QCOMPARE(written, table->table().render(analysis::TableStyle::Csv));
  }
  const QString png = dir.filePath(QStringLiteral("time.png"));
  QVERIFY(view.timeErrorPlot()->exportPng(png));
  QFile pngFile(png);
  QVERIFY(pngFile.open(QIODevice::ReadOnly));
  QCOMPARE(pngFile.read(8), QByteArray("\x89PNG\r\n\x1a\n", 8));
  QImage image(png);
  QVERIFY(!image.isNull());
  QVERIFY(image.width() >= 800);
  // Not a blank page: the plot drew in more than one colour.
  QSet<QRgb> colours;
  for (int y = 0; y < image.height(); y += 7)
    for (int x = 0; x < image.width(); x += 7)
      colours.insert(image.pixel(x, y));
  QVERIFY(colours.size() > 3);
  const QString pdf = dir.filePath(QStringLiteral("floor.pdf"));
  QVERIFY(view.rateFloorPlot()->exportPdf(pdf));
  QFile pdfFile(pdf);
  QVERIFY(pdfFile.open(QIODevice::ReadOnly));
  QVERIFY(pdfFile.read(4) == "%PDF");
  QVERIFY(!view.confusionCounts()->exportCsv(dir.filePath(QStringLiteral("no/such/x.csv"))).ok());
  QVERIFY(!view.timeErrorPlot()->exportPng(dir.filePath(QStringLiteral("no/such/x.png"))));
}

void SweepResultsViewTest::tableViewSortsNumbersAsNumbers() {
  analysis::Table t;
  t.title = "numbers";
  t.header = {"name", "value"};
  t.rows = {{"a", "10"}, {"b", "9"}, {"c", "100"}, {"d", "-2.5"}};
  gui::TableView view;
  view.setTable(t);
  view.view()->sortByColumn(1, Qt::AscendingOrder);
  const QAbstractItemModel* m = view.view()->model();
  QStringList shown;
  for (int r = 0; r < m->rowCount(); ++r)
    shown << m->index(r, 1).data().toString();
  QCOMPARE(shown, QStringList({"-2.5", "9", "10", "100"}));
  QCOMPARE(m->index(0, 1).data(Qt::TextAlignmentRole).toInt() & Qt::AlignRight,
           int(Qt::AlignRight));
  QCOMPARE(m->index(0, 0).data(Qt::TextAlignmentRole).toInt() & Qt::AlignRight, 0);
  // The table's own order is kept for export, whatever the view's sort.
  QCOMPARE(view.table().rows, t.rows);
}

void SweepResultsViewTest::failedCellShowsItsReason() {
  analysis::SweepResult sweep = sweepOnce();
  analysis::SweepCellResult failed;
  failed.cell.group = SensorGroup::Back;
  failed.reason = "no labelled contact samples";
  sweep.cells.push_back(failed);
  SweepResultsView view;
  view.setSweep(1, sweep);
  QVERIFY(view.selectedCell() != static_cast<int>(sweep.cells.size()) - 1);
  view.selectCell(static_cast<int>(sweep.cells.size()) - 1);
  QVERIFY(view.confusionCounts()->table().rows.empty());
  QVERIFY(view.patterns()->table().rows.empty());
  int shown = 0;
  for (QLabel* label : view.findChildren<QLabel*>())
    shown += label->text().contains(QStringLiteral("no labelled contact samples")) ? 1 : 0;
  QVERIFY(shown >= 2);  // on the confusion page and the patterns page
  // It is not drawn, and the best cell of its group does not exist.
  QCOMPARE(view.timeErrorPlot()->pointCount(), static_cast<int>(sweepOnce().cells.size()));
  QCOMPARE(view.timeErrorPlot()->markGraph()->dataCount(), 0);
  view.selectBestCell(SensorGroup::Back);
  QCOMPARE(view.selectedCell(), static_cast<int>(sweep.cells.size()) - 1);
}

void SweepResultsViewTest::emptyAndCancelledSweeps() {
  SweepResultsView view;
  QCOMPARE(view.title()->text(), QStringLiteral("No sweep"));
  QCOMPARE(view.selectedCell(), -1);
  QVERIFY(!view.timeErrorPlot()->emptyMessage().isEmpty());
  QVERIFY(!view.rateFloorPlot()->emptyMessage().isEmpty());
  QCOMPARE(view.rateFloorPlot()->seriesCount(), 0);
  analysis::SweepResult cancelled = sweepOnce();
  cancelled.cells.resize(5);
  cancelled.cancelled = true;
  view.setSweep(4, cancelled);
  QVERIFY(view.title()->text().contains(QStringLiteral("cancelled")));
  QVERIFY(view.title()->text().contains(QStringLiteral("5 cells")));
  QVERIFY(view.timeErrorPlot()->emptyMessage().isEmpty());
  cancelled.cancelled = false;
  view.setSweep(4, cancelled);
  QVERIFY(!view.title()->text().contains(QStringLiteral("cancelled")));
}

// Guards the time axis whose labels ran together ("0.000750.001") and left the lower decades
// bare, and the black FRC points that read as the Pareto front's rings: a tick at every decade
// in view, labelled in ms below a second, no two labels touching; FRC's points are not black.
void SweepResultsViewTest::timeAxisLabelsEveryDecadeInMsWithoutCollisions() {
  analysis::SweepResult sweep;
  const double seconds[] = {0.00028, 0.0031, 0.042, 0.5};
  for (int i = 0; i < 4; ++i) {
    analysis::SweepCellResult r;
    r.cell.group = i < 2 ? SensorGroup::FrontRightCorner : SensorGroup::Front;
    r.ok = true;
    r.fitSeconds = seconds[i];
    r.confusion.add(ContactClass::Wall, ContactClass::Wall, 10 + i);
    r.confusion.add(ContactClass::Corner, ContactClass::Wall, 3);
    r.confusion.add(ContactClass::Corner, ContactClass::Corner, 5);
    r.metrics = analysis::computeMetrics(r.confusion);
    sweep.cells.push_back(r);
  }
  SweepPlot plot;
  plot.resize(620, 360);
  plot.show();
  QVERIFY(QTest::qWaitForWindowExposed(&plot));
  plot.showTimeError(sweep, std::nullopt);
  plot.plot()->replot();
  QCPAxis* x = plot.plot()->xAxis;
  const QVector<double> ticks = x->tickVector();
  const QVector<QString> labels = x->tickVectorLabels();
  QStringList shown(labels.begin(), labels.end());
  for (const char* decade : {"0.1 ms", "1 ms", "10 ms", "100 ms"})
    QVERIFY2(shown.contains(QString::fromLatin1(decade)), qPrintable(shown.join(QLatin1Char('|'))));
  const QFontMetrics metrics(x->tickLabelFont());
  for (qsizetype i = 1; i < ticks.size(); ++i) {
    const double gap = x->coordToPixel(ticks[i]) - x->coordToPixel(ticks[i - 1]);
    const double needed =
        (metrics.horizontalAdvance(labels[i]) + metrics.horizontalAdvance(labels[i - 1])) / 2.0;
    QVERIFY2(gap >= needed, qPrintable(labels[i - 1] + QStringLiteral(" / ") + labels[i]));
  }
  bool sawFrc = false;
  for (int g = 0; g < plot.plot()->graphCount(); ++g) {
    QCPGraph* graph = plot.plot()->graph(g);
    if (!graph->name().contains(QStringLiteral("FRC"))) continue;
    sawFrc = true;
    QVERIFY(graph->scatterStyle().brush().color() != QColor(Qt::black));
  }
  QVERIFY(sawFrc);
  // A hover on a point reads its time in ms.
  const QPoint at(qRound(x->coordToPixel(0.00028)),
                  qRound(plot.plot()->yAxis->coordToPixel(
                      100.0 - 100.0 * sweep.cells[0].metrics.balancedAccuracy)));
  QVERIFY2(plot.tipAt(plot.plot()->mapTo(&plot, at)).contains(QStringLiteral("0.28 ms")),
           qPrintable(plot.tipAt(plot.plot()->mapTo(&plot, at))));
}

QTEST_MAIN(SweepResultsViewTest)
// A sweep scoring the step and online decisions: every fit appears once per decision, told apart
// by the Decision column; the decision filter shows one mode, and the rate figures hold one mode
// (the same fit under two decisions would be two points at one x).
void SweepResultsViewTest::decisionModesHaveAColumnAFilterAndOneFigureEach() {
  static const RunData a = testdata::makeLabelledRun(1200, 21, 0.9);
  static const RunData b = testdata::makeLabelledRun(800, 22, 0.9);
  analysis::SweepGrid g;
  g.groups = {SensorGroup::Right};
  g.orders = {1, 2};
  g.forms = {analysis::CovarianceForm::NodalDiag};
  g.varianceFloors = {0.01, 0.1};
  g.decisions = {analysis::DecisionMode::Step, analysis::DecisionMode::Online};
  g.maxIterations = 30;
  const analysis::SweepResult sweep = analysis::runSweep({{&a, analysis::labelsFromTruth(a)}},
                                                         {{&b, analysis::labelsFromTruth(b)}}, g);
  QCOMPARE(static_cast<int>(sweep.cells.size()), 8);
  SweepResultsView view;
  view.setSweep(3, sweep);
  const QAbstractItemModel* m = view.cellsView()->model();
  QCOMPARE(m->headerData(gui::SweepCellsModel::Decision, Qt::Horizontal).toString(),
           QStringLiteral("Decision"));
  const auto* proxy = static_cast<const QSortFilterProxyModel*>(m);
  int online = 0;
  for (int row = 0; row < m->rowCount(); ++row) {
    const auto& cell =
        sweep.cells[static_cast<std::size_t>(proxy->mapToSource(m->index(row, 0)).row())];
    QCOMPARE(m->data(m->index(row, gui::SweepCellsModel::Decision)).toString(),
             QString::fromUtf8(analysis::decisionModeName(cell.cell.decision).data()));
    online += cell.cell.decision == analysis::DecisionMode::Online ? 1 : 0;
  }
  QCOMPARE(online, 4);
  // The selected cell's title names its decision.
  const auto& selected = sweep.cells[static_cast<std::size_t>(view.selectedCell())];
  QVERIFY(
      view.findChild<QLabel*>(QStringLiteral("cellTitle"))
          ->text()
          .contains(QString::fromUtf8(analysis::decisionModeName(selected.cell.decision).data()) +
                    QStringLiteral(" decision")));
  // The rate figures hold the selected cell's decision only.
  const auto only = [&](analysis::DecisionMode d) {
    analysis::SweepResult out;
    out.grid = sweep.grid;
    for (const auto& c : sweep.cells)
      if (c.cell.decision == d) out.cells.push_back(c);
    return out;
  };
  checkRates(view.rateFloorPlot(),
             analysis::rateSeries(only(selected.cell.decision), analysis::SweptVariable::Floor));
  // The filter offers the scored modes and shows one of them.
  auto* box = view.findChild<QComboBox*>(QStringLiteral("decisionFilter"));
  QVERIFY(box != nullptr);
  QCOMPARE(box->count(), 3);  // all, step, online
  QCOMPARE(box->findData(static_cast<int>(analysis::DecisionMode::Offline)), -1);
  box->setCurrentIndex(box->findData(static_cast<int>(analysis::DecisionMode::Online)));
  QCOMPARE(m->rowCount(), 4);
  for (int row = 0; row < m->rowCount(); ++row)
    QCOMPARE(m->data(m->index(row, gui::SweepCellsModel::Decision)).toString(),
             QStringLiteral("online"));
  QCOMPARE(sweep.cells[static_cast<std::size_t>(view.selectedCell())].cell.decision,
           analysis::DecisionMode::Online);
  checkRates(view.rateFloorPlot(), analysis::rateSeries(only(analysis::DecisionMode::Online),
                                                        analysis::SweptVariable::Floor));
  view.setDecisionFilter(analysis::DecisionMode::Step);
  QCOMPARE(box->currentData().toInt(), static_cast<int>(analysis::DecisionMode::Step));
  QCOMPARE(sweep.cells[static_cast<std::size_t>(view.selectedCell())].cell.decision,
           analysis::DecisionMode::Step);
  checkRates(view.rateFloorPlot(), analysis::rateSeries(only(analysis::DecisionMode::Step),
                                                        analysis::SweptVariable::Floor));
  view.setDecisionFilter(std::nullopt);
  QCOMPARE(m->rowCount(), 8);
}

// The test steps beside the scores: the count, the rarest class's count, "too few" below
// kMinTestSteps, per-class counts in the tooltip; "none" for a cell without test steps.
void SweepResultsViewTest::testStepsShowCountsAndTooFew() {
  analysis::SweepResult sweep;
  sweep.grid = sweepOnce().grid;
  analysis::SweepCellResult enough = sweepOnce().cells.front();
  enough.ok = true;
  enough.confusion = {};
  enough.confusion.add(ContactClass::Wall, ContactClass::Wall, 200);
  enough.confusion.add(ContactClass::Corner, ContactClass::Corner, 40);
  analysis::SweepCellResult few = enough;
  few.cell.seed = 2;
  few.confusion.add(ContactClass::LeavingWall, ContactClass::Wall, 7);
  analysis::SweepCellResult none = enough;
  none.cell.seed = 3;
  none.confusion = {};
  sweep.cells = {enough, few, none};
  gui::SweepCellsModel model;
  model.setCells(sweep.cells);
  const auto shown = [&](int row) {
    return model.data(model.index(row, gui::SweepCellsModel::TestSteps)).toString();
  };
  QCOMPARE(model.headerData(gui::SweepCellsModel::TestSteps, Qt::Horizontal).toString(),
           QStringLiteral("Test steps"));
  QCOMPARE(shown(0), QStringLiteral("240 (rarest 40)"));
  QCOMPARE(shown(1), QStringLiteral("247 (rarest 7, too few)"));
  QCOMPARE(shown(2), QStringLiteral("none"));
  // Without test steps there is no score: never a 0, and it sorts below every real score.
  const auto balanced = [&](int row, int role) {
    return model.data(model.index(row, gui::SweepCellsModel::BalancedAccuracy), role);
  };
  QCOMPARE(balanced(2, Qt::DisplayRole).toString(), QStringLiteral("no test data"));
  QVERIFY(balanced(2, Qt::UserRole).toDouble() < balanced(1, Qt::UserRole).toDouble());
  QVERIFY(balanced(0, Qt::DisplayRole).toString() != QStringLiteral("no test data"));
  QCOMPARE(model.data(model.index(2, gui::SweepCellsModel::Accuracy)).toString(),
           QStringLiteral("no test data"));
  QCOMPARE(model.data(model.index(1, gui::SweepCellsModel::TestSteps), Qt::UserRole).toULongLong(),
           247ull);
  const QString tip =
      model.data(model.index(1, gui::SweepCellsModel::TestSteps), Qt::ToolTipRole).toString();
  QVERIFY2(tip.contains(QStringLiteral("LeavingWall: 7 test steps (too few)")), qPrintable(tip));
  QVERIFY2(tip.contains(QStringLiteral("Wall: 200 test steps")), qPrintable(tip));
  QVERIFY(!tip.contains(QStringLiteral("Corner: 40 test steps (too few)")));
}

#include "sweep_results_view_test.moc"
