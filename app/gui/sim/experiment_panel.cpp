#include "app/gui/sim/experiment_panel.h"

#include <QFont>
#include <QGridLayout>
#include <QLabel>
#include <QListWidget>
#include <QVBoxLayout>

#include "app/gui/common/plot_style.h"
#include "app/gui/sim/sim_session.h"
#include "nav/navigator.h"

namespace tactile::gui {
namespace {

QString text(std::string_view s) {
  return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

}  // namespace

QString ExperimentPanel::strategyTitle(nav::Strategy strategy) {
  switch (strategy) {
    case nav::Strategy::GoStraight:
      return tr("Go Straight");
    case nav::Strategy::HeadToDestination:
      return tr("Head to Destination");
    case nav::Strategy::CheckContact:
      return tr("Check Contact");
    case nav::Strategy::FollowWall:
      return tr("Follow Wall");
    case nav::Strategy::MoveThroughWall:
      return tr("Move through Wall");
    case nav::Strategy::RightUTurn:
      return tr("Right U Turn");
    case nav::Strategy::LeftUTurn:
      return tr("Left U Turn");
  }
  return text(nav::strategyTitle(strategy));
}

QString ExperimentPanel::statusTitle(const nav::ContactStatus& status) {
  switch (status.kind) {
    case nav::StatusKind::NoContact:
      return className(ContactClass::NoContact);
    case nav::StatusKind::Wall:
      return className(ContactClass::Wall);
    case nav::StatusKind::Corner:
      return className(ContactClass::Corner);
    case nav::StatusKind::LeavingWall:
      return className(ContactClass::LeavingWall);
    case nav::StatusKind::DeadPath:
      return className(ContactClass::DeadPath);
    case nav::StatusKind::Hole:
      return tr("Hole, %1 wide").arg(qRound(status.holeWidthUnits));
    case nav::StatusKind::Undecided:
      return tr("Undecided");
  }
  return QString::fromStdString(nav::statusText(status));
}

ExperimentPanel::ExperimentPanel(SimSession* session, QWidget* parent)
    : QWidget(parent), session_(session) {
  setObjectName(QStringLiteral("experimentPanel"));
  strategies_ = new QListWidget;
  strategies_->setObjectName(QStringLiteral("strategyList"));
  strategies_->setFocusPolicy(Qt::NoFocus);
  strategies_->setSelectionMode(QAbstractItemView::NoSelection);
  for (nav::Strategy s : nav::kStrategies)
    strategies_->addItem(strategyTitle(s));
  // Every strategy in view at once: the list never scrolls.
  strategies_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  strategies_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  strategies_->setFixedHeight(strategies_->sizeHintForRow(0) * nav::kStrategyCount +
                              2 * strategies_->frameWidth() + 2);
  auto* grid = new QGridLayout;
  grid->addWidget(new QLabel(tr("Status")), 0, 0);
  status_[0] = new QLabel;
  QFont bold = status_[0]->font();
  bold.setBold(true);
  status_[0]->setFont(bold);
  grid->addWidget(status_[0], 0, 1);
  for (const GroupInfo& g : kSensorGroups) {
    const int i = 1 + static_cast<int>(groupIndex(g.group));
    grid->addWidget(new QLabel(text(g.shortName)), 1 + (i - 1) / 2, 2 * ((i - 1) % 2));
    status_[static_cast<std::size_t>(i)] = new QLabel;
    grid->addWidget(status_[static_cast<std::size_t>(i)], 1 + (i - 1) / 2, 2 * ((i - 1) % 2) + 1);
  }
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel(tr("Strategies")));
  layout->addWidget(strategies_);
  layout->addLayout(grid);
  connect(session_, &SimSession::stepped, this, &ExperimentPanel::refresh);
  connect(session_, &SimSession::started, this, &ExperimentPanel::refresh);
  refresh();
}

const nav::Navigator* ExperimentPanel::navigator() const {
  return dynamic_cast<const nav::Navigator*>(session_->setup().driver.get());
}

void ExperimentPanel::refresh() {
  const nav::Navigator* n = session_->mode() == SimMode::Autonomous ? navigator() : nullptr;
  for (int row = 0; row < strategies_->count(); ++row) {
    QListWidgetItem* item = strategies_->item(row);
    const bool current = n != nullptr && session_->stepCount() > 0 &&
                         nav::kStrategies[static_cast<std::size_t>(row)] == n->strategy();
    QFont f = item->font();
    f.setBold(current);
    item->setFont(f);
    item->setBackground(current ? QColor(255, 214, 120) : QColor(Qt::transparent));
    item->setText((current ? QStringLiteral("\u25b6 ") : QStringLiteral("   ")) +
                  strategyTitle(nav::kStrategies[static_cast<std::size_t>(row)]));
  }
  if (n == nullptr || session_->stepCount() == 0) {
    for (QLabel* l : status_)
      l->setText(QStringLiteral("-"));
    return;
  }
  status_[0]->setText(statusTitle(n->integratedStatus()));
  const auto& groups = n->groupStatus();
  for (std::size_t g = 0; g < groups.size(); ++g)
    status_[1 + g]->setText(statusTitle(groups[g]));
}

int ExperimentPanel::markedStrategyRow() const {
  for (int row = 0; row < strategies_->count(); ++row) {
    if (strategies_->item(row)->font().bold()) return row;
  }
  return -1;
}

QString ExperimentPanel::statusText(int index) const {
  if (index < 0 || index >= static_cast<int>(status_.size())) return {};
  return status_[static_cast<std::size_t>(index)]->text();
}

}  // namespace tactile::gui
