// The sweep results views: one table row per cell sorted by balanced accuracy, the selected cell's
// confusion read back equal to the cell's, cells streaming in, the figures drawing what the core's
// series and Pareto front hold, CSV and image exports, and a failed cell's reason.
#include <qcustomplot.h>
#include <QComboBox>
#include <QFile>
#include <QImage>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include "analysis/report.h"
#include "analysis/sweep.h"
#include "app/gui/learning/sweep_cells_model.h"
#include "app/gui/learning/sweep_plots.h"
#include "app/gui/learning/sweep_results_view.h"
#include "app/gui/learning/table_view.h"
#include "tests/analysis/learn_test_data.h"

using namespace tactile;
using tactile::gui::SweepResultsView;

namespace {

// A real sweep over synthetic labelled runs: 2 groups x 3 orders x 2 forms x 2 floors, plus a
// group without data whose cells fail.
analysis::SweepResult makeSweep() {
  static const RunData a = testdata::makeLabelledRun(1200, 21);
  static const RunData b = testdata::makeLabelledRun(800, 22);
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

double shownScore(const QTableView* view, int row) {
  const QAbstractItemModel* m = view->model();
  return m->data(m->index(row, gui::SweepCellsModel::BalancedAccuracy), Qt::UserRole).toDouble();
}

}  // namespace

class SweepResultsViewTest : public QObject {
  Q_OBJECT

 private slots:
  void tableHasEveryCellSortedByBalancedAccuracy();
  void selectedCellShowsItsConfusion();
  void cellsStreamIn();
  void figuresDrawTheCoreSeriesAndFront();
  void groupFilterShowsOneGroup();
  void exportsWriteTheReportCsvAndImages();
  void failedCellShowsItsReason();
};

void SweepResultsViewTest::tableHasEveryCellSortedByBalancedAccuracy() {
  const analysis::SweepResult sweep = makeSweep();
  SweepResultsView view;
  view.setSweep(7, sweep);
  QCOMPARE(view.cellsView()->model()->rowCount(), static_cast<int>(sweep.cells.size()));
  for (int row = 1; row < view.cellsView()->model()->rowCount(); ++row)
    QVERIFY(shownScore(view.cellsView(), row) <= shownScore(view.cellsView(), row - 1));
  // The best cell is selected first.
  double best = -1;
  for (const analysis::SweepCellResult& c : sweep.cells)
    if (c.ok) best = std::max(best, c.metrics.balancedAccuracy);
  QVERIFY(view.selectedCell() >= 0);
  QCOMPARE(sweep.cells[static_cast<std::size_t>(view.selectedCell())].metrics.balancedAccuracy,
           best);
}

void SweepResultsViewTest::selectedCellShowsItsConfusion() {
  const analysis::SweepResult sweep = makeSweep();
  SweepResultsView view;
  view.setSweep(1, sweep);
  for (int index : {0, 5, static_cast<int>(sweep.cells.size()) - 1}) {
    const analysis::SweepCellResult& cell = sweep.cells[static_cast<std::size_t>(index)];
    if (!cell.ok) continue;
    view.selectCell(index);
    QCOMPARE(view.selectedCell(), index);
    // Rows are the true classes, columns 1.. the predicted ones, as the core's table.
    const std::vector<ContactClass> predicted = cell.confusion.activeClasses();
    int row = 0;
    for (ContactClass t : predicted) {
      if (cell.confusion.trueCount(t) == 0) continue;
      for (std::size_t c = 0; c < predicted.size(); ++c) {
        QCOMPARE(view.confusionCounts()->cellText(row, static_cast<int>(c) + 1).toULongLong(),
                 static_cast<qulonglong>(cell.confusion.count(t, predicted[c])));
      }
      ++row;
    }
    QVERIFY(row > 0);
    // Clicking a row selects it too.
    QSignalSpy selected(&view, &SweepResultsView::cellSelected);
    view.cellsView()->selectRow(0);
    if (view.selectedCell() != index) QCOMPARE(selected.count(), 1);
  }
  // Pattern rows add up to the cell's test rows.
  const analysis::SweepCellResult& chosen =
      sweep.cells[static_cast<std::size_t>(view.selectedCell())];
  QCOMPARE(view.patterns()->table().rows.size(), chosen.patterns.rows.size());
}

void SweepResultsViewTest::cellsStreamIn() {
  const analysis::SweepResult sweep = makeSweep();
  analysis::SweepResult empty;
  empty.grid = sweep.grid;
  SweepResultsView view;
  view.setSweep(3, empty);
  QCOMPARE(view.cellsView()->model()->rowCount(), 0);
  QCOMPARE(view.selectedCell(), -1);
  view.tabs()->setCurrentWidget(view.timeErrorPlot());
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    view.addCell(sweep.cells[i]);
    QCOMPARE(view.cellsView()->model()->rowCount(), static_cast<int>(i + 1));
  }
  QVERIFY(view.selectedCell() >= 0);  // the first cell with a model
  // The visible figure follows the stream.
  QCOMPARE(view.timeErrorPlot()->frontCount(),
           static_cast<int>(analysis::paretoFront(sweep).size()));
}

void SweepResultsViewTest::figuresDrawTheCoreSeriesAndFront() {
  const analysis::SweepResult sweep = makeSweep();
  SweepResultsView view;
  view.setSweep(1, sweep);
  // The rate figures hold the selected cell's group.
  const SensorGroup shownGroup =
      sweep.cells[static_cast<std::size_t>(view.selectedCell())].cell.group;
  analysis::SweepResult ofGroup;
  for (const auto& c : sweep.cells)
    if (c.cell.group == shownGroup) ofGroup.cells.push_back(c);
  const auto floorSeries = analysis::rateSeries(ofGroup, analysis::SweptVariable::Floor);
  const auto orderSeries = analysis::rateSeries(ofGroup, analysis::SweptVariable::Order);
  QVERIFY(!floorSeries.empty());
  QCOMPARE(view.rateFloorPlot()->seriesCount(), static_cast<int>(floorSeries.size()));
  QCOMPARE(view.rateOrderPlot()->seriesCount(), static_cast<int>(orderSeries.size()));
  std::size_t points = 0;
  for (const auto& s : floorSeries)
    points += s.x.size();
  QCOMPARE(view.rateFloorPlot()->pointCount(), static_cast<int>(points));
  QVERIFY(view.rateFloorPlot()->plot()->xAxis->scaleType() == QCPAxis::stLogarithmic);
  const std::vector<std::size_t> front = analysis::paretoFront(sweep);
  QVERIFY(!front.empty());
  QCOMPARE(view.timeErrorPlot()->frontCount(), static_cast<int>(front.size()));
  std::size_t ok = 0;
  for (const auto& c : sweep.cells)
    ok += c.ok && c.confusion.total() > 0 ? 1 : 0;
  QCOMPARE(view.timeErrorPlot()->pointCount(), static_cast<int>(ok));
  // A click on a front point selects that cell.
  QSignalSpy clicked(view.timeErrorPlot(), &gui::SweepPlot::cellClicked);
  QCustomPlot* plot = view.timeErrorPlot()->plot();
  QCPGraph* frontGraph = plot->graph(plot->graphCount() - 1);
  emit plot->plottableClick(frontGraph, 0, nullptr);
  QCOMPARE(clicked.count(), 1);
  QCOMPARE(view.selectedCell(), static_cast<int>(front.front()));
}

void SweepResultsViewTest::groupFilterShowsOneGroup() {
  const analysis::SweepResult sweep = makeSweep();
  SweepResultsView view;
  view.setSweep(1, sweep);
  view.setGroupFilter(SensorGroup::Right);
  int right = 0;
  for (const auto& c : sweep.cells)
    right += c.cell.group == SensorGroup::Right ? 1 : 0;
  QCOMPARE(view.cellsView()->model()->rowCount(), right);
  QCOMPARE(sweep.cells[static_cast<std::size_t>(view.selectedCell())].cell.group,
           SensorGroup::Right);
  QCOMPARE(view.timeErrorPlot()->frontCount(),
           static_cast<int>(analysis::paretoFront(sweep, SensorGroup::Right).size()));
  view.setGroupFilter(std::nullopt);
  QCOMPARE(view.cellsView()->model()->rowCount(), static_cast<int>(sweep.cells.size()));
}

void SweepResultsViewTest::exportsWriteTheReportCsvAndImages() {
  const analysis::SweepResult sweep = makeSweep();
  SweepResultsView view;
  view.resize(1200, 800);
  view.setSweep(1, sweep);
  QTemporaryDir dir;
  const QString csv = dir.filePath(QStringLiteral("confusion.csv"));
  QVERIFY(view.confusionCounts()->exportCsv(csv).ok());
  QFile file(csv);
  QVERIFY(file.open(QIODevice::ReadOnly));
  QCOMPARE(file.readAll().toStdString(),
           view.confusionCounts()->table().render(analysis::TableStyle::Csv));
  const QString png = dir.filePath(QStringLiteral("time.png"));
  QVERIFY(view.timeErrorPlot()->exportPng(png));
  QImage image(png);
  QVERIFY(!image.isNull());
  QVERIFY(image.width() >= 800);
  const QString pdf = dir.filePath(QStringLiteral("floor.pdf"));
  QVERIFY(view.rateFloorPlot()->exportPdf(pdf));
  QFile pdfFile(pdf);
  QVERIFY(pdfFile.open(QIODevice::ReadOnly));
  QVERIFY(pdfFile.read(4) == "%PDF");
  QVERIFY(!view.confusionCounts()->exportCsv(dir.filePath(QStringLiteral("no/such/x.csv"))).ok());
}

void SweepResultsViewTest::failedCellShowsItsReason() {
  analysis::SweepResult sweep = makeSweep();
  analysis::SweepCellResult failed;
  failed.cell.group = SensorGroup::Back;
  failed.reason = "no labelled contact samples";
  sweep.cells.push_back(failed);
  SweepResultsView view;
  view.setSweep(1, sweep);
  view.selectCell(static_cast<int>(sweep.cells.size()) - 1);
  QVERIFY(view.confusionCounts()->table().rows.empty());
  QVERIFY(view.findChildren<QLabel*>().size() > 0);
  bool shown = false;
  for (QLabel* label : view.findChildren<QLabel*>())
    shown = shown || label->text().contains(QStringLiteral("no labelled contact samples"));
  QVERIFY(shown);
}

QTEST_MAIN(SweepResultsViewTest)
#include "sweep_results_view_test.moc"
