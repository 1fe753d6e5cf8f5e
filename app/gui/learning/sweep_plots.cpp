#include "app/gui/learning/sweep_plots.h"

#include <qcustomplot.h>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace tactile::gui {

namespace {

const QColor kSeriesColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28),
                                 QColor(0x2c, 0xa0, 0x2c), QColor(0xff, 0x7f, 0x0e),
                                 QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                 QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf),
                                 QColor(0x7f, 0x7f, 0x7f), QColor(0xbc, 0xbd, 0x22)};
constexpr int kColourCount = sizeof kSeriesColours / sizeof kSeriesColours[0];
constexpr int kMaxLegendEntries = 14;

void useLogAxis(QCPAxis* axis) {
  axis->setScaleType(QCPAxis::stLogarithmic);
  QSharedPointer<QCPAxisTickerLog> ticker(new QCPAxisTickerLog);
  axis->setTicker(ticker);
  axis->setNumberFormat(QStringLiteral("gb"));
  axis->setNumberPrecision(3);
}

void useLinearAxis(QCPAxis* axis) {
  axis->setScaleType(QCPAxis::stLinear);
  axis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
  axis->setNumberFormat(QStringLiteral("g"));
  axis->setNumberPrecision(6);
}

// Range over positive values for a log axis (or any values for a linear one), padded.
QCPRange paddedRange(const std::vector<double>& values, bool log) {
  if (values.empty()) return log ? QCPRange(1e-3, 1) : QCPRange(0, 1);
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  if (log) return QCPRange(*mn / 1.5, *mx * 1.5);
  const double pad = *mx > *mn ? 0.05 * (*mx - *mn) : 1.0;
  return QCPRange(*mn - pad, *mx + pad);
}

}  // namespace

SweepPlot::SweepPlot(QWidget* parent) : QWidget(parent) {
  plot_ = new QCustomPlot;
  plot_->setMinimumSize(360, 260);
  plot_->yAxis->setRange(0, 100);
  plot_->legend->setFont(QFont(font().family(), 8));
  plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignRight);
  connect(plot_, &QCustomPlot::plottableClick, this, &SweepPlot::onPlottableClick);
  auto* png = new QPushButton(tr("Export PNG..."));
  png->setObjectName(QStringLiteral("exportPng"));
  auto* pdf = new QPushButton(tr("Export PDF..."));
  pdf->setObjectName(QStringLiteral("exportPdf"));
  connect(png, &QPushButton::clicked, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export PNG"), QString(), tr("PNG images (*.png)"));
    if (!path.isEmpty() && !exportPng(path))
      QMessageBox::warning(this, tr("Export PNG"), tr("Cannot write %1").arg(path));
  });
  connect(pdf, &QPushButton::clicked, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export PDF"), QString(), tr("PDF files (*.pdf)"));
    if (!path.isEmpty() && !exportPdf(path))
      QMessageBox::warning(this, tr("Export PDF"), tr("Cannot write %1").arg(path));
  });
  auto* buttons = new QHBoxLayout;
  buttons->addStretch();
  buttons->addWidget(png);
  buttons->addWidget(pdf);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_, 1);
  layout->addLayout(buttons);
}

void SweepPlot::clear() {
  plot_->clearPlottables();
  plot_->clearItems();
  cellsOf_.clear();
  seriesCount_ = 0;
  frontCount_ = 0;
  pointCount_ = 0;
}

void SweepPlot::showRates(const std::vector<analysis::RateSeries>& series,
                          analysis::SweptVariable variable) {
  clear();
  std::vector<double> xs;
  bool allPositive = true;
  for (const analysis::RateSeries& s : series)
    for (double x : s.x) {
      xs.push_back(x);
      allPositive = allPositive && x > 0;
    }
  const bool log = allPositive && !xs.empty();
  if (log) {
    useLogAxis(plot_->xAxis);
  } else {
    useLinearAxis(plot_->xAxis);
  }
  plot_->xAxis->setLabel(variable == analysis::SweptVariable::Floor ? tr("Variance floor")
                                                                    : tr("Model order"));
  plot_->yAxis->setLabel(tr("Correct rate per class (%)"));
  for (const analysis::RateSeries& s : series) {
    const QColor colour = kSeriesColours[seriesCount_ % kColourCount];
    QCPGraph* graph = plot_->addGraph();
    graph->setName(QString::fromStdString(s.label));
    graph->setPen(QPen(colour, 1.8));
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, colour, colour, 5));
    QVector<double> keys, means, minus, plus;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.mean[i]) || (log && s.x[i] <= 0)) continue;
      keys << s.x[i];
      means << s.mean[i];
      minus << s.mean[i] - s.min[i];
      plus << s.max[i] - s.mean[i];
    }
    graph->setData(keys, means, true);
    auto* bars = new QCPErrorBars(plot_->xAxis, plot_->yAxis);
    bars->removeFromLegend();
    bars->setDataPlottable(graph);
    bars->setData(minus, plus);
    bars->setPen(QPen(colour.lighter(130), 1));
    pointCount_ += static_cast<int>(keys.size());
    ++seriesCount_;
  }
  // Ticks at exactly the swept values (a log ticker would pick round numbers between them).
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  QSharedPointer<QCPAxisTickerText> ticks(new QCPAxisTickerText);
  for (double x : xs)
    ticks->addTick(x, QString::number(x, 'g', 4));
  plot_->xAxis->setTicker(ticks);
  plot_->xAxis->setRange(paddedRange(xs, log));
  plot_->yAxis->setRange(0, 105);
  plot_->legend->setVisible(seriesCount_ > 0 && seriesCount_ <= kMaxLegendEntries);
  plot_->replot();
}

void SweepPlot::showTimeError(const analysis::SweepResult& sweep,
                              std::optional<SensorGroup> group) {
  clear();
  useLogAxis(plot_->xAxis);
  plot_->xAxis->setLabel(tr("Fit + predict time (s)"));
  plot_->yAxis->setLabel(tr("Error: 100 - balanced accuracy (%)"));
  constexpr double kMinSeconds = 1e-6;
  auto timeOf = [&](std::size_t i) {
    const analysis::SweepCellResult& r = sweep.cells[i];
    return std::max(r.fitSeconds + r.predictSeconds, kMinSeconds);
  };
  auto errorOf = [&](std::size_t i) {
    return 100.0 - 100.0 * sweep.cells[i].metrics.balancedAccuracy;
  };
  // One graph of points per group, points by ascending time (QCustomPlot keeps data sorted).
  std::map<int, std::vector<std::size_t>> byGroup;
  std::vector<double> times;
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const analysis::SweepCellResult& r = sweep.cells[i];
    if (!r.ok || r.confusion.total() == 0 || (group && r.cell.group != *group)) continue;
    if (!std::isfinite(r.fitSeconds + r.predictSeconds) ||
        !std::isfinite(r.metrics.balancedAccuracy))
      continue;
    byGroup[groupIndex(r.cell.group)].push_back(i);
    times.push_back(timeOf(i));
  }
  for (auto& [g, cells] : byGroup) {
    std::stable_sort(cells.begin(), cells.end(),
                     [&](std::size_t a, std::size_t b) { return timeOf(a) < timeOf(b); });
    const QColor colour = kSeriesColours[g % kColourCount];
    QCPGraph* graph = plot_->addGraph();
    graph->setName(tr("group %1")
                       .arg(QString::fromUtf8(
                           kSensorGroups[static_cast<std::size_t>(g)].shortName.data(),
                           static_cast<qsizetype>(
                               kSensorGroups[static_cast<std::size_t>(g)].shortName.size()))));
    graph->setLineStyle(QCPGraph::lsNone);
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colour, colour, 6));
    QVector<double> keys, values;
    std::vector<int>& cellIndex = cellsOf_[graph];
    for (std::size_t i : cells) {
      keys << timeOf(i);
      values << errorOf(i);
      cellIndex.push_back(static_cast<int>(i));
    }
    graph->setData(keys, values, true);
    pointCount_ += static_cast<int>(keys.size());
    ++seriesCount_;
  }
  const std::vector<std::size_t> front = analysis::paretoFront(sweep, group);
  if (!front.empty()) {
    QCPGraph* graph = plot_->addGraph();
    graph->setName(tr("Pareto front (%1)").arg(front.size()));
    graph->setPen(QPen(Qt::black, 1.2, Qt::DashLine));
    graph->setLineStyle(QCPGraph::lsStepLeft);
    graph->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black, 1.5), Qt::NoBrush, 11));
    QVector<double> keys, values;
    std::vector<int>& cellIndex = cellsOf_[graph];
    for (std::size_t i : front) {
      keys << timeOf(i);
      values << errorOf(i);
      cellIndex.push_back(static_cast<int>(i));
    }
    graph->setData(keys, values, true);
    frontCount_ = static_cast<int>(front.size());
  }
  plot_->xAxis->setRange(paddedRange(times, true));
  plot_->yAxis->setRange(0, 105);
  plot_->legend->setVisible(seriesCount_ > 0);
  plot_->replot();
}

void SweepPlot::onPlottableClick(QCPAbstractPlottable* plottable, int dataIndex, QMouseEvent*) {
  const auto it = cellsOf_.find(plottable);
  if (it == cellsOf_.end() || dataIndex < 0 || dataIndex >= static_cast<int>(it->second.size()))
    return;
  emit cellClicked(it->second[static_cast<std::size_t>(dataIndex)]);
}

bool SweepPlot::exportPng(const QString& path) {
  return plot_->savePng(path, std::max(plot_->width(), 800), std::max(plot_->height(), 500));
}

bool SweepPlot::exportPdf(const QString& path) {
  return plot_->savePdf(path, std::max(plot_->width(), 800), std::max(plot_->height(), 500));
}

}  // namespace tactile::gui
