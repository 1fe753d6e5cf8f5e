#include "app/gui/sim/signal_bars_view.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

#include "app/gui/common/plot_style.h"
#include "app/gui/sim/sim_session.h"
#include "sim/simulator.h"

namespace tactile::gui {

SignalBarsView::SignalBarsView(SimSession* session, QWidget* parent)
    : QWidget(parent), session_(session) {
  setMinimumHeight(120 + legendHeight());
  connect(session_, &SimSession::stepped, this, qOverload<>(&QWidget::update));
}

QRect SignalBarsView::groupRect(SensorGroup group) const {
  // Panel widths follow the dome counts, with a floor so the two-dome corners stay readable.
  constexpr int kGap = 6;
  double weights = 0.0;
  for (const GroupInfo& g : kSensorGroups)
    weights += std::max(3, g.sensorCount);
  const double unit = (width() - kGap * (kGroupCount + 1)) / weights;
  double x = kGap;
  for (const GroupInfo& g : kSensorGroups) {
    const double w = unit * std::max(3, g.sensorCount);
    if (g.group == group)
      return QRect(static_cast<int>(x), 4, static_cast<int>(w), height() - 8 - legendHeight());
    x += w + kGap;
  }
  return {};
}

void SignalBarsView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().window());
  const sim::Simulator* simulator = session_->simulator();
  const QFontMetrics fm(font());
  for (const GroupInfo& g : kSensorGroups) {
    const QRect r = groupRect(g.group);
    p.setPen(QColor(150, 150, 150));
    p.setBrush(Qt::white);
    p.drawRect(r.adjusted(0, 0, -1, -1));
    p.setPen(QColor(30, 30, 30));
    p.drawText(QRect(r.left(), r.bottom() - fm.height() - 2, r.width(), fm.height()),
               Qt::AlignCenter,
               QString::fromUtf8(g.shortName.data(), static_cast<int>(g.shortName.size())));
    const int top = r.top() + 4;
    const int shearHeight = std::max(10, r.height() / 6);
    const int base = r.bottom() - fm.height() - 6 - shearHeight - 4;  // normal bars stand on it
    const int shearMid = base + 4 + shearHeight / 2;
    p.setPen(QColor(200, 200, 200));
    p.drawLine(r.left() + 2, base, r.right() - 2, base);
    p.drawLine(r.left() + 2, shearMid, r.right() - 2, shearMid);
    if (simulator == nullptr) continue;
    const auto& values = simulator->sensors();
    const double slot = (r.width() - 4.0) / g.sensorCount;
    for (int i = 0; i < g.sensorCount; ++i) {
      const int sensor = g.firstSensor + i;
      const double n = values[static_cast<std::size_t>(normalOffset(sensor))];
      const double sh = values[static_cast<std::size_t>(shearOffset(sensor))];
      const double x = r.left() + 2 + i * slot + 0.15 * slot;
      const double w = std::max(1.0, 0.7 * slot);
      if (n > 0.0) {
        const double h = std::min(1.0, n / kMaxNormal) * (base - top);
        p.fillRect(QRectF(x, base - h, w, h), valueColor(n, kMaxNormal));
      }
      if (sh != 0.0) {
        const double h = std::clamp(sh / kMaxShear, -1.0, 1.0) * 0.5 * shearHeight;
        p.fillRect(QRectF(x, shearMid - std::max(h, 0.0), w, std::abs(h)),
                   signedValueColor(sh, kMaxShear));
      }
    }
  }
  drawLegend(p);
}

int SignalBarsView::legendHeight() const {
  return fontMetrics().height() + 6;
}

// The two scales the bars use, under them: normal force 0..5 (sequential) and shear -5..5
// (diverging, neutral at zero).
void SignalBarsView::drawLegend(QPainter& p) const {
  const QFontMetrics fm(font());
  const int y = height() - legendHeight() + 2;
  const int h = fm.height();
  const int half = width() / 2;
  auto scale = [&](int left, int right, const QString& name, const QString& low,
                   const QString& high, bool signedScale) {
    int x = left + 6;
    p.setPen(QColor(30, 30, 30));
    const QString head = name + QLatin1Char(' ') + low;
    p.drawText(QRect(x, y, fm.horizontalAdvance(head) + 2, h), Qt::AlignVCenter, head);
    x += fm.horizontalAdvance(head) + 6;
    const int end = right - fm.horizontalAdvance(high) - 10;
    const int barWidth = std::max(20, end - x);
    for (int i = 0; i < barWidth; ++i) {
      const double t = static_cast<double>(i) / std::max(1, barWidth - 1);
      p.fillRect(QRect(x + i, y + 3, 1, h - 6),
                 signedScale ? signedValueColor(2.0 * t - 1.0, 1.0) : valueColor(t, 1.0));
    }
    p.drawText(QRect(x + barWidth + 4, y, fm.horizontalAdvance(high) + 2, h), Qt::AlignVCenter,
               high);
  };
  scale(0, half, tr("normal"), QStringLiteral("0"), QStringLiteral("5"), false);
  scale(half, width(), tr("shear"), QStringLiteral("-5"), QStringLiteral("+5"), true);
}

}  // namespace tactile::gui
