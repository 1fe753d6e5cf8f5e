#include "app/gui/learning/sweep_plots.h"

#include <qcustomplot.h>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QMessageBox>
#include <QPushButton>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "app/gui/common/file_dialog_memory.h"

namespace tactile::gui {

namespace {

// Okabe and Ito's palette (yellow darkened to show on white): its hues stay apart for readers
// with any common colour-vision deficiency, and no red sits beside a green.
const QColor kSeriesColours[] = {QColor(0x00, 0x72, 0xb2), QColor(0xe6, 0x9f, 0x00),
                                 QColor(0x00, 0x9e, 0x73), QColor(0xcc, 0x79, 0xa7),
                                 QColor(0x56, 0xb4, 0xe9), QColor(0xd5, 0x5e, 0x00),
                                 QColor(0xb8, 0xa9, 0x00), QColor(0x00, 0x00, 0x00)};
constexpr int kColourCount = sizeof kSeriesColours / sizeof kSeriesColours[0];
const QCPScatterStyle::ScatterShape kShapes[] = {QCPScatterStyle::ssCircle,
                                                 QCPScatterStyle::ssSquare,
                                                 QCPScatterStyle::ssTriangle,
                                                 QCPScatterStyle::ssDiamond,
                                                 QCPScatterStyle::ssTriangleInverted,
                                                 QCPScatterStyle::ssCross,
                                                 QCPScatterStyle::ssPlus,
                                                 QCPScatterStyle::ssStar};
constexpr int kShapeCount = sizeof kShapes / sizeof kShapes[0];
// More series than this leave the legend out (it would be taller than the figure).
constexpr int kMaxLegendEntries = 24;

// Text ticks at given values, of which it keeps only those whose labels do not run into the
// previous kept one at the axis's current length (swept values like 0.004 and 0.005 sit close on
// a log axis).
class SparseTextTicker : public QCPAxisTickerText {
 public:
  explicit SparseTextTicker(QCPAxis* axis) : axis_(axis) {}
  void generate(const QCPRange& range, const QLocale& locale, QChar formatChar, int precision,
                QVector<double>& ticks, QVector<double>* subTicks,
                QVector<QString>* tickLabels) override {
    QCPAxisTickerText::generate(range, locale, formatChar, precision, ticks, subTicks, tickLabels);
    if (tickLabels == nullptr || tickLabels->size() != ticks.size()) return;
    const QFontMetrics metrics(axis_->tickLabelFont());
    QVector<double> keptTicks;
    QVector<QString> keptLabels;
    double lastRight = -HUGE_VAL;
    for (qsizetype i = 0; i < ticks.size(); ++i) {
      const double half = metrics.horizontalAdvance(tickLabels->at(i)) / 2.0;
      const double x = axis_->coordToPixel(ticks[i]);
      if (x - half < lastRight + kLabelGapPixels) continue;
      lastRight = x + half;
      keptTicks << ticks[i];
      keptLabels << tickLabels->at(i);
    }
    ticks = keptTicks;
    *tickLabels = keptLabels;
  }

 private:
  static constexpr double kLabelGapPixels = 8.0;
  QCPAxis* axis_;
};

// The groups' colours in the time plot: the palette, but grey for the eighth group, whose black
// would read as the Pareto front's black rings.
QColor groupColour(int g) {
  return g % kColourCount == kColourCount - 1 ? QColor(0x88, 0x88, 0x88)
                                              : kSeriesColours[g % kColourCount];
}

// Seconds as a reader takes them in: milliseconds below one second ("0.28 ms", "40 ms"), else
// seconds ("2.5 s").
QString secondsText(double seconds) {
  if (seconds < 1.0) return QObject::tr("%1 ms").arg(QString::number(1000.0 * seconds, 'g', 3));
  return QObject::tr("%1 s").arg(QString::number(seconds, 'g', 3));
}

// A log axis of seconds with a labelled tick at every decade in view (none skipped, however
// wide the range), labels in ms below one second, and any label that would run into its
// neighbour left out.
class DecadeSecondsTicker : public SparseTextTicker {
 public:
  using SparseTextTicker::SparseTextTicker;
  void generate(const QCPRange& range, const QLocale& locale, QChar formatChar, int precision,
                QVector<double>& ticks, QVector<double>* subTicks,
                QVector<QString>* tickLabels) override {
    clear();
    const int first = static_cast<int>(std::floor(std::log10(std::max(range.lower, 1e-12))));
    const int last = static_cast<int>(std::ceil(std::log10(std::max(range.upper, 1e-12))));
    for (int e = first; e <= last && e - first < 40; ++e)
      addTick(std::pow(10.0, e), secondsText(std::pow(10.0, e)));
    SparseTextTicker::generate(range, locale, formatChar, precision, ticks, subTicks, tickLabels);
  }
};

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

// A series' colour: one hue per family of settings (all but the fixed value), darker for a
// smaller fixed value, lighter for a larger one.
QColor shade(const QColor& base, int rank, int count) {
  if (count <= 1) return base;
  const double t = static_cast<double>(rank) / (count - 1);
  float h = 0, s = 0, l = 0, a = 1;
  base.getHslF(&h, &s, &l, &a);
  return QColor::fromHslF(h, s, static_cast<float>(0.25 + 0.40 * t), a);
}

}  // namespace

SweepPlot::SweepPlot(QWidget* parent) : QWidget(parent) {
  plot_ = new QCustomPlot;
  plot_->setMinimumSize(360, 260);
  plot_->yAxis->setRange(0, 105);
  QFont small = font();
  small.setPointSizeF(small.pointSizeF() * 0.9);
  plot_->legend->setFont(small);
  // The legend beside the axes, at the top, so it never covers a point.
  auto* side = new QCPLayoutGrid;
  plot_->plotLayout()->addElement(0, 1, side);
  side->addElement(0, 0, plot_->legend);
  side->addElement(1, 0, new QCPLayoutElement(plot_));
  side->setRowStretchFactor(0, 0.001);
  side->setRowStretchFactor(1, 1);
  side->setAutoMargins(QCP::msNone);
  side->setMargins(QMargins(4, 8, 8, 4));
  plot_->plotLayout()->setColumnStretchFactor(1, 0.001);
  empty_ = new QCPItemText(plot_);
  empty_->position->setType(QCPItemPosition::ptAxisRectRatio);
  empty_->position->setCoords(0.5, 0.5);
  empty_->setPositionAlignment(Qt::AlignCenter);
  empty_->setColor(QColor(0x60, 0x60, 0x60));
  ring_ = new QCPItemTracer(plot_);
  ring_->setClipToAxisRect(false);
  ring_->setStyle(QCPItemTracer::tsCircle);
  ring_->setSize(17);
  ring_->setPen(QPen(QColor(0xff, 0xc4, 0x00), 3));
  ring_->setBrush(Qt::NoBrush);
  ring_->setVisible(false);
  connect(plot_, &QCustomPlot::plottableClick, this, &SweepPlot::onPlottableClick);
  // The wheel zooms about the pointer, a drag pans, a double click shows everything again, and
  // hovering a point tells its values.
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->setMouseTracking(true);
  connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* event) {
    const QString tip = pointTip(event->position());
    if (tip.isEmpty())
      QToolTip::hideText();
    else
      QToolTip::showText(plot_->mapToGlobal(event->position().toPoint()), tip, plot_);
  });
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] { resetView(); });
  auto* png = new QPushButton(tr("Export PNG..."));
  png->setObjectName(QStringLiteral("exportPng"));
  auto* pdf = new QPushButton(tr("Export PDF..."));
  pdf->setObjectName(QStringLiteral("exportPdf"));
  connect(png, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export PNG"), startPath(QStringLiteral("figures")), tr("PNG images (*.png)"));
    rememberPath(QStringLiteral("figures"), path);
    if (!path.isEmpty() && !exportPng(path))
      QMessageBox::warning(this, tr("Export PNG"), tr("Cannot write %1").arg(path));
  });
  connect(pdf, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export PDF"), startPath(QStringLiteral("figures")), tr("PDF files (*.pdf)"));
    rememberPath(QStringLiteral("figures"), path);
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
  finish(tr("No fitted cells yet."));
}

void SweepPlot::clear() {
  plot_->clearPlottables();
  front_ = nullptr;
  mark_ = nullptr;
  cellsOf_.clear();
  xOf_.clear();
  pointOf_.clear();
  timeAxis_ = false;
  seriesCount_ = 0;
  frontCount_ = 0;
  pointCount_ = 0;
}

// After the data: the ring of the marked cell, the legend, the empty note, one redraw.
void SweepPlot::finish(const QString& emptyText) {
  mark_ = plot_->addGraph();
  mark_->setLineStyle(QCPGraph::lsNone);
  // The graph holds the marked point; the ring drawn is an item, which unlike a graph may reach
  // past the axes, so a ring on a point at 0 or 100 is drawn whole.
  mark_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssNone));
  mark_->removeFromLegend();
  homeX_ = {plot_->xAxis->range().lower, plot_->xAxis->range().upper};
  homeY_ = {plot_->yAxis->range().lower, plot_->yAxis->range().upper};
  const bool legend = seriesCount_ > 0 && plot_->legend->itemCount() <= kMaxLegendEntries;
  if (!legend) plot_->legend->clearItems();
  plot_->legend->setVisible(legend);
  empty_->setText(pointCount_ == 0 ? emptyText : QString());
  empty_->setVisible(pointCount_ == 0);
  markCell(marked_);
  plot_->replot();
}

QString SweepPlot::emptyMessage() const {
  return empty_->visible() ? empty_->text() : QString();
}

void SweepPlot::showRates(const std::vector<analysis::RateSeries>& series,
                          analysis::SweptVariable variable, const std::vector<int>& cellOf) {
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
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());

  // Families: series equal in all but the fixed value (order or floor) share a hue.
  using Family = std::tuple<int, int, int, int, std::uint64_t>;
  auto familyOf = [](const analysis::RateSeries& s) {
    return Family(groupIndex(s.group), static_cast<int>(s.features), static_cast<int>(s.method),
                  static_cast<int>(s.form), s.seed);
  };
  std::map<Family, int> hue;
  std::map<Family, std::vector<double>> fixedValues;
  for (const analysis::RateSeries& s : series) {
    hue.try_emplace(familyOf(s), static_cast<int>(hue.size()));
    fixedValues[familyOf(s)].push_back(s.fixedValue);
  }
  for (auto& [family, values] : fixedValues) {
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
  }

  // Series at one x are spread a little sideways, so their error bars stay apart; the ticks stay
  // at the swept values.
  // `gap` is the smallest step between swept values: in decades on a log axis.
  double gap = xs.size() > 1 ? HUGE_VAL : 1.0;
  for (std::size_t i = 1; i < xs.size(); ++i)
    gap = std::min(gap, log ? std::log10(xs[i] / xs[i - 1]) : xs[i] - xs[i - 1]);
  const int n = static_cast<int>(series.size());
  const double spread = std::min(0.3, 0.04 * std::max(n - 1, 0)) * gap;
  const double step = n > 1 ? spread / (n - 1) : 0.0;

  for (int k = 0; k < n; ++k) {
    const analysis::RateSeries& s = series[static_cast<std::size_t>(k)];
    const Family family = familyOf(s);
    const std::vector<double>& values = fixedValues[family];
    const int rank = static_cast<int>(std::lower_bound(values.begin(), values.end(), s.fixedValue) -
                                      values.begin());
    const QColor colour =
        shade(kSeriesColours[hue[family] % kColourCount], rank, static_cast<int>(values.size()));
    QCPGraph* graph = plot_->addGraph();
    graph->setName(QString::fromStdString(s.label));
    graph->setPen(QPen(colour, 1.8));
    graph->setScatterStyle(
        QCPScatterStyle(kShapes[rank % kShapeCount], QPen(colour, 1.5), colour, 7));
    const double offset = (k - (n - 1) / 2.0) * step;
    QVector<double> keys, means, minus, plus;
    std::vector<int>& cells = cellsOf_[graph];
    std::vector<double>& trueX = xOf_[graph];
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.mean[i]) || (log && s.x[i] <= 0)) continue;
      const double x = log ? s.x[i] * std::pow(10.0, offset) : s.x[i] + offset;
      keys << x;
      trueX.push_back(s.x[i]);
      means << s.mean[i];
      minus << s.mean[i] - s.min[i];
      plus << s.max[i] - s.mean[i];
      int cell = i < s.cells.size() ? static_cast<int>(s.cells[i]) : -1;
      if (cell >= 0 && !cellOf.empty())
        cell = static_cast<std::size_t>(cell) < cellOf.size()
                   ? cellOf[static_cast<std::size_t>(cell)]
                   : -1;
      cells.push_back(cell);
      if (cell >= 0) pointOf_[cell] = QPointF(x, s.mean[i]);
    }
    graph->setData(keys, means, true);
    auto* bars = new QCPErrorBars(plot_->xAxis, plot_->yAxis);
    bars->removeFromLegend();
    bars->setDataPlottable(graph);
    bars->setData(minus, plus);
    QColor barColour = colour;
    barColour.setAlpha(170);
    bars->setPen(QPen(barColour, 1.2));
    bars->setWhiskerWidth(6);
    pointCount_ += static_cast<int>(keys.size());
    ++seriesCount_;
  }
  QSharedPointer<SparseTextTicker> ticks(new SparseTextTicker(plot_->xAxis));
  for (double x : xs)
    ticks->addTick(x, QString::number(x, 'g', 4));
  plot_->xAxis->setTicker(ticks);
  QCPRange range = paddedRange(xs, log);
  if (log && xs.size() > 1) range = QCPRange(xs.front() / 1.6, xs.back() * 1.6);
  plot_->xAxis->setRange(range);
  plot_->yAxis->setRange(0, 105);
  finish(tr("No fitted cells yet."));
}

void SweepPlot::showTimeError(const analysis::SweepResult& sweep,
                              std::optional<SensorGroup> group) {
  clear();
  useLogAxis(plot_->xAxis);
  plot_->xAxis->setTicker(QSharedPointer<DecadeSecondsTicker>::create(plot_->xAxis));
  timeAxis_ = true;
  plot_->xAxis->setLabel(tr("Fit + predict time"));
  plot_->yAxis->setLabel(tr("Error: 100 - balanced accuracy (%)"));
  constexpr double kMinSeconds = 1e-6;
  auto timeOf = [&](std::size_t i) {
    const analysis::SweepCellResult& r = sweep.cells[i];
    return std::max(r.fitSeconds + r.predictSeconds, kMinSeconds);
  };
  auto errorOf = [&](std::size_t i) {
    return 100.0 - 100.0 * sweep.cells[i].metrics.balancedAccuracy;
  };
  // One graph of points per group and family (boosted trees as squares, the mixtures as dots),
  // points by ascending time (QCustomPlot keeps data sorted).
  std::map<std::pair<int, bool>, std::vector<std::size_t>> bySeries;
  std::vector<double> times;
  bool anyTrees = false, anyMixtures = false;
  for (std::size_t i = 0; i < sweep.cells.size(); ++i) {
    const analysis::SweepCellResult& r = sweep.cells[i];
    if (!r.ok || r.confusion.total() == 0 || (group && r.cell.group != *group)) continue;
    if (!std::isfinite(r.fitSeconds + r.predictSeconds) ||
        !std::isfinite(r.metrics.balancedAccuracy))
      continue;
    const bool trees = r.cell.method == analysis::ClassifierMethod::Gbt;
    anyTrees = anyTrees || trees;
    anyMixtures = anyMixtures || !trees;
    bySeries[{groupIndex(r.cell.group), trees}].push_back(i);
    times.push_back(timeOf(i));
  }
  for (auto& [key, cells] : bySeries) {
    const auto [g, trees] = key;
    std::stable_sort(cells.begin(), cells.end(),
                     [&](std::size_t a, std::size_t b) { return timeOf(a) < timeOf(b); });
    const QColor colour = groupColour(g);
    const std::string_view name = kSensorGroups[static_cast<std::size_t>(g)].shortName;
    const QString groupName = QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
    QCPGraph* graph = plot_->addGraph();
    // The legend names each group once, by its colour (the shapes have entries of their own
    // below); a point's series names its family where the plot shows both.
    graph->setName(anyTrees && anyMixtures && trees ? tr("group %1, boosted trees").arg(groupName)
                                                    : tr("group %1").arg(groupName));
    if (trees && bySeries.count({g, false}) != 0) graph->removeFromLegend();
    graph->setLineStyle(QCPGraph::lsNone);
    graph->setScatterStyle(QCPScatterStyle(
        trees ? QCPScatterStyle::ssSquare : QCPScatterStyle::ssDisc, colour, colour, 6));
    QVector<double> keys, values;
    std::vector<int>& cellIndex = cellsOf_[graph];
    for (std::size_t i : cells) {
      keys << timeOf(i);
      values << errorOf(i);
      cellIndex.push_back(static_cast<int>(i));
      pointOf_[static_cast<int>(i)] = QPointF(timeOf(i), errorOf(i));
    }
    graph->setData(keys, values, true);
    pointCount_ += static_cast<int>(keys.size());
    ++seriesCount_;
  }
  if (anyTrees && anyMixtures) {
    // Legend entries for the two shapes (graphs without points).
    for (const auto& [shape, name] :
         {std::pair{QCPScatterStyle::ssDisc, tr("dots: Gaussian mixtures")},
          std::pair{QCPScatterStyle::ssSquare, tr("squares: boosted trees")}}) {
      QCPGraph* key = plot_->addGraph();
      key->setName(name);
      key->setLineStyle(QCPGraph::lsNone);
      key->setScatterStyle(QCPScatterStyle(shape, Qt::darkGray, Qt::darkGray, 6));
    }
  }
  const std::vector<std::size_t> front = analysis::paretoFront(sweep, group);
  if (!front.empty()) {
    front_ = plot_->addGraph();
    front_->setName(tr("Pareto front (%1)").arg(front.size()));
    front_->setPen(QPen(Qt::black, 1.2, Qt::DashLine));
    front_->setLineStyle(QCPGraph::lsStepLeft);
    front_->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black, 1.5), Qt::NoBrush, 11));
    QVector<double> keys, values;
    std::vector<int>& cellIndex = cellsOf_[front_];
    for (std::size_t i : front) {
      keys << timeOf(i);
      values << errorOf(i);
      cellIndex.push_back(static_cast<int>(i));
    }
    front_->setData(keys, values, true);
    frontCount_ = static_cast<int>(front.size());
  }
  // Whole decades, so the fastest and the slowest cells each have a labelled decade beside them.
  const QCPRange padded = paddedRange(times, true);
  plot_->xAxis->setRange(std::pow(10.0, std::floor(std::log10(padded.lower))),
                         std::pow(10.0, std::ceil(std::log10(padded.upper))));
  plot_->yAxis->setRange(0, 105);
  finish(tr("No fitted cells scored on test rows."));
}

void SweepPlot::markCell(int cellIndex) {
  marked_ = cellIndex;
  if (mark_ == nullptr) return;
  mark_->data()->clear();
  ring_->setVisible(false);
  if (const auto it = pointOf_.find(cellIndex); it != pointOf_.end()) {
    mark_->addData(it->second.x(), it->second.y());
    ring_->position->setCoords(it->second.x(), it->second.y());
    ring_->setVisible(true);
  }
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void SweepPlot::onPlottableClick(QCPAbstractPlottable* plottable, int dataIndex, QMouseEvent*) {
  const auto it = cellsOf_.find(plottable);
  if (it == cellsOf_.end() || dataIndex < 0 || dataIndex >= static_cast<int>(it->second.size()))
    return;
  const int cell = it->second[static_cast<std::size_t>(dataIndex)];
  if (cell >= 0) emit cellClicked(cell);
}

void SweepPlot::resetView() {
  plot_->xAxis->setRange(homeX_.first, homeX_.second);
  plot_->yAxis->setRange(homeY_.first, homeY_.second);
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

QString SweepPlot::pointTip(QPointF pos) const {
  constexpr double kReachPixels = 8.0;
  double best = kReachPixels;
  QString tip;
  for (const auto& [plottable, cells] : cellsOf_) {
    const auto* graph = qobject_cast<const QCPGraph*>(plottable);
    if (graph == nullptr || graph == front_) continue;
    const auto data = graph->data();
    for (int i = 0; i < data->size(); ++i) {
      const QCPGraphData& d = *(data->constBegin() + i);
      const double dx = plot_->xAxis->coordToPixel(d.key) - pos.x();
      const double dy = plot_->yAxis->coordToPixel(d.value) - pos.y();
      const double distance = std::hypot(dx, dy);
      if (distance > best) continue;
      best = distance;
      const int cell = i < static_cast<int>(cells.size()) ? cells[static_cast<std::size_t>(i)] : -1;
      // The value the point stands for, not where it was drawn (points at one value are spread).
      double x = d.key;
      if (const auto it = xOf_.find(graph);
          it != xOf_.end() && i < static_cast<int>(it->second.size()))
        x = it->second[static_cast<std::size_t>(i)];
      tip = tr("%1\n%2: %3\n%4: %5%6")
                .arg(graph->name())
                .arg(plot_->xAxis->label())
                .arg(timeAxis_ ? secondsText(x) : QString::number(x, 'g', 4))
                .arg(plot_->yAxis->label())
                .arg(d.value, 0, 'f', 1)
                .arg(cell >= 0 ? tr("\ncell %1 (click to select)").arg(cell) : QString());
    }
  }
  return tip;
}

QString SweepPlot::tipAt(QPoint pos) const {
  return pointTip(QPointF(plot_->mapFrom(this, pos)));
}

bool SweepPlot::exportPng(const QString& path) {
  return plot_->savePng(path, std::max(plot_->width(), 800), std::max(plot_->height(), 500));
}

bool SweepPlot::exportPdf(const QString& path) {
  return plot_->savePdf(path, std::max(plot_->width(), 800), std::max(plot_->height(), 500));
}

}  // namespace tactile::gui
