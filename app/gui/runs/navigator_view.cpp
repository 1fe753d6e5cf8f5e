#include "app/gui/runs/navigator_view.h"

#include <QFormLayout>
#include <QHelpEvent>
#include <QLabel>
#include <QListWidget>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "app/gui/common/plot_style.h"
#include "app/gui/runs/navigator_track_model.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"

namespace tactile::gui {
namespace {

constexpr int kRowHeight = 12;
constexpr int kRowGap = 2;
constexpr std::array<SensorGroup, 4> kSideRows{SensorGroup::Front, SensorGroup::Left,
                                               SensorGroup::Right, SensorGroup::Back};

QColor strategyColor(nav::Strategy s) {
  static const std::array<QColor, nav::kStrategyCount> kColors{
      QColor(0x9e, 0x9e, 0x9e),  // Go Straight
      QColor(0x2e, 0x7d, 0x32),  // Head to Destination
      QColor(0xf9, 0xa8, 0x25),  // Check Contact
      QColor(0x15, 0x65, 0xc0),  // Follow Wall
      QColor(0x6a, 0x1b, 0x9a),  // Move through Wall
      QColor(0xc6, 0x28, 0x28),  // Right U Turn
      QColor(0xef, 0x6c, 0x00),  // Left U Turn
  };
  return kColors[static_cast<std::size_t>(s)];
}

QColor statusColor(const nav::ContactStatus& s) {
  switch (s.kind) {
    case nav::StatusKind::Hole:
      return QColor(0x00, 0x96, 0x88);
    case nav::StatusKind::Undecided:
      return QColor(0xff, 0xff, 0xff);
    default:
      return classColor(static_cast<ContactClass>(s.kind));
  }
}

QString strategyText(nav::Strategy s) {
  return QString::fromUtf8(nav::strategyTitle(s).data(),
                           static_cast<int>(nav::strategyTitle(s).size()));
}

QString statusString(const std::optional<nav::ContactStatus>& s) {
  return s ? QString::fromStdString(nav::statusText(*s)) : QStringLiteral("-");
}

}  // namespace

NavigatorStripView::NavigatorStripView(RunSession* session, NavigatorTrackModel* track,
                                       TimelineView* timeline, QWidget* parent)
    : QWidget(parent), session_(session), track_(track), timeline_(timeline) {
  setObjectName(QStringLiteral("navigatorStrips"));
  setMouseTracking(true);
  const auto repaint = [this] { update(); };
  connect(track_, &NavigatorTrackModel::changed, this, [this] {
    setVisible(track_->hasTrack());
    update();
  });
  connect(session_, &RunSession::currentStepChanged, this, repaint);
  connect(timeline_, &TimelineView::visibleRangeChanged, this, repaint);
  setVisible(track_->hasTrack());
}

QSize NavigatorStripView::sizeHint() const {
  return QSize(400, kRows * (kRowHeight + kRowGap) + 4);
}

double NavigatorStripView::xOf(double step) const {
  // The timeline's x of a step, moved into this widget (both sit in one column).
  const StepRange r = timeline_->visibleRange();
  const double x0 = timeline_->stepToX(r.first);
  const double x1 = timeline_->stepToX(r.last);
  const double x = r.last > r.first ? x0 + (step - r.first) * (x1 - x0) / (r.last - r.first) : x0;
  const QPoint shift = mapFromGlobal(timeline_->mapToGlobal(QPoint(0, 0)));
  return x + shift.x();
}

QRect NavigatorStripView::rowRect(int row) const {
  const StepRange r = timeline_->visibleRange();
  const double half =
      r.last > r.first ? 0.5 * (xOf(r.last) - xOf(r.first)) / (r.last - r.first) : 0.5;
  const int left = static_cast<int>(std::floor(xOf(r.first) - half));
  const int right = static_cast<int>(std::ceil(xOf(r.last) + half));
  return QRect(left, 2 + row * (kRowHeight + kRowGap), std::max(1, right - left), kRowHeight);
}

std::int64_t NavigatorStripView::stepAtX(int x) const {
  const StepRange r = timeline_->visibleRange();
  const double x0 = xOf(r.first);
  const double x1 = xOf(r.last);
  if (r.last <= r.first || x1 <= x0) return r.first;
  const double step = r.first + (x - x0) * (r.last - r.first) / (x1 - x0);
  return std::clamp<std::int64_t>(std::llround(step), r.first, r.last);
}

QString NavigatorStripView::textAt(int row, std::int64_t step) const {
  if (row == 0) {
    const auto s = track_->strategyAt(step);
    return s ? strategyText(*s) : QStringLiteral("-");
  }
  if (row == 1) return statusString(track_->integratedAt(step));
  return statusString(track_->groupAt(step, kSideRows[static_cast<std::size_t>(row - 2)]));
}

void NavigatorStripView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().window());
  if (!track_->hasTrack() || !session_->isOpen()) return;
  static const std::array<QString, kRows> kNames{tr("strategy"),      tr("status"),
                                                 QStringLiteral("F"), QStringLiteral("L"),
                                                 QStringLiteral("R"), QStringLiteral("B")};
  for (int row = 0; row < kRows; ++row) {
    const QRect rr = rowRect(row);
    p.setPen(palette().text().color());
    p.drawText(QRect(0, rr.top() - 1, std::max(0, rr.left() - 4), kRowHeight + 2),
               Qt::AlignRight | Qt::AlignVCenter, kNames[static_cast<std::size_t>(row)]);
    // One colour per pixel column: the step at the column's centre.
    for (int x = std::max(0, rr.left()); x < std::min(width(), rr.right() + 1); ++x) {
      const std::int64_t step = stepAtX(x);
      QColor c = palette().base().color();
      if (row == 0) {
        if (const auto s = track_->strategyAt(step)) c = strategyColor(*s);
      } else {
        const auto s = row == 1
                           ? track_->integratedAt(step)
                           : track_->groupAt(step, kSideRows[static_cast<std::size_t>(row - 2)]);
        if (s) c = statusColor(*s);
      }
      p.fillRect(QRect(x, rr.top(), 1, kRowHeight), c);
    }
  }
  // The cursor, as on the timelines.
  const int cx = static_cast<int>(std::lround(xOf(static_cast<double>(session_->currentStep()))));
  p.setPen(QPen(Qt::black, 1));
  p.drawLine(cx, 0, cx, height());
}

void NavigatorStripView::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && track_->hasTrack()) {
    session_->setCurrentStep(stepAtX(static_cast<int>(event->position().x())));
    event->accept();
    return;
  }
  QWidget::mousePressEvent(event);
}

bool NavigatorStripView::event(QEvent* e) {
  if (e->type() == QEvent::ToolTip && track_->hasTrack()) {
    auto* help = static_cast<QHelpEvent*>(e);
    for (int row = 0; row < kRows; ++row) {
      if (rowRect(row).contains(help->pos())) {
        const std::int64_t step = stepAtX(help->pos().x());
        QToolTip::showText(help->globalPos(), tr("step %1: %2").arg(step).arg(textAt(row, step)),
                           this);
        return true;
      }
    }
    QToolTip::hideText();
    return true;
  }
  return QWidget::event(e);
}

NavigatorPanelView::NavigatorPanelView(RunSession* session, NavigatorTrackModel* track,
                                       QWidget* parent)
    : QWidget(parent), session_(session), track_(track) {
  setObjectName(QStringLiteral("navigatorPanel"));
  auto* layout = new QVBoxLayout(this);
  note_ = new QLabel(tr("This run has no navigator columns. Runs written by "
                        "'tactile navigate' have them."),
                     this);
  note_->setWordWrap(true);
  layout->addWidget(note_);
  layout->addWidget(new QLabel(tr("Command set:"), this));
  strategies_ = new QListWidget(this);
  strategies_->setSelectionMode(QAbstractItemView::NoSelection);
  strategies_->setFocusPolicy(Qt::NoFocus);
  for (nav::Strategy s : nav::kStrategies) {
    auto* item = new QListWidgetItem(
        QStringLiteral("%1-%2").arg(static_cast<int>(s) + 1).arg(strategyText(s)), strategies_);
    item->setData(Qt::DecorationRole, strategyColor(s));
  }
  strategies_->setMaximumHeight(strategies_->sizeHintForRow(0) * nav::kStrategyCount + 6);
  layout->addWidget(strategies_);
  auto* form = new QFormLayout();
  mode_ = new QLabel(this);
  form->addRow(tr("Current control mode:"), mode_);
  status_[0] = new QLabel(this);
  form->addRow(tr("Status:"), status_[0]);
  for (const GroupInfo& info : kSensorGroups) {
    auto* label = new QLabel(this);
    status_[1 + static_cast<std::size_t>(groupIndex(info.group))] = label;
    form->addRow(
        tr("Status-%1:")
            .arg(QString::fromUtf8(info.shortName.data(), static_cast<int>(info.shortName.size()))),
        label);
  }
  layout->addLayout(form);
  layout->addStretch(1);
  connect(track_, &NavigatorTrackModel::changed, this, &NavigatorPanelView::refresh);
  connect(session_, &RunSession::currentStepChanged, this, &NavigatorPanelView::refresh);
  refresh();
}

int NavigatorPanelView::markedStrategyRow() const {
  for (int i = 0; i < strategies_->count(); ++i)
    if (strategies_->item(i)->font().bold()) return i;
  return -1;
}

QString NavigatorPanelView::statusText(int index) const {
  return status_[static_cast<std::size_t>(index)]->text();
}

void NavigatorPanelView::refresh() {
  const bool has = track_->hasTrack() && session_->isOpen();
  note_->setVisible(!has);
  const std::int64_t step = session_->currentStep();
  const auto current = has ? track_->strategyAt(step) : std::nullopt;
  for (int i = 0; i < strategies_->count(); ++i) {
    QListWidgetItem* item = strategies_->item(i);
    const bool marked = current && static_cast<int>(*current) == i;
    QFont f = item->font();
    f.setBold(marked);
    item->setFont(f);
    item->setBackground(marked ? palette().highlight() : palette().base());
    item->setForeground(marked ? palette().highlightedText() : palette().text());
  }
  mode_->setText(current ? strategyText(*current) : QStringLiteral("-"));
  status_[0]->setText(has ? statusString(track_->integratedAt(step)) : QStringLiteral("-"));
  for (const GroupInfo& info : kSensorGroups) {
    status_[1 + static_cast<std::size_t>(groupIndex(info.group))]->setText(
        has ? statusString(track_->groupAt(step, info.group)) : QStringLiteral("-"));
  }
}

}  // namespace tactile::gui
