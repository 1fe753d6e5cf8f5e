#include "app/gui/runs/timeline_view.h"

#include <qcustomplot.h>
#include <QMouseEvent>
#include <QScrollArea>
#include <QSettings>
#include <QToolTip>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "analysis/hole_detection.h"
#include "app/gui/common/plot_style.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/learning/prediction_model.h"

namespace tactile::gui {
namespace {

constexpr double kGrabPixels = 4.0;  // edge grab distance and drag threshold
constexpr std::int64_t kMinVisibleSteps = 20;
constexpr double kZoomPerNotch = 0.8;

// Command strip rows, top to bottom.
enum Lane { kLaneLeft, kLaneRight, kLaneForward, kLaneBack, kLaneBlocked, kLaneCount };

// What a re-bin refills.
enum Part : unsigned { kHeat = 1, kTrack = 2, kLabels = 4, kAll = 7 };

// A prediction whose posterior is below this is drawn pale.
constexpr float kConfident = 0.8f;
constexpr double kDisagreeLevel = 2.0 * kContactClassCount + 1.0;
constexpr double kHoleLevel = kDisagreeLevel + 1.0;

const QString kChannelKey = QStringLiteral("timelineView/channel");
const QString kRangeKey = QStringLiteral("timelineView/range");

// The visible steps split into equal pixel columns of at least one step. A step belongs to the
// column whose x span holds its centre, so cells line up with the axis coordinate of each step.
struct Columns {
  std::int64_t first = 0;
  int count = 1;
  double width = 1.0;  // steps per column
  Columns(StepRange range, int pixels) : first(range.first) {
    count = static_cast<int>(std::clamp<std::int64_t>(pixels, 1, range.size()));
    width = static_cast<double>(range.size()) / count;
  }
  std::int64_t firstStep(int c) const {
    return first + static_cast<std::int64_t>(std::ceil(c * width - 0.5));
  }
  std::int64_t lastStep(int c) const { return firstStep(c + 1) - 1; }
  std::int64_t middle(int c) const { return (firstStep(c) + lastStep(c)) / 2; }
  int columnOf(std::int64_t step) const {
    const double c = std::floor((static_cast<double>(step - first) + 0.5) / width);
    return std::clamp(static_cast<int>(c), 0, count - 1);
  }
  QCPRange edges() const { return {first - 0.5, first - 0.5 + count * width}; }
};

// A colour map's cells between outer edges. QCPColorMap spans cell centres, so a map one cell
// wide or high would draw nothing: such a dimension gets two identical cells.
class CellGrid {
 public:
  CellGrid(int cols, int rows, QCPRange keyEdges, QCPRange valueEdges)
      : cols_(cols),
        rows_(rows),
        data_(std::make_unique<QCPColorMapData>(std::max(cols, 2), std::max(rows, 2),
                                                centres(keyEdges, std::max(cols, 2)),
                                                centres(valueEdges, std::max(rows, 2)))) {
    data_->fill(0.0);
  }
  void set(int c, int r, double z) {
    for (int cc = c; cc <= (cols_ == 1 ? 1 : c); ++cc) {
      for (int rr = r; rr <= (rows_ == 1 ? 1 : r); ++rr)
        data_->setCell(cc, rr, z);
    }
  }
  double at(int c, int r) const { return data_->cell(c, r); }
  // The map takes ownership.
  void handTo(QCPColorMap* map) { map->setData(data_.release(), false); }

 private:
  static QCPRange centres(QCPRange edges, int n) {
    const double half = edges.size() / (2.0 * n);
    return {edges.lower + half, edges.upper - half};
  }
  int cols_;
  int rows_;
  std::unique_ptr<QCPColorMapData> data_;
};

// One level per colour, so cell value i shows exactly colours[i].
QCPColorGradient levelGradient(const std::vector<QColor>& colours) {
  QCPColorGradient g;
  g.setColorInterpolation(QCPColorGradient::ciRGB);
  g.setLevelCount(static_cast<int>(colours.size()));
  QMap<double, QColor> stops;
  const double step = 1.0 / static_cast<double>(colours.size() - 1);
  for (std::size_t i = 0; i < colours.size(); ++i)
    stops.insert(static_cast<double>(i) * step, colours[i]);
  g.setColorStops(stops);
  return g;
}

// The heat map's scale: sequential for normal force and magnitude, diverging (neutral zero) for
// shear; the colour scale beside it shows the same.
QCPColorGradient valueGradient(bool signedValues) {
  QCPColorGradient g;
  g.setColorInterpolation(QCPColorGradient::ciRGB);
  g.setLevelCount(256);
  QMap<double, QColor> stops;
  constexpr int kStops = 32;
  for (int i = 0; i <= kStops; ++i) {
    const double t = static_cast<double>(i) / kStops;
    stops.insert(t, signedValues ? signedValueColor(2.0 * t - 1.0, 1.0) : valueColor(t, 1.0));
  }
  g.setColorStops(stops);
  return g;
}

QString channelName(TimelineView::Channel c) {
  const std::array<QString, 3> names{QStringLiteral("normal"), QStringLiteral("shear"),
                                     QStringLiteral("magnitude")};
  return names[static_cast<std::size_t>(c)];
}

void setRowNames(QCPAxisRect* rect, const QVector<double>& at, const QVector<QString>& names,
                 int rows) {
  auto ticker = QSharedPointer<QCPAxisTickerText>::create();
  ticker->setTicks(at, names);
  QCPAxis* y = rect->axis(QCPAxis::atLeft);
  y->setTicker(ticker);
  y->setRange(-0.5, rows - 0.5);
  y->setRangeReversed(true);  // first row on top
}

// A thin horizontal line between rows, in the rect's plot coordinates.
QCPItemStraightLine* rowSeparator(QCustomPlot* plot, QCPAxisRect* rect, double y, QColor colour) {
  auto* line = new QCPItemStraightLine(plot);
  line->setClipAxisRect(rect);
  for (QCPItemPosition* p : {line->point1, line->point2})
    p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  line->point1->setCoords(0, y);
  line->point2->setCoords(1, y);
  line->setPen(QPen(colour, 1));
  return line;
}

// x in plot coordinates, y as a fraction of the rect's height: spans the rect whatever its rows.
void spanRect(QCPItemPosition* p, QCPAxisRect* rect) {
  p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  p->setAxisRect(rect);
  p->setTypeX(QCPItemPosition::ptPlotCoords);
  p->setTypeY(QCPItemPosition::ptAxisRectRatio);
}

}  // namespace

struct TimelineView::Impl {
  TimelineView* q = nullptr;
  RunSession* session = nullptr;
  LabelModel* labels = nullptr;
  QCustomPlot* plot = nullptr;
  QCPAxisRect* heatRect = nullptr;
  QCPAxisRect* headRect = nullptr;
  QCPAxisRect* cmdRect = nullptr;
  QCPAxisRect* labelRect = nullptr;
  QCPColorMap* heat = nullptr;
  QCPColorMap* heading = nullptr;
  QCPColorMap* commands = nullptr;
  QCPColorMap* labelMap = nullptr;
  QCPColorScale* scale = nullptr;
  QCPLayer* cursorLayer = nullptr;
  std::vector<QCPItemLine*> cursors;
  std::vector<QCPItemRect*> bands;
  // The selected group: outlined in the heatmap (its sensor rows) and in the label rows.
  QCPItemRect* groupHeatMark = nullptr;
  QCPItemRect* groupLabelMark = nullptr;
  QCPItemRect* edgePreview = nullptr;
  int rowHeight = 16;  // pixels per label, truth or model row
  std::vector<QCPItemStraightLine*> labelSeparators;

  Channel channel = Channel::Normal;
  StepRange range;
  std::optional<StepRange> restoredRange;  // waits for a run it fits
  std::optional<std::int64_t> openingStep;
  bool truthRows = false;
  // With predictions, four more rows per group: the per-step class (pale where its posterior is
  // under kConfident), the online decision (HMM forward filter, causal), the offline decision
  // (forward-backward) and a row marking steps where the per-step class disagrees with the label.
  const PredictionModel* predictions = nullptr;
  bool predictionRows = false;
  unsigned dirty = kAll;
  int binnedWidth = -1;
  bool replotQueued = false;
  bool inLayout = false;
  QScrollArea* scroll = nullptr;  // holds the plot: its rows scroll when the window is short
  bool syncing = false;

  enum class Drag { None, Pending, Select, Edge, Pan };
  Drag drag = Drag::None;
  QPointF pressPos;
  std::int64_t pressStep = 0;
  StepRange pressRange;
  storage::LabelSegment edgeSegment;
  SensorGroup edgeGroup = SensorGroup::Front;
  bool edgeIsLast = false;
  StepRange edgeRange;

  std::array<QCPAxisRect*, 4> rects() const { return {heatRect, headRect, cmdRect, labelRect}; }
  std::int64_t steps() const { return session->isOpen() ? session->stepCount() : 0; }
  QCPAxis* xAxis() const { return heatRect->axis(QCPAxis::atBottom); }
  bool hasLabels() const {
    return labels != nullptr && labels->hasSet() && session->isOpen() &&
           labels->runId() == session->info().id;
  }
  int rowsPerGroup() const { return 1 + (truthRows ? 1 : 0) + (predictionRows ? 4 : 0); }
  int labelRow(SensorGroup g) const { return groupIndex(g) * rowsPerGroup(); }
  int predictedRow(SensorGroup g) const { return labelRow(g) + (truthRows ? 1 : 0) + 1; }
  int onlineRow(SensorGroup g) const { return predictedRow(g) + 1; }
  int offlineRow(SensorGroup g) const { return predictedRow(g) + 2; }
  int disagreeRow(SensorGroup g) const { return predictedRow(g) + 3; }
  // Below the groups, with predictions: the steps where a side shows a hole (thesis 4.5).
  int holesRow() const { return kGroupCount * rowsPerGroup(); }
  int labelRows() const { return kGroupCount * rowsPerGroup() + (predictionRows ? 1 : 0); }

  void build();
  void configureLabelRows();
  // Over a model row: the predicted class and its posterior; over the holes row: the holes with
  // their widths. Empty elsewhere.
  QString predictionTip(QPointF pos) const;
  // Over the heatmap: the sensor and its value; over the heading or command strip: the step's
  // heading or command. Empty elsewhere.
  QString trackTip(QPointF pos) const;
  // A label-rect row's rectangle in the widget's coordinates.
  QRect rowRect(int row) const {
    const QCPAxis* y = labelRect->axis(QCPAxis::atLeft);
    const auto top = static_cast<int>(std::lround(y->coordToPixel(row - 0.5)));
    const auto bottom = static_cast<int>(std::lround(y->coordToPixel(row + 0.5)));
    const QRect inner = labelRect->rect();
    return QRect(QPoint(inner.left(), top), QPoint(inner.right(), bottom - 1))
        .translated(plot->pos());
  }
  void applyChannel();
  void applyAxisRange();
  void rebin(unsigned parts);
  void fillHeat(const Columns& cols);
  void fillTrack(const Columns& cols);
  void fillLabels(const Columns& cols);
  void updateOverlay();
  void replotOverlay();
  void queueReplot();
  StepRange fitted(std::int64_t first, std::int64_t size) const;
  std::int64_t stepAtPixel(double x) const;
  bool grabEdge(QPointF pos);
  void showEdgePreview();
  void zoom(double x, int delta);
  void release(QPointF pos);
};

void TimelineView::Impl::build() {
  plot->setMouseTracking(true);
  plot->setInteractions({});  // every mouse gesture is handled in eventFilter
  plot->plotLayout()->clear();
  QCPLayoutGrid* grid = plot->plotLayout();
  grid->setRowSpacing(4);
  auto* sides = new QCPMarginGroup(plot);
  auto* heatEdges = new QCPMarginGroup(plot);
  QFont small = plot->font();
  small.setPointSizeF(small.pointSizeF() * 0.85);
  int row = 0;
  for (QCPAxisRect** r : {&heatRect, &headRect, &cmdRect, &labelRect}) {
    *r = new QCPAxisRect(plot);
    grid->addElement(row++, 0, *r);
    (*r)->setMarginGroup(QCP::msLeft | QCP::msRight, sides);
    (*r)->setMinimumMargins(QMargins(4, 2, 8, 2));
    QCPAxis* y = (*r)->axis(QCPAxis::atLeft);
    y->setSubTicks(false);
    y->setTickLength(0, 0);
    y->setTickLabelFont(small);
    y->grid()->setVisible(false);
    QCPAxis* x = (*r)->axis(QCPAxis::atBottom);
    x->grid()->setVisible(false);
    x->setVisible(*r == labelRect);
    connect(x, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), q, [this](const QCPRange& span) {
      if (syncing) return;
      syncing = true;  // one shared step axis: the others follow whichever moved
      for (QCPAxisRect* other : rects())
        other->axis(QCPAxis::atBottom)->setRange(span);
      syncing = false;
    });
  }
  headRect->setMinimumSize(50, 10);     // axis rects default to at least 50 px high
  cmdRect->setMinimumSize(50, 5 * 11);  // five lanes, each as tall as its name
  labelRect->axis(QCPAxis::atBottom)->setLabel(TimelineView::tr("Step"));
  labelRect->axis(QCPAxis::atBottom)->setNumberFormat(QStringLiteral("f"));
  labelRect->axis(QCPAxis::atBottom)->setNumberPrecision(0);
  labelRect->axis(QCPAxis::atBottom)->setTickLabelFont(small);

  scale = new QCPColorScale(plot);
  grid->addElement(0, 1, scale);
  scale->setType(QCPAxis::atRight);
  scale->setBarWidth(10);
  scale->axis()->setTickLabelFont(small);
  heatRect->setMarginGroup(QCP::msTop | QCP::msBottom, heatEdges);
  scale->setMarginGroup(QCP::msTop | QCP::msBottom, heatEdges);
  grid->setColumnStretchFactors({1.0, 0.001});

  heat = new QCPColorMap(heatRect->axis(QCPAxis::atBottom), heatRect->axis(QCPAxis::atLeft));
  heat->setColorScale(scale);
  heading = new QCPColorMap(headRect->axis(QCPAxis::atBottom), headRect->axis(QCPAxis::atLeft));
  heading->setGradient(levelGradient({headingColor(0.0), headingColor(std::numbers::pi)}));
  heading->setDataRange({0, 1});
  commands = new QCPColorMap(cmdRect->axis(QCPAxis::atBottom), cmdRect->axis(QCPAxis::atLeft));
  commands->setGradient(levelGradient({Qt::white, QColor(215, 40, 40), QColor(60, 60, 60)}));
  commands->setDataRange({0, 2});
  labelMap = new QCPColorMap(labelRect->axis(QCPAxis::atBottom), labelRect->axis(QCPAxis::atLeft));
  // Levels: 0 empty, 1..C the classes, C+1..2C the same paler (an unsure prediction), then the
  // disagreement mark.
  std::vector<QColor> classes{Qt::white};
  for (int c = 0; c < kContactClassCount; ++c)
    classes.push_back(classColor(ContactClass(c)));
  for (int c = 0; c < kContactClassCount; ++c) {
    const QColor full = classColor(ContactClass(c));
    classes.push_back(QColor((full.red() + 2 * 255) / 3, (full.green() + 2 * 255) / 3,
                             (full.blue() + 2 * 255) / 3));
  }
  classes.push_back(QColor(200, 0, 0));
  classes.push_back(QColor(70, 70, 70));
  labelMap->setGradient(levelGradient(classes));
  labelMap->setDataRange({0, kHoleLevel});
  for (QCPColorMap* m : {heat, heading, commands, labelMap}) {
    m->setInterpolate(false);
    m->data()->clear();  // nothing until the first binning
  }

  QVector<double> at;
  QVector<QString> names;
  for (const GroupInfo& g : kSensorGroups) {
    at << g.firstSensor + (g.sensorCount - 1) / 2.0;
    names << QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size()));
    if (g.firstSensor > 0) rowSeparator(plot, heatRect, g.firstSensor - 0.5, Qt::white);
  }
  setRowNames(heatRect, at, names, kSensorCount);
  setRowNames(headRect, {0.0}, {TimelineView::tr("heading")}, 1);
  setRowNames(
      cmdRect, {0, 1, 2, 3, 4},
      {TimelineView::tr("turn left"), TimelineView::tr("turn right"), TimelineView::tr("forward"),
       TimelineView::tr("backward"), TimelineView::tr("blocked")},
      kLaneCount);
  // Legends of the two strips, beside them where the heatmap has its colour bar.
  auto legend = [&](int row, const QString& text) {
    auto* t = new QCPTextElement(plot, text, small);
    t->setTextFlags(Qt::AlignLeft | Qt::AlignVCenter);
    grid->addElement(row, 1, t);
    return t;
  };
  legend(1, TimelineView::tr("blue: facing +x\nred: facing \u2212x"))
      ->setTextColor(QColor(60, 60, 60));
  legend(2, TimelineView::tr("red: command\ngrey: blocked"))->setTextColor(QColor(60, 60, 60));
  for (int lane = 1; lane < kLaneCount; ++lane)
    rowSeparator(plot, cmdRect, lane - 0.5, QColor(225, 225, 225));

  // The cursor and the selection live on a buffered layer of their own: moving them repaints that
  // layer alone, never the colour maps.
  plot->addLayer(QStringLiteral("cursor"), plot->layer(QStringLiteral("overlay")),
                 QCustomPlot::limBelow);
  cursorLayer = plot->layer(QStringLiteral("cursor"));
  cursorLayer->setMode(QCPLayer::lmBuffered);
  for (QCPAxisRect* r : rects()) {
    auto* band = new QCPItemRect(plot);
    band->setLayer(cursorLayer);
    band->setClipAxisRect(r);
    spanRect(band->topLeft, r);
    spanRect(band->bottomRight, r);
    // Violet: no class colour, and not the grey of NoContact.
    band->setPen(QPen(QColor(120, 30, 170, 200), 1));
    band->setBrush(QColor(150, 60, 210, 60));
    band->setVisible(false);
    bands.push_back(band);
    auto* line = new QCPItemLine(plot);
    line->setLayer(cursorLayer);
    line->setClipAxisRect(r);
    spanRect(line->start, r);
    spanRect(line->end, r);
    line->setPen(QPen(QColor(20, 20, 20), 2));
    cursors.push_back(line);
  }
  auto groupMark = [&](QCPAxisRect* r) {
    auto* mark = new QCPItemRect(plot);
    mark->setLayer(cursorLayer);
    mark->setClipAxisRect(r);
    for (QCPItemPosition* p : {mark->topLeft, mark->bottomRight}) {
      p->setAxes(r->axis(QCPAxis::atBottom), r->axis(QCPAxis::atLeft));
      p->setAxisRect(r);
      p->setTypeX(QCPItemPosition::ptAxisRectRatio);
      p->setTypeY(QCPItemPosition::ptPlotCoords);
    }
    mark->setPen(QPen(QColor(20, 20, 20), 2));
    mark->setBrush(Qt::NoBrush);
    return mark;
  };
  groupHeatMark = groupMark(heatRect);
  groupLabelMark = groupMark(labelRect);
  edgePreview = new QCPItemRect(plot);
  edgePreview->setLayer(cursorLayer);
  edgePreview->setClipAxisRect(labelRect);
  for (QCPItemPosition* p : {edgePreview->topLeft, edgePreview->bottomRight})
    p->setAxes(labelRect->axis(QCPAxis::atBottom), labelRect->axis(QCPAxis::atLeft));
  edgePreview->setPen(QPen(Qt::black, 1, Qt::DashLine));
  edgePreview->setVisible(false);
}

// Label rows, with a truth row under each group's when the run has truth.
void TimelineView::Impl::configureLabelRows() {
  truthRows = session->isOpen() && session->track().hasTruth();
  predictionRows = predictions != nullptr && predictions->hasPredictions() && session->isOpen() &&
                   predictions->runName() == QString::fromStdString(session->info().name);
  QVector<double> at;
  QVector<QString> names;
  for (const GroupInfo& g : kSensorGroups) {
    const QString name =
        QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size()));
    at << labelRow(g.group);
    names << name;
    if (truthRows) {
      at << labelRow(g.group) + 1;
      names << TimelineView::tr("%1 truth").arg(name);
    }
    if (predictionRows) {
      at << predictedRow(g.group) << onlineRow(g.group) << offlineRow(g.group)
         << disagreeRow(g.group);
      names << TimelineView::tr("%1 model").arg(name) << TimelineView::tr("%1 online").arg(name)
            << TimelineView::tr("%1 offline").arg(name)
            << TimelineView::tr("%1 \u2260 label").arg(name);
    }
  }
  if (predictionRows) {
    at << holesRow();
    names << TimelineView::tr("holes");
  }
  const int rows = labelRows();
  setRowNames(labelRect, at, names, rows);
  for (QCPItemStraightLine* line : labelSeparators)
    plot->removeItem(line);
  labelSeparators.clear();
  for (int g = 1; g < kGroupCount; ++g) {
    const double y = labelRow(SensorGroup(g)) - 0.5;
    labelSeparators.push_back(rowSeparator(plot, labelRect, y, QColor(150, 150, 150)));
  }
  // Label rows have the chosen height; the heatmap takes what is left (at least 88 px, two per
  // sensor), so the window asks for enough height to show every row.
  const int labelHeight = rows * rowHeight;
  labelRect->setMinimumSize(50, labelHeight);
  labelRect->setMaximumSize(QWIDGETSIZE_MAX, labelHeight);
  heatRect->setMinimumSize(50, 2 * kSensorCount);
  plot->plotLayout()->setRowStretchFactors({44.0, 2.2, 8.0, 1.0});
  plot->setMinimumHeight(labelHeight + 2 * kSensorCount + 10 + 55 + 90);
}

QString TimelineView::Impl::predictionTip(QPointF pos) const {
  if (!predictionRows || !labelRect->rect().contains(pos.toPoint())) return {};
  const auto row = std::llround(labelRect->axis(QCPAxis::atLeft)->pixelToCoord(pos.y()));
  const std::int64_t step = stepAtPixel(pos.x());
  if (row == holesRow()) {
    QStringList lines;
    for (const HoleMark& h : predictions->holesAt(step)) {
      lines << TimelineView::tr("step %1, %2 side: hole %3 units wide between domes %4 and %5")
                   .arg(step)
                   .arg(
                       QString::fromLatin1(analysis::kSides[static_cast<std::size_t>(h.side)].name))
                   .arg(h.widthUnits, 0, 'f', 1)
                   .arg(h.sensorBefore)
                   .arg(h.sensorAfter);
    }
    return lines.join(QLatin1Char('\n'));
  }
  for (const GroupInfo& g : kSensorGroups) {
    if (row == onlineRow(g.group) || row == offlineRow(g.group)) {
      const GroupPrediction& p = predictions->group(g.group);
      const bool online = row == onlineRow(g.group);
      const std::vector<std::int8_t>& decided = online ? p.online : p.offline;
      if (step < 0 || step >= static_cast<std::int64_t>(decided.size()) ||
          decided[static_cast<std::size_t>(step)] < 0)
        return {};
      return TimelineView::tr("step %1, %2: the %3 decision is %4")
          .arg(step)
          .arg(QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size())))
          .arg(online ? TimelineView::tr("online (causal)")
                      : TimelineView::tr("offline (whole contact)"))
          .arg(className(ContactClass(decided[static_cast<std::size_t>(step)])));
    }
    if (row != predictedRow(g.group) && row != disagreeRow(g.group)) continue;
    const GroupPrediction& p = predictions->group(g.group);
    const auto cls = p.classAt(step);
    if (!cls) return {};
    QString tip =
        TimelineView::tr("step %1, %2: the model says %3 (%4 %)")
            .arg(step)
            .arg(QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size())))
            .arg(className(*cls))
            .arg(100.0 * p.confidence[static_cast<std::size_t>(step)], 0, 'f', 0);
    if (const auto label = labels != nullptr ? labels->classAt(g.group, step) : std::nullopt)
      tip += TimelineView::tr(", the label %1").arg(className(*label));
    return tip;
  }
  return {};
}

QString TimelineView::Impl::trackTip(QPointF pos) const {
  if (steps() == 0) return {};
  const QPoint p = pos.toPoint();
  const std::int64_t step = stepAtPixel(pos.x());
  const auto at = static_cast<std::size_t>(step);
  const storage::RunTrack& t = session->track();
  if (heatRect->rect().contains(p)) {
    const auto sensor = static_cast<int>(std::clamp<long long>(
        std::llround(heatRect->axis(QCPAxis::atLeft)->pixelToCoord(pos.y())), 0, kSensorCount - 1));
    const GroupInfo& g = groupInfo(groupOfSensor(sensor));
    const Columns cols(range, heatRect->width());
    const int c = cols.columnOf(step);
    const double value = heat->data()->data(xAxis()->pixelToCoord(pos.x()), sensor);
    const std::array<QString, 3> names{TimelineView::tr("normal"), TimelineView::tr("shear"),
                                       TimelineView::tr("magnitude")};
    const QString steps = cols.firstStep(c) == cols.lastStep(c)
                              ? TimelineView::tr("step %1").arg(cols.firstStep(c))
                              : TimelineView::tr("steps %1-%2 (largest)")
                                    .arg(cols.firstStep(c))
                                    .arg(cols.lastStep(c));
    return TimelineView::tr("%1, sensor %2 (%3 %4): %5 %6")
        .arg(steps)
        .arg(sensor)
        .arg(QString::fromUtf8(g.shortName.data(), static_cast<qsizetype>(g.shortName.size())))
        .arg(sensor - g.firstSensor + 1)
        .arg(names[static_cast<std::size_t>(channel)])
        .arg(value, 0, 'f', 2);
  }
  if (at >= t.stepCount()) return {};
  if (headRect->rect().contains(p)) {
    const double degrees = t.theta[at] * 180.0 / std::numbers::pi;
    return TimelineView::tr("step %1: heading %2\u00b0 (%3)")
        .arg(step)
        .arg(degrees, 0, 'f', 1)
        .arg(std::cos(t.theta[at]) >= 0.0 ? TimelineView::tr("blue: facing +x")
                                          : TimelineView::tr("red: facing \u2212x"));
  }
  if (cmdRect->rect().contains(p)) {
    return TimelineView::tr("step %1: v %2, omega %3%4")
        .arg(step)
        .arg(t.v[at], 0, 'f', 2)
        .arg(t.omega[at], 0, 'f', 3)
        .arg(t.blocked[at] != 0 ? TimelineView::tr(", blocked") : QString());
  }
  return {};
}

QString TimelineView::trackTipAt(QPoint widgetPos) const {
  return d_->trackTip(d_->plot->mapFrom(this, widgetPos));
}

void TimelineView::setRowHeight(int pixels) {
  pixels = std::clamp(pixels, 4, 100);
  if (pixels == d_->rowHeight) return;
  d_->rowHeight = pixels;
  d_->configureLabelRows();
  d_->updateOverlay();
  d_->queueReplot();
}

int TimelineView::rowHeight() const {
  return d_->rowHeight;
}

QString TimelineView::predictionTipAt(QPoint widgetPos) const {
  return d_->predictionTip(d_->plot->mapFrom(this, widgetPos));
}

void TimelineView::Impl::applyChannel() {
  const bool shear = channel == Channel::Shear;
  scale->setGradient(valueGradient(shear));
  scale->setDataRange(shear ? QCPRange(-kMaxShear, kMaxShear) : QCPRange(0.0, kMaxNormal));
  const std::array<QString, 3> titles{TimelineView::tr("Normal"), TimelineView::tr("Shear"),
                                      TimelineView::tr("Magnitude")};
  scale->axis()->setLabel(titles[static_cast<std::size_t>(channel)]);
}

void TimelineView::Impl::applyAxisRange() {
  xAxis()->setRange(range.first - 0.5, range.last + 0.5);
}

StepRange TimelineView::Impl::fitted(std::int64_t first, std::int64_t size) const {
  const std::int64_t n = std::max<std::int64_t>(1, steps());
  size = std::clamp<std::int64_t>(size, 1, n);
  first = std::clamp<std::int64_t>(first, 0, n - size);
  return {first, first + size - 1};
}

std::int64_t TimelineView::Impl::stepAtPixel(double x) const {
  const double coord = xAxis()->pixelToCoord(x);
  return std::clamp<std::int64_t>(std::llround(coord), 0, std::max<std::int64_t>(0, steps() - 1));
}

void TimelineView::Impl::queueReplot() {
  if (inLayout) return;  // the replot under way draws the new data
  replotQueued = true;
  plot->replot(QCustomPlot::rpQueuedReplot);
}

// Re-binning reads summaries and scans the track, so it runs only when what is shown changes
// (range, width, run, channel, labels) and never while the view is hidden.
void TimelineView::Impl::rebin(unsigned parts) {
  dirty |= parts;
  if (!q->isVisible()) return;
  parts = dirty;
  dirty = 0;
  binnedWidth = heatRect->width();
  if (steps() == 0) {
    for (QCPColorMap* m : {heat, heading, commands, labelMap})
      m->data()->clear();
  } else {
    const Columns cols(range, binnedWidth);
    if (parts & kHeat) fillHeat(cols);
    if (parts & kTrack) fillTrack(cols);
    if (parts & kLabels) fillLabels(cols);
  }
  queueReplot();
}

void TimelineView::Impl::fillHeat(const Columns& cols) {
  auto summary = session->summary(range.first, range.last, cols.count);
  if (!summary) {
    heat->data()->clear();
    return;
  }
  const std::vector<storage::SummaryBucket>& buckets = summary->buckets;
  // One value per bucket and sensor. Magnitude is an upper bound: the largest normal and the
  // largest shear of a bucket need not come from the same step.
  std::vector<float> values(buckets.size() * kSensorCount);
  for (std::size_t b = 0; b < buckets.size(); ++b) {
    const storage::SummaryBucket& k = buckets[b];
    for (int s = 0; s < kSensorCount; ++s) {
      const double nMin = k.min[normalOffset(s)], nMax = k.max[normalOffset(s)];
      const double sMin = k.min[shearOffset(s)], sMax = k.max[shearOffset(s)];
      const double shear = std::abs(sMax) >= std::abs(sMin) ? sMax : sMin;
      double v = nMax;
      if (channel == Channel::Shear) v = shear;
      if (channel == Channel::Magnitude)
        v = std::hypot(std::max(std::abs(nMin), std::abs(nMax)), std::abs(shear));
      values[b * kSensorCount + static_cast<std::size_t>(s)] = static_cast<float>(v);
    }
  }
  const bool signedValues = channel == Channel::Shear;
  CellGrid grid(cols.count, kSensorCount, cols.edges(), {-0.5, kSensorCount - 0.5});
  std::array<float, kSensorCount> column{};
  std::size_t j = 0;
  for (int c = 0; c < cols.count; ++c) {
    const std::int64_t cf = cols.firstStep(c), cl = cols.lastStep(c);
    while (j + 1 < buckets.size() && buckets[j].lastStep < cf)
      ++j;
    column.fill(0.0f);
    // Every bucket touching the column counts, so a one-step spike is never binned away.
    for (std::size_t k = j; k < buckets.size() && buckets[k].firstStep <= cl; ++k) {
      const float* v = &values[k * kSensorCount];
      for (int s = 0; s < kSensorCount; ++s) {
        if (signedValues ? std::abs(v[s]) > std::abs(column[s]) : v[s] > column[s])
          column[s] = v[s];
      }
    }
    for (int s = 0; s < kSensorCount; ++s)
      grid.set(c, s, column[s]);
  }
  grid.handTo(heat);
}

void TimelineView::Impl::fillTrack(const Columns& cols) {
  const storage::RunTrack& t = session->track();
  const QColor forward = headingColor(0.0);
  CellGrid head(cols.count, 1, cols.edges(), {-0.5, 0.5});
  CellGrid lanes(cols.count, kLaneCount, cols.edges(), {-0.5, double(kLaneCount) - 0.5});
  for (int c = 0; c < cols.count; ++c) {
    const auto mid = static_cast<std::size_t>(cols.middle(c));
    head.set(c, 0, headingColor(t.theta[mid]) == forward ? 0.0 : 1.0);
    // A lane is on in a column when any of its steps has that command.
    unsigned on = 0;
    const auto last = static_cast<std::size_t>(cols.lastStep(c));
    for (auto s = static_cast<std::size_t>(cols.firstStep(c)); s <= last; ++s) {
      on |= (unsigned{t.omega[s] > 0} << kLaneLeft) | (unsigned{t.omega[s] < 0} << kLaneRight) |
            (unsigned{t.v[s] > 0} << kLaneForward) | (unsigned{t.v[s] < 0} << kLaneBack) |
            (unsigned{t.blocked[s] != 0} << kLaneBlocked);
    }
    for (int lane = 0; lane < kLaneCount; ++lane) {
      if (on & (1u << lane)) lanes.set(c, lane, lane == kLaneBlocked ? 2.0 : 1.0);
    }
  }
  head.handTo(heading);
  lanes.handTo(commands);
}

void TimelineView::Impl::fillLabels(const Columns& cols) {
  const int rows = labelRows();
  CellGrid grid(cols.count, rows, cols.edges(), {-0.5, rows - 0.5});
  const storage::RunTrack& t = session->track();
  const bool labelled = hasLabels();
  for (const GroupInfo& g : kSensorGroups) {
    const int row = labelRow(g.group);
    if (labelled) {
      const std::vector<storage::LabelSegment>& segs = labels->segments(g.group);
      const auto begin = std::lower_bound(
          segs.begin(), segs.end(), range.first,
          [](const storage::LabelSegment& s, std::int64_t step) { return s.lastStep < step; });
      auto seg = begin;
      for (int c = 0; c < cols.count; ++c) {
        const std::int64_t m = cols.middle(c);
        while (seg != segs.end() && seg->lastStep < m)
          ++seg;
        if (seg != segs.end() && seg->firstStep <= m) grid.set(c, row, int(seg->cls) + 1.0);
      }
      // A segment narrower than a column misses every column's middle step; it still takes the
      // column it sits in when nothing else claimed that column.
      for (seg = begin; seg != segs.end() && seg->firstStep <= range.last; ++seg) {
        const int c = cols.columnOf(std::max(range.first, (seg->firstStep + seg->lastStep) / 2));
        if (grid.at(c, row) == 0.0) grid.set(c, row, int(seg->cls) + 1.0);
      }
    }
    if (truthRows) {
      for (int c = 0; c < cols.count; ++c) {
        const auto cls = t.truthAt(static_cast<std::size_t>(cols.middle(c)), g.group);
        grid.set(c, row + 1, int(cls) + 1.0);
      }
    }
    if (predictionRows) {
      const GroupPrediction& p = predictions->group(g.group);
      const auto n = static_cast<std::int64_t>(p.cls.size());
      for (int c = 0; c < cols.count; ++c) {
        // The column's middle step shows its class; a disagreement anywhere in the column marks
        // it, so none hides between two pixel columns.
        const std::int64_t m = cols.middle(c);
        if (m < n && p.cls[static_cast<std::size_t>(m)] >= 0) {
          const int cls = p.cls[static_cast<std::size_t>(m)];
          const bool sure = p.confidence[static_cast<std::size_t>(m)] >= kConfident;
          grid.set(c, predictedRow(g.group), cls + 1.0 + (sure ? 0.0 : kContactClassCount));
        }
        for (const auto& [decided, row] : {std::pair{&p.online, onlineRow(g.group)},
                                           std::pair{&p.offline, offlineRow(g.group)}}) {
          if (m < static_cast<std::int64_t>(decided->size()) &&
              (*decided)[static_cast<std::size_t>(m)] >= 0)
            grid.set(c, row, (*decided)[static_cast<std::size_t>(m)] + 1.0);
        }
        const std::int64_t first = cols.firstStep(c);
        const std::int64_t last = std::min(cols.lastStep(c), n - 1);
        for (std::int64_t s = first; s <= last; ++s) {
          if (p.disagrees.size() > static_cast<std::size_t>(s) &&
              p.disagrees[static_cast<std::size_t>(s)]) {
            grid.set(c, disagreeRow(g.group), kDisagreeLevel);
            break;
          }
        }
      }
    }
  }
  if (predictionRows) {
    const std::vector<HoleMark>& holes = predictions->holes();
    auto h = std::lower_bound(holes.begin(), holes.end(), range.first,
                              [](const HoleMark& m, std::int64_t step) { return m.step < step; });
    for (; h != holes.end() && h->step <= range.last; ++h)
      grid.set(cols.columnOf(h->step), holesRow(), kHoleLevel);
  }
  grid.handTo(labelMap);
}

void TimelineView::Impl::updateOverlay() {
  const auto step = static_cast<double>(session->currentStep());
  for (QCPItemLine* line : cursors) {
    line->start->setCoords(step, 0.0);
    line->end->setCoords(step, 1.0);
    line->setVisible(steps() > 0);
  }
  const GroupInfo& g = groupInfo(session->selectedGroup());
  groupHeatMark->topLeft->setCoords(0.0, g.firstSensor - 0.5);
  groupHeatMark->bottomRight->setCoords(1.0, g.firstSensor + g.sensorCount - 0.5);
  groupLabelMark->topLeft->setCoords(0.0, labelRow(g.group) - 0.5);
  groupLabelMark->bottomRight->setCoords(1.0, labelRow(g.group) + rowsPerGroup() - 0.5);
  groupHeatMark->setVisible(steps() > 0);
  groupLabelMark->setVisible(steps() > 0);
  const std::optional<StepRange> sel = session->selection();
  for (QCPItemRect* band : bands) {
    band->setVisible(sel.has_value() && steps() > 0);
    if (!sel) continue;
    band->topLeft->setCoords(sel->first - 0.5, 0.0);
    band->bottomRight->setCoords(sel->last + 0.5, 1.0);
  }
}

void TimelineView::Impl::replotOverlay() {
  // A pending full replot draws the overlay anyway; a layer replot before it would force an
  // immediate full one.
  if (!q->isVisible() || replotQueued) return;
  cursorLayer->replot();
}

// Picks the label segment edge within kGrabPixels of a press in a label row, if any.
bool TimelineView::Impl::grabEdge(QPointF pos) {
  if (!hasLabels() || !labelRect->rect().contains(pos.toPoint())) return false;
  const auto row = std::llround(labelRect->axis(QCPAxis::atLeft)->pixelToCoord(pos.y()));
  if (row < 0 || row % rowsPerGroup() != 0) return false;  // only label rows have edges
  const auto group = static_cast<std::uint8_t>(row / rowsPerGroup());
  if (group >= kGroupCount) return false;
  edgeGroup = SensorGroup(group);
  const auto& segs = labels->segments(edgeGroup);
  const std::int64_t s = stepAtPixel(pos.x());
  const double stepsPerPixel = static_cast<double>(range.size()) / std::max(1, heatRect->width());
  const auto reach = static_cast<std::int64_t>(std::ceil(kGrabPixels * stepsPerPixel)) + 1;
  auto it = std::lower_bound(
      segs.begin(), segs.end(), s - reach,
      [](const storage::LabelSegment& seg, std::int64_t step) { return seg.lastStep < step; });
  double best = kGrabPixels;
  bool found = false;
  for (; it != segs.end() && it->firstStep <= s + reach; ++it) {
    // On a shared boundary the segment under the pointer wins.
    const double bias = (it->firstStep <= s && s <= it->lastStep) ? 0.0 : 0.01;
    const double dFirst = std::abs(xAxis()->coordToPixel(it->firstStep - 0.5) - pos.x()) + bias;
    const double dLast = std::abs(xAxis()->coordToPixel(it->lastStep + 0.5) - pos.x()) + bias;
    if (std::min(dFirst, dLast) <= best) {
      best = std::min(dFirst, dLast);
      edgeSegment = *it;
      edgeIsLast = dLast < dFirst;
      found = true;
    }
  }
  edgeRange = {edgeSegment.firstStep, edgeSegment.lastStep};
  return found;
}

void TimelineView::Impl::showEdgePreview() {
  const double row = labelRow(edgeGroup);
  edgePreview->topLeft->setCoords(edgeRange.first - 0.5, row - 0.5);
  edgePreview->bottomRight->setCoords(edgeRange.last + 0.5, row + 0.5);
  QColor fill = classColor(edgeSegment.cls);
  fill.setAlpha(170);
  edgePreview->setBrush(fill);
  edgePreview->setVisible(true);
  replotOverlay();
}

void TimelineView::Impl::zoom(double x, int delta) {
  if (steps() == 0 || delta == 0) return;
  const double pointer = xAxis()->pixelToCoord(x);
  const double anchor = (pointer - (range.first - 0.5)) / static_cast<double>(range.size());
  const double factor = std::pow(kZoomPerNotch, delta / 120.0);
  const std::int64_t minSize = std::min(kMinVisibleSteps, steps());
  std::int64_t size = std::llround(static_cast<double>(range.size()) * factor);
  if (delta > 0 && size == range.size()) --size;
  if (delta < 0 && size == range.size()) ++size;
  size = std::clamp(size, minSize, steps());
  const auto first = std::llround(pointer + 0.5 - anchor * static_cast<double>(size));
  q->setVisibleRange(fitted(first, size));
}

void TimelineView::Impl::release(QPointF pos) {
  const Drag was = drag;
  drag = Drag::None;
  if (was == Drag::Edge) {
    edgePreview->setVisible(false);
    replotOverlay();
    if (edgeRange != StepRange{edgeSegment.firstStep, edgeSegment.lastStep}) {
      const Status moved = labels->moveSegment(edgeSegment.id, edgeRange.first, edgeRange.last);
      if (!moved)
        QToolTip::showText(plot->mapToGlobal(pos.toPoint()),
                           QString::fromStdString(moved.errorText()));
      return;
    }
  }
  if (was == Drag::Select) session->setSelection(pressStep, stepAtPixel(pos.x()));
  if (was == Drag::Pending || was == Drag::Edge) {
    if (heatRect->rect().contains(pressPos.toPoint())) {
      const auto sensor = std::llround(heatRect->axis(QCPAxis::atLeft)->pixelToCoord(pressPos.y()));
      session->setSelectedGroup(
          groupOfSensor(static_cast<int>(std::clamp<long long>(sensor, 0, kSensorCount - 1))));
    }
    session->setCurrentStep(pressStep);
  }
}

TimelineView::TimelineView(RunSession* session, LabelModel* labels, QWidget* parent)
    : QWidget(parent), d_(new Impl) {
  d_->q = this;
  d_->session = session;
  d_->labels = labels;
  setObjectName(QStringLiteral("timelineView"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  // The plot asks for the height its rows need (with predictions on, more than a laptop screen
  // has); the scroll area around it never does, so the window stays within the screen and the
  // rows scroll instead.
  d_->scroll = new QScrollArea(this);
  d_->scroll->setObjectName(QStringLiteral("timelineScroll"));
  d_->scroll->setFrameShape(QFrame::NoFrame);
  d_->scroll->setWidgetResizable(true);
  d_->scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  d_->scroll->setFocusPolicy(Qt::NoFocus);
  d_->plot = new QCustomPlot(d_->scroll);
  d_->scroll->setWidget(d_->plot);
  layout->addWidget(d_->scroll);
  d_->build();
  d_->configureLabelRows();
  d_->applyChannel();
  d_->plot->installEventFilter(this);
  d_->range = d_->fitted(0, d_->steps());
  d_->applyAxisRange();
  d_->updateOverlay();

  connect(d_->plot, &QCustomPlot::afterReplot, this, [this] { d_->replotQueued = false; });
  connect(d_->plot, &QCustomPlot::afterLayout, this, [this] {
    // A new width means new pixel columns; bin them for the replot already under way.
    if (d_->heatRect->width() == d_->binnedWidth || !isVisible()) return;
    d_->inLayout = true;
    d_->rebin(kAll);
    d_->inLayout = false;
  });
  connect(session, &RunSession::runOpened, this, [this] {
    d_->configureLabelRows();
    StepRange next = d_->fitted(0, d_->steps());
    const std::optional<StepRange> wanted = std::exchange(d_->restoredRange, std::nullopt);
    if (wanted && wanted->first >= 0 && wanted->first <= wanted->last && wanted->last < d_->steps())
      next = *wanted;
    // The cursor's move to the opening step must not pan away from a restored range.
    d_->openingStep = d_->session->currentStep();
    const bool changed = next != d_->range;
    d_->range = next;
    d_->applyAxisRange();
    d_->updateOverlay();
    d_->rebin(kAll);
    if (changed) emit visibleRangeChanged(next);
  });
  connect(session, &RunSession::currentStepChanged, this, [this](std::int64_t step) {
    const bool opening = std::exchange(d_->openingStep, std::nullopt) == step;
    if (d_->steps() > 0 && !d_->range.contains(step) && !opening) {
      // Keep the zoom, bring the cursor to the middle.
      setVisibleRange(d_->fitted(step - d_->range.size() / 2, d_->range.size()));
    }
    d_->updateOverlay();
    d_->replotOverlay();
  });
  connect(session, &RunSession::selectedGroupChanged, this, [this] {
    d_->updateOverlay();
    d_->replotOverlay();
  });
  connect(session, &RunSession::selectionChanged, this, [this] {
    d_->updateOverlay();
    d_->replotOverlay();
  });
  if (labels != nullptr) {
    connect(labels, &LabelModel::labelsChanged, this, [this] { d_->rebin(kLabels); });
    connect(labels, &LabelModel::labelSetChanged, this, [this] { d_->rebin(kLabels); });
  }
}

TimelineView::~TimelineView() {
  delete d_;
}

TimelineView::Channel TimelineView::channel() const {
  return d_->channel;
}

void TimelineView::setChannel(Channel channel) {
  if (channel == d_->channel) return;
  d_->channel = channel;
  d_->applyChannel();
  d_->rebin(kHeat);
}

StepRange TimelineView::visibleRange() const {
  return d_->range;
}

void TimelineView::setVisibleRange(StepRange range) {
  const StepRange next =
      d_->fitted(range.first, std::max(range.first, range.last) - range.first + 1);
  if (next == d_->range) return;
  d_->range = next;
  d_->applyAxisRange();
  d_->rebin(kAll);
  emit visibleRangeChanged(next);
}

void TimelineView::showWholeRun() {
  setVisibleRange(d_->fitted(0, d_->steps()));
}

void TimelineView::saveSettings(QSettings& settings) const {
  settings.setValue(kChannelKey, channelName(d_->channel));
  settings.setValue(kRangeKey, QVariantList{qlonglong(d_->range.first), qlonglong(d_->range.last)});
}

void TimelineView::restoreSettings(const QSettings& settings) {
  const QString name = settings.value(kChannelKey).toString();
  for (Channel c : {Channel::Normal, Channel::Shear, Channel::Magnitude}) {
    if (name == channelName(c)) setChannel(c);
  }
  const QStringList parts = settings.value(kRangeKey).toStringList();
  if (parts.size() != 2) return;
  bool okFirst = false, okLast = false;
  const StepRange r{parts[0].toLongLong(&okFirst), parts[1].toLongLong(&okLast)};
  if (!okFirst || !okLast || r.first < 0 || r.first > r.last) return;
  if (r.last < d_->steps())
    setVisibleRange(r);
  else
    d_->restoredRange = r;  // for the run it was saved with, opened later
}

double TimelineView::stepToX(std::int64_t step) const {
  return d_->xAxis()->coordToPixel(static_cast<double>(step)) + d_->plot->x();
}

QRect TimelineView::heatmapRect() const {
  return d_->heatRect->rect().translated(d_->plot->pos());
}

QRect TimelineView::headingRect() const {
  return d_->headRect->rect().translated(d_->plot->pos());
}

QRect TimelineView::labelStripRect(SensorGroup group) const {
  return d_->rowRect(d_->labelRow(group));
}

QRect TimelineView::predictionStripRect(SensorGroup group) const {
  return d_->predictionRows ? d_->rowRect(d_->predictedRow(group)) : QRect();
}

QRect TimelineView::disagreementStripRect(SensorGroup group) const {
  return d_->predictionRows ? d_->rowRect(d_->disagreeRow(group)) : QRect();
}

QRect TimelineView::holesStripRect() const {
  return d_->predictionRows ? d_->rowRect(d_->holesRow()) : QRect();
}

bool TimelineView::showsPredictions() const {
  return d_->predictionRows;
}

void TimelineView::setPredictions(const PredictionModel* predictions) {
  if (d_->predictions != nullptr) disconnect(d_->predictions, nullptr, this, nullptr);
  d_->predictions = predictions;
  if (predictions != nullptr) {
    auto refresh = [this] {
      d_->configureLabelRows();
      d_->rebin(kLabels);
    };
    connect(predictions, &PredictionModel::ready, this, refresh);
    connect(predictions, &PredictionModel::changed, this, refresh);
  }
  d_->configureLabelRows();
  d_->rebin(kLabels);
}

QCustomPlot* TimelineView::plot() const {
  return d_->plot;
}

void TimelineView::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  d_->updateOverlay();
  d_->rebin(0);  // whatever went dirty while hidden
}

bool TimelineView::eventFilter(QObject* watched, QEvent* event) {
  if (watched != d_->plot) return QWidget::eventFilter(watched, event);
  Impl& d = *d_;
  switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick: {
      auto* me = static_cast<QMouseEvent*>(event);
      const QPointF pos = me->position();
      const QRect inner = d.heatRect->rect();
      if (d.steps() == 0 || pos.x() < inner.left() || pos.x() > inner.right()) return true;
      d.pressPos = pos;
      if (me->button() == Qt::LeftButton) {
        d.pressStep = d.stepAtPixel(pos.x());
        if (me->modifiers() & Qt::ShiftModifier) {
          d.session->setSelection(d.session->currentStep(), d.pressStep);
          d.drag = Impl::Drag::None;
        } else {
          d.drag = d.grabEdge(pos) ? Impl::Drag::Edge : Impl::Drag::Pending;
        }
      } else if (me->button() == Qt::RightButton || me->button() == Qt::MiddleButton) {
        d.drag = Impl::Drag::Pan;
        d.pressRange = d.range;
      }
      return true;
    }
    case QEvent::MouseMove: {
      const QPointF pos = static_cast<QMouseEvent*>(event)->position();
      const double dx = pos.x() - d.pressPos.x();
      if (d.drag == Impl::Drag::None) {
        d.plot->setCursor(d.grabEdge(pos) ? Qt::SizeHorCursor : Qt::ArrowCursor);
        QString tip = d.predictionTip(pos);
        if (tip.isEmpty()) tip = d.trackTip(pos);
        if (tip.isEmpty())
          QToolTip::hideText();
        else
          QToolTip::showText(d.plot->mapToGlobal(pos.toPoint()), tip, d.plot);
      } else if (d.drag == Impl::Drag::Pending && std::abs(dx) > kGrabPixels) {
        d.drag = Impl::Drag::Select;
      }
      if (d.drag == Impl::Drag::Select) {
        d.session->setSelection(d.pressStep, d.stepAtPixel(pos.x()));
      } else if (d.drag == Impl::Drag::Edge) {
        const std::int64_t s = d.stepAtPixel(pos.x());
        if (d.edgeIsLast)
          d.edgeRange.last = std::max(s, d.edgeSegment.firstStep);
        else
          d.edgeRange.first = std::min(s, d.edgeSegment.lastStep);
        d.showEdgePreview();
      } else if (d.drag == Impl::Drag::Pan) {
        const double perPixel =
            static_cast<double>(d.pressRange.size()) / std::max(1, d.heatRect->width());
        const auto shift = std::llround(-dx * perPixel);
        setVisibleRange(d.fitted(d.pressRange.first + shift, d.pressRange.size()));
      }
      return true;
    }
    case QEvent::MouseButtonRelease:
      d.release(static_cast<QMouseEvent*>(event)->position());
      return true;
    case QEvent::Wheel: {
      auto* we = static_cast<QWheelEvent*>(event);
      const QPoint delta = we->angleDelta();
      d.zoom(we->position().x(), delta.y() != 0 ? delta.y() : delta.x());
      return true;
    }
    default:
      return QWidget::eventFilter(watched, event);
  }
}

}  // namespace tactile::gui
