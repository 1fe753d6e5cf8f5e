#include "app/gui/runs/route_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QSettings>
#include <QWheelEvent>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "app/gui/common/plot_style.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/learning/prediction_model.h"
#include "app/gui/runs/run_session_model.h"
#include "run/robot_geometry.h"

namespace tactile::gui {
namespace {

constexpr double kCloseUpUnits = 400.0;  // scene units across the shorter side of the close-up
constexpr double kFitMarginPx = 12.0;
constexpr double kDragThresholdPx = 4.0;
constexpr double kMinZoom = 0.05, kMaxZoom = 500.0;
// Colour keys: time bins 0..kTimeBins-1, or a contact class, or unlabelled.
constexpr int kTimeBins = 64;
constexpr std::uint8_t kUnlabelledKey = kContactClassCount;
// Polyline pieces stay short so that culling and click search can skip most of a long route.
constexpr int kMaxChunkPoints = 512;
constexpr int kMaxHoleMarks = 300;  // hole marks along the route, at most
constexpr std::size_t kWidePenPoints = 50000;

const QString kColourModeKey = QStringLiteral("routeView/colourMode");
const QString kWholeSceneKey = QStringLiteral("routeView/wholeScene");

// Scene to widget: (s * x + tx, -s * y + ty), y flipped so the scene is drawn y up. The route
// cache holds "scaled" coordinates (s * x, -s * y), valid for every translation at one scale, so
// the close-up following the robot never rebuilds it.
struct Transform {
  double s = 1.0, tx = 0.0, ty = 0.0;
  QPointF map(double x, double y) const { return {s * x + tx, -s * y + ty}; }
  QTransform qt() const { return {s, 0.0, 0.0, -s, tx, ty}; }
  bool operator==(const Transform&) const = default;
};

QColor timeColour(int bin) {
  const double t = bin / double(kTimeBins - 1);
  return QColor::fromRgbF(float(0.62 - 0.56 * t), float(0.76 - 0.62 * t), float(0.96 - 0.54 * t));
}

void drawArrow(QPainter& p, QPointF from, QPointF to, const QColor& colour) {
  const QPointF d = to - from;
  const double len = std::hypot(d.x(), d.y());
  if (len < 1.0) return;
  const QPointF u = d / len;
  const QPointF n(-u.y(), u.x());
  const double head = std::min(10.0, 0.5 * len);
  p.setPen(QPen(colour, 2.5, Qt::SolidLine, Qt::RoundCap));
  p.drawLine(from, to - u * head * 0.8);
  p.setPen(Qt::NoPen);
  p.setBrush(colour);
  const QPointF base = to - u * head;
  p.drawPolygon(QPolygonF({to, base + n * head * 0.5, base - n * head * 0.5}));
}

QRectF boundingBox(const QPointF* p, int count) {
  double x0 = p[0].x(), x1 = x0, y0 = p[0].y(), y1 = y0;
  for (int i = 1; i < count; ++i) {
    x0 = std::min(x0, p[i].x());
    x1 = std::max(x1, p[i].x());
    y0 = std::min(y0, p[i].y());
    y1 = std::max(y1, p[i].y());
  }
  return {QPointF(x0, y0), QPointF(x1, y1)};
}

// Unlike QRectF::intersects, true for a box of zero width or height (a straight piece of route).
bool overlaps(const QRectF& a, const QRectF& b) {
  return a.left() <= b.right() && b.left() <= a.right() && a.top() <= b.bottom() &&
         b.top() <= a.bottom();
}

// A line of text on a light box, centred at the bottom of `area` or at its top left.
void drawBadge(QPainter& p, const QRect& area, const QString& text, bool bottom) {
  const QFontMetrics fm = p.fontMetrics();
  const QSize size(fm.horizontalAdvance(text) + 12, fm.height() + 6);
  const QPoint at =
      bottom ? QPoint(area.center().x() - size.width() / 2, area.bottom() - size.height() - 8)
             : QPoint(area.left() + 8, area.top() + 8);
  const QRect box(at, size);
  p.setPen(QColor(120, 120, 120));
  p.setBrush(QColor(255, 255, 255, 225));
  p.drawRoundedRect(box, 4, 4);
  p.setPen(QColor(30, 30, 30));
  p.drawText(box, Qt::AlignCenter, text);
}

// Where a label of `size` goes next to the point `at`: the first of four places around it that
// lies inside `area` and overlaps no label already placed (then it is added to `placed`);
// nullopt when every place is taken, so the label is left out rather than drawn over another.
// A place for a label beside `at`: the first of the four corners, then the same a little further
// out, that lies in `area`, overlaps no label placed before and nothing `blocked` says is in the
// way (obstacles, the route). None: the label is left out (its mark stays).
std::optional<QRectF> placeLabel(QPointF at, QSizeF size, const QRectF& area,
                                 std::vector<QRectF>& placed,
                                 const std::function<bool(const QRectF&)>& blocked = {}) {
  for (const double gap : {4.0, 14.0, 26.0}) {
    const std::array<QPointF, 4> corners{
        QPointF(at.x() + 2 + gap, at.y() - gap - size.height()),
        QPointF(at.x() + 2 + gap, at.y() + gap),
        QPointF(at.x() - 2 - gap - size.width(), at.y() - gap - size.height()),
        QPointF(at.x() - 2 - gap - size.width(), at.y() + gap)};
    for (const QPointF& c : corners) {
      const QRectF r(c, size);
      if (!area.contains(r)) continue;
      if (std::any_of(placed.begin(), placed.end(),
                      [&r](const QRectF& other) { return other.intersects(r); }))
        continue;
      if (blocked && blocked(r)) continue;
      placed.push_back(r);
      return r;
    }
  }
  return std::nullopt;
}

}  // namespace

struct RouteView::Impl {
  struct PixelRun {               // consecutive steps on one pixel with one colour key
    std::int64_t px = 0, py = 0;  // the pixel, in scaled coordinates
    std::int64_t first = 0, last = 0;
    std::uint8_t key = 0;
    int point = 0;  // its first point in `points`
  };
  struct Chunk {  // a polyline piece of one colour: runs [runBegin, runEnd)
    int runBegin = 0, runEnd = 0;
    int pointBegin = 0;  // first point drawn (the previous chunk's last point, to join them)
    int pointEnd = 0;
    std::uint8_t key = 0;
    QRectF box;  // scaled coordinates
  };

  RouteView* q = nullptr;
  RunSession* session = nullptr;
  LabelModel* labels = nullptr;
  ColourMode mode = ColourMode::Time;
  bool whole = true;
  double zoom = 1.0;  // on top of the mode's fit
  QPointF pan;        // pixels, on top of the mode's centre

  bool runDirty = true;
  QRectF sceneRect;  // scene units, y up: what the whole-scene mode fits
  std::vector<QPolygonF> obstacles;
  std::array<DomePlacement, kSensorCount> domes = domePlacements();
  const PredictionModel* predictions = nullptr;
  RobotGeometry robot;

  bool routeDirty = true;
  double cacheScale = 0.0;
  std::vector<PixelRun> runs;
  std::vector<QPointF> points;
  std::vector<Chunk> chunks;

  bool layerDirty = true;
  QPixmap layer;
  Transform layerTransform;

  bool pressed = false, dragging = false;
  QPointF pressPos, lastPos;

  bool hasRoute() const {
    return session != nullptr && session->isOpen() && session->stepCount() > 0;
  }

  void markRouteDirty() {
    routeDirty = true;
    layerDirty = true;
  }
  void refresh() {
    if (q->isVisible()) q->update();
  }
  void resetView() {
    zoom = 1.0;
    pan = {};
    layerDirty = true;
    refresh();
  }

  void ensureRun() {
    if (!runDirty) return;
    runDirty = false;
    obstacles.clear();
    const storage::RunTrack& t = session->track();
    if (const auto& scene = session->scene()) {
      const sim::SceneBounds& b = scene->bounds;
      sceneRect = QRectF(b.xmin, b.ymin, b.xmax - b.xmin, b.ymax - b.ymin);
      for (const sim::Obstacle& o : scene->obstacles) {
        QPolygonF poly;
        for (const sim::Vec2& v : o.polygon)
          poly << QPointF(v.x(), v.y());
        obstacles.push_back(std::move(poly));
      }
    } else {  // no scene: the route's box
      const auto [xmin, xmax] = std::minmax_element(t.x.begin(), t.x.end());
      const auto [ymin, ymax] = std::minmax_element(t.y.begin(), t.y.end());
      QRectF box(QPointF(*xmin, *ymin), QPointF(*xmax, *ymax));
      if (const auto g = session->goal()) box |= QRectF(g->first, g->second, 0.0, 0.0);
      const double margin = std::max(50.0, 0.05 * std::max(box.width(), box.height()));
      sceneRect = box.adjusted(-margin, -margin, margin, margin);
    }
  }

  Pose2d poseAt(std::int64_t step) const {
    const storage::RunTrack& t = session->track();
    const auto i =
        static_cast<std::size_t>(std::clamp<std::int64_t>(step, 0, session->stepCount() - 1));
    return {t.x[i], t.y[i], t.theta[i]};
  }

  Transform prepare() {
    ensureRun();
    return transform();
  }

  Transform transform() const {
    const double w = std::max(1, q->width());
    const double h = std::max(1, q->height());
    double base = 1.0;
    QPointF centre = sceneRect.center();
    if (whole) {
      const double sw = std::max(1e-9, sceneRect.width());
      const double sh = std::max(1e-9, sceneRect.height());
      base = std::min(std::max(1.0, w - 2 * kFitMarginPx) / sw,
                      std::max(1.0, h - 2 * kFitMarginPx) / sh);
    } else {
      base = std::min(w, h) / kCloseUpUnits;
      const Pose2d pose = poseAt(session->currentStep());
      centre = QPointF(pose.x, pose.y);
    }
    Transform xf;
    xf.s = base * zoom;
    xf.tx = 0.5 * w + pan.x() - xf.s * centre.x();
    xf.ty = 0.5 * h + pan.y() + xf.s * centre.y();
    return xf;
  }

  std::uint8_t labelKey(const std::vector<storage::LabelSegment>& segs, std::size_t& next,
                        std::int64_t step) const {
    while (next < segs.size() && segs[next].lastStep < step)
      ++next;
    if (next < segs.size() && segs[next].firstStep <= step) {
      return static_cast<std::uint8_t>(segs[next].cls);
    }
    return kUnlabelledKey;
  }

  QColor keyColour(std::uint8_t key) const {
    if (mode == ColourMode::Time) return timeColour(key);
    if (key == kUnlabelledKey) return QColor(150, 150, 150);
    return classColor(static_cast<ContactClass>(key));
  }

  // One walk over the track: a point is kept only where the pixel (or the colour) changes, plus
  // the last step of each pixel run, so the drawn shape is exact to a pixel.
  void ensureRoute(double s) {
    if (!routeDirty && s == cacheScale) return;
    routeDirty = false;
    layerDirty = true;
    cacheScale = s;
    runs.clear();
    points.clear();
    chunks.clear();
    const storage::RunTrack& t = session->track();
    const auto n = static_cast<std::int64_t>(t.stepCount());
    const bool byLabel =
        mode == ColourMode::Label && labels != nullptr && labels->runId() == session->info().id;
    static const std::vector<storage::LabelSegment> kNoSegments;
    const auto& segs = byLabel ? labels->segments(session->selectedGroup()) : kNoSegments;
    std::size_t nextSeg = 0;
    auto closeRun = [&] {
      const PixelRun& r = runs.back();
      if (r.last == r.first) return;
      points.emplace_back(s * t.x[std::size_t(r.last)], -s * t.y[std::size_t(r.last)]);
    };
    for (std::int64_t i = 0; i < n; ++i) {
      const double u = s * t.x[std::size_t(i)];
      const double v = -s * t.y[std::size_t(i)];
      const auto px = static_cast<std::int64_t>(std::floor(u));
      const auto py = static_cast<std::int64_t>(std::floor(v));
      const std::uint8_t key = mode == ColourMode::Time
                                   ? static_cast<std::uint8_t>(i * kTimeBins / n)
                                   : labelKey(segs, nextSeg, i);
      if (!runs.empty() && runs.back().px == px && runs.back().py == py && runs.back().key == key) {
        runs.back().last = i;
        continue;
      }
      if (!runs.empty()) closeRun();
      runs.push_back({px, py, i, i, key, static_cast<int>(points.size())});
      points.emplace_back(u, v);
    }
    if (!runs.empty()) closeRun();

    for (int r = 0; r < static_cast<int>(runs.size()); ++r) {
      const PixelRun& run = runs[std::size_t(r)];
      if (chunks.empty() || chunks.back().key != run.key ||
          run.point - chunks.back().pointBegin >= kMaxChunkPoints) {
        chunks.push_back({r, r, std::max(0, run.point - 1), 0, run.key, {}});
      }
      chunks.back().runEnd = r + 1;
      chunks.back().pointEnd = r + 1 < static_cast<int>(runs.size())
                                   ? runs[std::size_t(r) + 1].point
                                   : int(points.size());
    }
    for (Chunk& c : chunks)
      c.box = boundingBox(points.data() + c.pointBegin, c.pointEnd - c.pointBegin);
  }

  // Bounds, obstacles, route, start and goal for one transform; reused while only the cursor
  // moves in the whole-scene mode.
  void ensureLayer(const Transform& xf) {
    const qreal dpr = q->devicePixelRatioF();
    const QSize size = q->size() * dpr;
    if (!layerDirty && xf == layerTransform && layer.size() == size) return;
    layerDirty = false;
    layerTransform = xf;
    layer = QPixmap(size);
    layer.setDevicePixelRatio(dpr);
    layer.fill(QColor(226, 226, 226));
    QPainter p(&layer);
    const QRectF view(QPointF(0, 0), QSizeF(q->size()));
    const QRectF bounds = xf.qt().mapRect(sceneRect);
    p.fillRect(bounds, Qt::white);
    if (session->scene()) {
      p.setPen(QPen(QColor(60, 60, 60), 1.5));
      p.setBrush(Qt::NoBrush);
      p.drawRect(bounds);
    }

    p.setRenderHint(QPainter::Antialiasing, true);
    QPen outline(QColor(85, 85, 85), 1.2);
    outline.setCosmetic(true);
    p.setPen(outline);
    p.setBrush(QColor(175, 175, 175));
    p.setTransform(xf.qt());
    for (const QPolygonF& poly : obstacles)
      p.drawPolygon(poly);
    p.resetTransform();

    // The long polyline without antialiasing; only the pieces that reach the view.
    p.setRenderHint(QPainter::Antialiasing, false);
    p.translate(xf.tx, xf.ty);
    const QRectF visible = view.translated(-xf.tx, -xf.ty).adjusted(-4, -4, 4, 4);
    // Wide pens go through the stroker, ten times slower than a cosmetic 1-pixel pen.
    const double width = points.size() < kWidePenPoints ? 2.0 : 0.0;
    for (const Chunk& c : chunks) {
      if (!overlaps(c.box, visible)) continue;
      p.setPen(QPen(keyColour(c.key), width, Qt::SolidLine, Qt::SquareCap, Qt::BevelJoin));
      if (c.pointEnd - c.pointBegin == 1) {
        p.drawPoint(points[c.pointBegin]);
      } else {
        p.drawPolyline(points.data() + c.pointBegin, c.pointEnd - c.pointBegin);
      }
    }
    p.resetTransform();

    p.setRenderHint(QPainter::Antialiasing, true);
    if (const auto start = session->start()) {
      const QPointF at = xf.map(start->x, start->y);
      const QPointF dir(std::cos(start->theta), -std::sin(start->theta));
      p.setPen(QPen(QColor(20, 120, 40), 2.0));
      p.setBrush(QColor(60, 190, 80));
      p.drawEllipse(at, 5.0, 5.0);
      p.drawLine(at, at + dir * 12.0);
    }
    if (const auto goal = goalPoint()) {
      const QPointF at = xf.map(goal->x(), goal->y());
      p.setPen(QPen(QColor(150, 20, 20), 1.5));
      p.setBrush(QColor(230, 60, 60, 170));
      p.drawEllipse(at, 7.0, 7.0);
      p.setPen(QPen(QColor(120, 20, 20), 2.0));
      p.drawLine(at, at + QPointF(0, -22));
      p.setPen(Qt::NoPen);
      p.setBrush(QColor(220, 40, 40));
      p.drawPolygon(
          QPolygonF({at + QPointF(1, -22), at + QPointF(14, -17.5), at + QPointF(1, -13)}));
    }
  }

  std::optional<QPointF> goalPoint() const {
    const auto g = session->goal();
    return g ? std::optional(QPointF(g->first, g->second)) : std::nullopt;
  }

  // Holes (thesis 4.5) from the predictions: one mark with its width where a run of consecutive
  // steps shows a hole on one side, and at the current step the gap itself between its two domes.
  void drawHoles(QPainter& p, const Transform& xf) const {
    if (predictions == nullptr || !predictions->hasPredictions() || !session->isOpen() ||
        predictions->runName() != QString::fromStdString(session->info().name))
      return;
    p.setRenderHint(QPainter::Antialiasing, true);
    const std::vector<HoleMark>& holes = predictions->holes();
    QFont small = q->font();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    p.setFont(small);
    int drawn = 0;
    const QFontMetricsF metrics(small);
    // Labels stay inside the view, clear of the badges at the top and bottom and of each other.
    const QRectF area =
        QRectF(q->rect()).adjusted(2, metrics.height() + 16, -2, -(3 * metrics.height() + 48));
    std::vector<QRectF> placed;
    // Labels keep off the obstacles and the route, so neither hides the other.
    std::vector<QPolygonF> obstaclePixels;
    for (const QPolygonF& poly : obstacles)
      obstaclePixels.push_back(xf.qt().map(poly));
    const QPointF routeShift(xf.tx, xf.ty);
    auto blocked = [&](const QRectF& r) {
      const QPolygonF box(r);
      for (const QPolygonF& poly : obstaclePixels)
        if (poly.boundingRect().intersects(r) && poly.intersects(box)) return true;
      const QRectF scaled = r.translated(-routeShift);
      for (const Chunk& c : chunks) {
        if (!overlaps(c.box, scaled)) continue;
        for (int i = c.pointBegin; i < c.pointEnd; ++i)
          if (scaled.contains(points[static_cast<std::size_t>(i)])) return true;
      }
      return false;
    };
    for (std::size_t i = 0; i < holes.size() && drawn < kMaxHoleMarks; ++i) {
      // The first step of a run of steps with a hole on the same side.
      bool continues = false;
      for (std::size_t j = i; j-- > 0 && holes[j].step >= holes[i].step - 1;) {
        if (holes[j].step == holes[i].step - 1 && holes[j].side == holes[i].side) continues = true;
      }
      if (continues) continue;
      const Pose2d pose = poseAt(holes[i].step);
      const QPointF at = xf.map(pose.x, pose.y);
      p.setPen(QPen(QColor(20, 20, 20), 1.5));
      p.setBrush(QColor(255, 200, 0));
      p.drawRect(QRectF(at.x() - 3.5, at.y() - 3.5, 7, 7));
      const QString text = RouteView::tr("hole %1").arg(holes[i].widthUnits, 0, 'f', 1);
      if (const auto box =
              placeLabel(at, metrics.size(0, text) + QSizeF(4, 0), area, placed, blocked)) {
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 200));
        p.drawRect(*box);
        p.setPen(QColor(20, 20, 20));
        p.drawText(box->adjusted(2, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, text);
      }
      ++drawn;
    }
    // What a hole is, once, above the distance badge (as tall as its wrapped text needs).
    if (drawn > 0) {
      const QString legend =
          RouteView::tr("\u25A0 hole N: a gap N units wide that the model felt on one side");
      const QRectF room(6, 0, q->width() - 12, q->height());
      const QRectF text = metrics.boundingRect(room, Qt::AlignLeft | Qt::TextWordWrap, legend);
      const QRectF box(QPointF(4, q->height() - metrics.height() - 30 - text.height()),
                       QSizeF(q->width() - 8, text.height() + 4));
      p.setPen(Qt::NoPen);
      p.setBrush(QColor(255, 255, 255, 210));
      p.drawRect(box);
      p.setPen(QColor(20, 20, 20));
      p.drawText(box.adjusted(2, 2, -2, -2), Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap,
                 legend);
    }
    const Pose2d pose = poseAt(session->currentStep());
    const double c = std::cos(pose.theta);
    const double sn = std::sin(pose.theta);
    const QTransform body = QTransform(c, sn, -sn, c, pose.x, pose.y) * xf.qt();
    for (const HoleMark& h : predictions->holesAt(session->currentStep())) {
      const DomePlacement& a = domes[static_cast<std::size_t>(h.sensorBefore)];
      const DomePlacement& b = domes[static_cast<std::size_t>(h.sensorAfter)];
      const QPointF pa = body.map(QPointF(a.centre.x, a.centre.y));
      const QPointF pb = body.map(QPointF(b.centre.x, b.centre.y));
      p.setPen(QPen(QColor(255, 140, 0), 3.0, Qt::DashLine, Qt::RoundCap));
      p.drawLine(pa, pb);
      p.setPen(QColor(20, 20, 20));
      const QString text = RouteView::tr("hole %1 wide").arg(h.widthUnits, 0, 'f', 1);
      if (const auto box = placeLabel((pa + pb) / 2, metrics.size(0, text),
                                      QRectF(q->rect()).adjusted(2, 2, -2, -2), placed))
        p.drawText(*box, Qt::AlignLeft | Qt::AlignVCenter, text);
    }
  }

  void drawRobot(QPainter& p, const Transform& xf) const {
    const Pose2d pose = poseAt(session->currentStep());
    const double c = std::cos(pose.theta);
    const double sn = std::sin(pose.theta);
    const QTransform body = QTransform(c, sn, -sn, c, pose.x, pose.y) * xf.qt();
    p.setRenderHint(QPainter::Antialiasing, true);

    QPainterPath outline;
    outline.addRoundedRect(
        QRectF(robot.backX(), -robot.halfWidth(), robot.lengthUnits, robot.widthUnits),
        robot.cornerRadiusUnits, robot.cornerRadiusUnits);
    p.setPen(QPen(QColor(40, 40, 40), 1.5));
    p.setBrush(QColor(255, 255, 255, 190));
    p.drawPath(body.map(outline));

    const auto& values = session->currentSensors();
    const SensorGroup selected = session->selectedGroup();
    const double radius = std::max(2.0, robot.domeRadiusUnits * xf.s);
    const QPen plain(QColor(70, 70, 70), 1.0);
    const QPen highlight(QColor(255, 150, 0), std::max(2.0, 0.35 * radius));
    for (int i = 0; i < kSensorCount; ++i) {
      const DomePlacement& d = domes[static_cast<std::size_t>(i)];
      const double value = values[static_cast<std::size_t>(normalOffset(i))];
      p.setPen(groupOfSensor(i) == selected ? highlight : plain);
      p.setBrush(value > 0.0 ? QBrush(valueColor(value, kMaxNormal)) : QBrush(Qt::NoBrush));
      p.drawEllipse(body.map(QPointF(d.centre.x, d.centre.y)), radius, radius);
    }

    const QPointF centre = body.map(QPointF(0.5 * (robot.frontX() + robot.backX()), 0.0));
    const QPointF ahead = body.map(QPointF(1.0, 0.0)) - body.map(QPointF(0.0, 0.0));
    const double aheadLen = std::hypot(ahead.x(), ahead.y());
    const double headingPx = std::max(30.0, 0.75 * robot.lengthUnits * xf.s);
    if (aheadLen > 0.0)
      drawArrow(p, centre, centre + ahead / aheadLen * headingPx, QColor(30, 90, 220));

    if (const auto goal = goalPoint()) {
      const QPointF to = xf.map(goal->x(), goal->y()) - centre;
      const double toLen = std::hypot(to.x(), to.y());
      const double goalPx = std::min(toLen, std::max(40.0, 0.6 * robot.lengthUnits * xf.s));
      if (toLen > 0.0) drawArrow(p, centre, centre + to / toLen * goalPx, QColor(210, 40, 40));
      const double dist = std::hypot(goal->x() - pose.x, goal->y() - pose.y);
      drawBadge(p, q->rect(), RouteView::tr("%1 units to the goal").arg(qRound(dist)), true);
    }
  }
};

void RouteView::setPredictions(const PredictionModel* predictions) {
  if (d_->predictions != nullptr) disconnect(d_->predictions, nullptr, this, nullptr);
  d_->predictions = predictions;
  if (predictions != nullptr) {
    connect(predictions, &PredictionModel::ready, this, [this] { update(); });
    // Hide Predictions takes the holes off at once.
    connect(predictions, &PredictionModel::changed, this, [this] { update(); });
  }
  update();
}

int RouteView::holeMarksAt(std::int64_t step) const {
  if (d_->predictions == nullptr || !d_->predictions->hasPredictions()) return 0;
  return static_cast<int>(d_->predictions->holesAt(step).size());
}

RouteView::RouteView(RunSession* session, LabelModel* labels, QWidget* parent)
    : QWidget(parent), d_(new Impl) {
  d_->q = this;
  d_->session = session;
  d_->labels = labels;
  setObjectName(QStringLiteral("routeView"));
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(200, 150);
  connect(session, &RunSession::runOpened, this, [this] {
    d_->runDirty = true;
    d_->markRouteDirty();
    d_->resetView();
  });
  // The cursor only moves the robot (and, in the close-up, the translation): no rebuild.
  connect(session, &RunSession::currentStepChanged, this, [this] { d_->refresh(); });
  connect(session, &RunSession::selectedGroupChanged, this, [this] {
    if (d_->mode == ColourMode::Label) d_->markRouteDirty();
    d_->refresh();
  });
  if (labels != nullptr) {
    connect(labels, &LabelModel::labelsChanged, this, [this] {
      if (d_->mode != ColourMode::Label) return;
      d_->markRouteDirty();
      d_->refresh();
    });
  }
}

RouteView::~RouteView() {
  delete d_;
}

RouteView::ColourMode RouteView::colourMode() const {
  return d_->mode;
}

void RouteView::setColourMode(ColourMode mode) {
  if (mode == d_->mode) return;
  d_->mode = mode;
  d_->markRouteDirty();
  d_->refresh();
  emit viewSettingsChanged();
}

QString RouteView::badgeText() const {
  // Zoomed or panned, the view no longer shows what the mode's name says.
  const bool moved = d_->zoom != 1.0 || !d_->pan.isNull();
  if (!moved) return d_->whole ? tr("Whole scene (M: close-up)") : tr("Close-up (M: whole scene)");
  const QString zoom = QString::number(d_->zoom, 'f', d_->zoom < 10 ? 1 : 0);
  return d_->whole ? tr("Zoomed %1x (double click: whole scene)").arg(zoom)
                   : tr("Close-up zoomed %1x (double click: close-up)").arg(zoom);
}

bool RouteView::wholeScene() const {
  return d_->whole;
}

void RouteView::setWholeScene(bool whole) {
  if (whole == d_->whole) return;
  d_->whole = whole;
  d_->resetView();
  emit viewSettingsChanged();
}

void RouteView::saveSettings(QSettings& settings) const {
  settings.setValue(kColourModeKey, d_->mode == ColourMode::Label ? QStringLiteral("label")
                                                                  : QStringLiteral("time"));
  settings.setValue(kWholeSceneKey, d_->whole);
}

void RouteView::restoreSettings(const QSettings& settings) {
  const QString mode = settings.value(kColourModeKey, QStringLiteral("time")).toString();
  setColourMode(mode == QLatin1String("label") ? ColourMode::Label : ColourMode::Time);
  setWholeScene(settings.value(kWholeSceneKey, true).toBool());
}

QPointF RouteView::stepToWidget(std::int64_t step) const {
  if (!d_->hasRoute()) return {};
  const Pose2d pose = d_->poseAt(step);
  return d_->prepare().map(pose.x, pose.y);
}

// Searches the decimated pixel runs (skipping whole chunks by their boxes), nearest pixel first,
// and scans the exact steps only of runs whose pixel could still hold a nearer point.
std::optional<std::int64_t> RouteView::stepAt(QPointF widgetPos, double radius) const {
  if (!d_->hasRoute()) return std::nullopt;
  const Transform xf = d_->prepare();
  d_->ensureRoute(xf.s);
  const QPointF at = widgetPos - QPointF(xf.tx, xf.ty);
  const double r2 = radius * radius;
  std::vector<std::pair<double, int>> candidates;
  for (const Impl::Chunk& c : d_->chunks) {
    if (!c.box.adjusted(-radius - 1, -radius - 1, radius + 1, radius + 1).contains(at)) continue;
    for (int r = c.runBegin; r < c.runEnd; ++r) {
      const Impl::PixelRun& run = d_->runs[static_cast<std::size_t>(r)];
      const double px = static_cast<double>(run.px);
      const double py = static_cast<double>(run.py);
      const double dx = std::max({px - at.x(), 0.0, at.x() - (px + 1.0)});
      const double dy = std::max({py - at.y(), 0.0, at.y() - (py + 1.0)});
      const double bound = dx * dx + dy * dy;
      if (bound <= r2) candidates.emplace_back(bound, r);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  const storage::RunTrack& t = d_->session->track();
  double best = r2;
  std::optional<std::int64_t> found;
  for (const auto& [bound, r] : candidates) {
    if (bound > best) break;
    const Impl::PixelRun& run = d_->runs[static_cast<std::size_t>(r)];
    for (std::int64_t i = run.first; i <= run.last; ++i) {
      const auto j = static_cast<std::size_t>(i);
      const double dx = xf.s * t.x[j] - at.x();
      const double dy = -xf.s * t.y[j] - at.y();
      const double dist = dx * dx + dy * dy;
      if (dist < best || (!found && dist <= best)) {
        best = dist;
        found = i;
      }
    }
  }
  return found;
}

int RouteView::drawnRoutePoints() const {
  if (!d_->hasRoute()) return 0;
  d_->ensureRoute(d_->prepare().s);
  return static_cast<int>(d_->points.size());
}

void RouteView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  if (!d_->hasRoute()) {
    p.fillRect(rect(), QColor(226, 226, 226));
    p.setPen(QColor(90, 90, 90));
    p.drawText(rect(), Qt::AlignCenter, tr("No run open"));
    return;
  }
  const Transform xf = d_->prepare();
  d_->ensureRoute(xf.s);
  d_->ensureLayer(xf);
  p.drawPixmap(0, 0, d_->layer);
  d_->drawRobot(p, xf);
  d_->drawHoles(p, xf);
  p.setRenderHint(QPainter::Antialiasing, false);
  drawBadge(p, rect(), badgeText(), false);
}

void RouteView::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) {
    QWidget::mousePressEvent(event);
    return;
  }
  // QWidget delivers a double click here too: it resets the zoom and is no click of its own.
  if (event->type() == QEvent::MouseButtonDblClick) {
    d_->pressed = false;
    d_->resetView();
    return;
  }
  d_->pressed = true;
  d_->dragging = false;
  d_->pressPos = d_->lastPos = event->position();
}

void RouteView::mouseMoveEvent(QMouseEvent* event) {
  if (!d_->pressed || !(event->buttons() & Qt::LeftButton)) return;
  const QPointF pos = event->position();
  if (!d_->dragging) {
    const QPointF moved = pos - d_->pressPos;
    if (std::hypot(moved.x(), moved.y()) <= kDragThresholdPx) return;
    d_->dragging = true;
    setCursor(Qt::ClosedHandCursor);
  }
  d_->pan += pos - d_->lastPos;
  d_->lastPos = pos;
  update();
}

void RouteView::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || !d_->pressed) return;
  const bool click = !d_->dragging;
  d_->pressed = d_->dragging = false;
  unsetCursor();
  if (!click) return;
  if (const auto step = stepAt(event->position())) d_->session->setCurrentStep(*step);
}

void RouteView::wheelEvent(QWheelEvent* event) {
  const int delta = event->angleDelta().y();
  if (delta == 0 || !d_->hasRoute()) {
    event->ignore();
    return;
  }
  const double target = std::clamp(d_->zoom * std::pow(2.0, delta / 480.0), kMinZoom, kMaxZoom);
  const double f = target / d_->zoom;
  // Keeps the scene point under the pointer where it is: pan' = p - c - f (p - c - pan).
  const QPointF centre(0.5 * std::max(1, width()), 0.5 * std::max(1, height()));
  const QPointF offset = event->position() - centre;
  d_->pan = offset - f * (offset - d_->pan);
  d_->zoom = target;
  event->accept();
  update();
}

void RouteView::keyPressEvent(QKeyEvent* event) {
  if (event->key() == Qt::Key_M) {
    setWholeScene(!d_->whole);
  } else if (event->key() == Qt::Key_Home) {
    d_->resetView();
  } else {
    QWidget::keyPressEvent(event);
  }
}

void RouteView::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);  // the layer follows the size by itself
}

void RouteView::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  update();
}

}  // namespace tactile::gui
