#include "app/gui/sim/status_picture_view.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

#include "app/gui/common/plot_style.h"
#include "app/gui/sim/sim_session.h"
#include "nav/navigator.h"
#include "run/robot_geometry.h"
#include "sim/simulator.h"

namespace tactile::gui {
namespace {

void drawArrow(QPainter& p, QPointF from, QPointF to, const QColor& colour, double width) {
  const QPointF d = to - from;
  const double len = std::hypot(d.x(), d.y());
  if (len < 1.0) return;
  const QPointF u = d / len;
  const QPointF n(-u.y(), u.x());
  const double head = std::min(14.0 + width, 0.4 * len);
  p.setPen(QPen(colour, width, Qt::SolidLine, Qt::RoundCap));
  p.drawLine(from, to - u * head * 0.6);
  QPolygonF tip;
  tip << to << to - u * head + n * head * 0.45 << to - u * head - n * head * 0.45;
  p.setPen(Qt::NoPen);
  p.setBrush(colour);
  p.drawPolygon(tip);
}

// World to widget: x right, y up, uniform scale.
struct Frame {
  double scale = 1.0;
  QPointF origin;  // widget point of world (0, 0)
  QPointF map(double x, double y) const { return {origin.x() + x * scale, origin.y() - y * scale}; }
  QTransform qt() const { return QTransform(scale, 0, 0, -scale, origin.x(), origin.y()); }
};

}  // namespace

QColor StatusPictureView::touchedColour() {
  return {150, 60, 0};
}

QColor StatusPictureView::closedColour() {
  return {255, 150, 40};
}

QColor StatusPictureView::planColour() {
  return {130, 40, 170};
}

StatusPictureView::StatusPictureView(SimSession* session, QWidget* parent)
    : QWidget(parent), session_(session) {
  setMinimumSize(320, 320);
  setFocusPolicy(Qt::StrongFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);
  connect(session_, &SimSession::stepped, this, qOverload<>(&QWidget::update));
  connect(session_, &SimSession::started, this, [this] {
    if (!session_->mayShowScene()) setWholeScene(false);
    mapImage_ = QImage();  // a new run has a new navigator and map
    update();
  });
}

bool StatusPictureView::setWholeScene(bool whole) {
  if (whole && !session_->mayShowScene()) whole = false;
  if (whole != wholeScene_) {
    wholeScene_ = whole;
    emit viewChanged(wholeScene_);
    update();
  }
  return wholeScene_;
}

bool StatusPictureView::toggle() {
  const bool before = wholeScene_;
  return setWholeScene(!wholeScene_) != before;
}

void StatusPictureView::setShowTouchMap(bool show) {
  if (show == showTouchMap_) return;
  showTouchMap_ = show;
  update();
}

void StatusPictureView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(250, 250, 247));
  p.setRenderHint(QPainter::Antialiasing, true);
  const sim::Simulator* simulator = session_->simulator();
  if (simulator == nullptr) {
    p.setPen(QColor(90, 90, 90));
    p.drawText(rect(), Qt::AlignCenter, tr("Choose a scene and a mode, then press Start."));
    return;
  }
  const RobotGeometry robot = simulator->config().geometry;
  const sim::Scene& scene = *session_->scene();
  const Pose2d pose = simulator->pose();
  // Below the caption at the top, above the distance at the bottom.
  const QRectF area = QRectF(rect()).adjusted(16, 28, -16, -40);

  Frame f;
  if (wholeScene_) {
    const auto& b = scene.bounds;
    f.scale = std::min(area.width() / (b.xmax - b.xmin), area.height() / (b.ymax - b.ymin));
    const QPointF centre = area.center();
    f.origin =
        centre - QPointF(0.5 * (b.xmin + b.xmax) * f.scale, -0.5 * (b.ymin + b.ymax) * f.scale);
    // Bounds and obstacles.
    p.setPen(QPen(QColor(60, 60, 60), 2.0));
    p.setBrush(Qt::white);
    p.drawRect(QRectF(f.map(b.xmin, b.ymax), f.map(b.xmax, b.ymin)));
    p.setBrush(QColor(150, 150, 150));
    p.setPen(QPen(QColor(70, 70, 70), 1.0));
    for (const sim::Obstacle& o : scene.obstacles) {
      QPolygonF poly;
      for (const sim::Vec2& v : o.polygon)
        poly << f.map(v.x(), v.y());
      p.drawPolygon(poly);
    }
    // The route so far, one point per pixel at most.
    if (const RunData* run = session_->run(); run != nullptr && run->stepCount() > 1) {
      QPolygonF route;
      QPointF last(-1e9, -1e9);
      const QPointF start = f.map(scene.start.x, scene.start.y);
      route << start;
      for (std::size_t k = 0; k < run->stepCount(); ++k) {
        const QPointF pt = f.map(run->x[k], run->y[k]);
        if (std::abs(pt.x() - last.x()) + std::abs(pt.y() - last.y()) < 1.0) continue;
        route << pt;
        last = pt;
      }
      p.setPen(QPen(QColor(40, 120, 60), 1.5));
      p.setBrush(Qt::NoBrush);
      p.drawPolyline(route);
    }
    // Start and goal.
    p.setPen(QPen(QColor(30, 90, 220), 2.0));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(f.map(scene.start.x, scene.start.y), 5.0, 5.0);
    const double goalRadius = 60.0 * f.scale;
    p.setPen(QPen(QColor(210, 40, 40), 2.0));
    p.setBrush(QColor(210, 40, 40, 40));
    p.drawEllipse(f.map(scene.goal.x(), scene.goal.y()), goalRadius, goalRadius);
  } else {
    // The robot fills about half the picture, its body centre in the middle.
    f.scale = 0.5 * std::min(area.width(), area.height()) / robot.lengthUnits;
    const double cx = 0.5 * (robot.frontX() + robot.backX());
    const double wx = pose.x + cx * std::cos(pose.theta);
    const double wy = pose.y + cx * std::sin(pose.theta);
    f.origin = area.center() - QPointF(wx * f.scale, -wy * f.scale);
    // A faint grid moves under the robot so a person sees it move.
    const double spacing = 50.0;
    p.setPen(QPen(QColor(228, 228, 222), 1.0));
    const double halfW = 0.5 * width() / f.scale + spacing;
    const double halfH = 0.5 * height() / f.scale + spacing;
    for (double x = std::floor((wx - halfW) / spacing) * spacing; x < wx + halfW; x += spacing)
      p.drawLine(f.map(x, wy - halfH), f.map(x, wy + halfH));
    for (double y = std::floor((wy - halfH) / spacing) * spacing; y < wy + halfH; y += spacing)
      p.drawLine(f.map(wx - halfW, y), f.map(wx + halfW, y));
  }

  frame_ = f.qt();

  // The navigator's touch map, its plan and its odometry pose.
  touchMapDrawn_ = false;
  const auto* navigator = session_->mode() == SimMode::Autonomous
                              ? dynamic_cast<const nav::Navigator*>(session_->setup().driver.get())
                              : nullptr;
  if (showTouchMap_ && navigator != nullptr && !navigator->touchMap().empty()) {
    const nav::TouchMap& map = navigator->touchMap();
    if (mapOf_ != &map || mapRevision_ != map.revision() || mapImage_.isNull()) {
      mapImage_ = QImage(map.cols(), map.rows(), QImage::Format_ARGB32);
      mapImage_.fill(Qt::transparent);
      QColor closed = closedColour();
      closed.setAlpha(90);
      const QRgb closedRgb = closed.rgba();
      const QRgb touchedRgb = touchedColour().rgba();
      for (int row = 0; row < map.rows(); ++row) {
        auto* line = reinterpret_cast<QRgb*>(mapImage_.scanLine(map.rows() - 1 - row));
        for (int col = 0; col < map.cols(); ++col) {
          if (map.cellTouched(col, row))
            line[col] = touchedRgb;
          else if (map.cellClosed(col, row))
            line[col] = closedRgb;
        }
      }
      mapOf_ = &map;
      mapRevision_ = map.revision();
    }
    const double cell = map.config().cellUnits;
    const sim::Vec2 first = map.cellCentre(0, 0);
    const double x0 = first.x() - 0.5 * cell;
    const double y0 = first.y() - 0.5 * cell;
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    p.drawImage(QRectF(f.map(x0, y0 + map.rows() * cell), f.map(x0 + map.cols() * cell, y0)),
                mapImage_);
    touchMapDrawn_ = true;
  }

  // The robot.
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  const QTransform body = QTransform(c, s, -s, c, pose.x, pose.y) * f.qt();
  QPainterPath outline;
  outline.addRoundedRect(
      QRectF(robot.backX(), -robot.halfWidth(), robot.lengthUnits, robot.widthUnits),
      robot.cornerRadiusUnits, robot.cornerRadiusUnits);
  p.setPen(QPen(QColor(40, 40, 40), 1.5));
  p.setBrush(QColor(255, 255, 255, 220));
  p.drawPath(body.map(outline));
  const auto domes = domePlacements(robot);
  const auto& values = simulator->sensors();
  const double radius = std::max(2.0, robot.domeRadiusUnits * f.scale);
  for (int i = 0; i < kSensorCount; ++i) {
    const DomePlacement& d = domes[static_cast<std::size_t>(i)];
    const double value = values[static_cast<std::size_t>(normalOffset(i))];
    p.setPen(QPen(QColor(70, 70, 70), 1.0));
    p.setBrush(value > 0.0 ? QBrush(valueColor(value, kMaxNormal)) : QBrush(Qt::NoBrush));
    p.drawEllipse(body.map(QPointF(d.centre.x, d.centre.y)), radius, radius);
  }
  const QPointF centre = body.map(QPointF(0.5 * (robot.frontX() + robot.backX()), 0.0));
  const double arrowPx = std::max(30.0, 0.8 * robot.lengthUnits * f.scale);
  drawArrow(p, centre, centre + QPointF(c, -s) * arrowPx, QColor(30, 90, 220), 3.0);
  const QPointF goal = f.map(scene.goal.x(), scene.goal.y());
  const QPointF to = goal - centre;
  const double toLen = std::hypot(to.x(), to.y());
  if (toLen > 1.0) {
    const double len = wholeScene_ ? std::min(toLen, arrowPx) : 0.75 * arrowPx;
    drawArrow(p, centre, centre + to / toLen * len, QColor(210, 40, 40), 3.0);
  }

  // Over the robot: the navigator's plan and where its odometry puts the robot.
  if (touchMapDrawn_) {
    if (const auto& plan = navigator->plan(); plan && !plan->points.empty()) {
      QPolygonF line;
      const Pose2d& odo = navigator->odometry();
      line << f.map(odo.x, odo.y);
      for (const sim::Vec2& pt : plan->points)
        line << f.map(pt.x(), pt.y());
      p.setPen(QPen(planColour(), 2.0, Qt::DashLine, Qt::RoundCap));
      p.setBrush(Qt::NoBrush);
      p.drawPolyline(line);
    }
    // Where the odometry puts the robot: a ring with its heading.
    const Pose2d& odo = navigator->odometry();
    const QPointF at = f.map(odo.x, odo.y);
    const double ring = std::max(4.0, 10.0 * f.scale);
    p.setPen(QPen(planColour(), 2.0));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(at, ring, ring);
    p.drawLine(at, at + QPointF(std::cos(odo.theta), -std::sin(odo.theta)) * 2.0 * ring);
  }

  // The distance at the bottom, as in the thesis's picture.
  QFont font = p.font();
  font.setPointSizeF(font.pointSizeF() * 1.4);
  font.setBold(true);
  p.setFont(font);
  p.setPen(QColor(30, 30, 30));
  p.drawText(QRectF(0, height() - 38, width(), 30), Qt::AlignCenter,
             tr("%1 units to the goal").arg(qRound(session_->goalDistance())));
  p.setFont(this->font());
  if (touchMapDrawn_) {
    // A legend at the top right: touched, closed, plan.
    const QFontMetrics fm(p.font());
    const QString items[3] = {tr("touched"), tr("closed to the plan"), tr("plan, odometry (T)")};
    const QColor colours[3] = {touchedColour(), closedColour(), planColour()};
    double x = width() - 8;
    for (int k = 2; k >= 0; --k) {
      x -= fm.horizontalAdvance(items[k]);
      p.setPen(QColor(70, 70, 70));
      p.drawText(QPointF(x, 19), items[k]);
      x -= 16;
      p.setPen(Qt::NoPen);
      p.setBrush(colours[k]);
      p.drawRect(QRectF(x, 8, 12, 12));
      x -= 14;
    }
  }
  p.setPen(QColor(110, 110, 110));
  p.drawText(QRectF(8, 6, width() - 16, 20), Qt::AlignLeft | Qt::AlignTop,
             wholeScene_ ? tr("Whole scene (M: robot close-up)")
                         : (session_->mayShowScene() ? tr("Robot close-up (M: whole scene)")
                                                     : tr("Robot close-up (scene hidden)")));
}

}  // namespace tactile::gui
