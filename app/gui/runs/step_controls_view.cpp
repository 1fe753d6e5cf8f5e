#include "app/gui/runs/step_controls_view.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QToolButton>

#include <algorithm>
#include <array>
#include <limits>

#include "app/gui/runs/run_session_model.h"

namespace tactile::gui {
namespace {

constexpr std::array<int, 7> kSpeeds{1, 5, 10, 25, 50, 100, 500};
constexpr int kTickMs = 40;

// QSlider and QSpinBox hold an int; a run longer than that is scrubbed in proportion.
int toInt(std::int64_t step) {
  return static_cast<int>(std::min<std::int64_t>(step, std::numeric_limits<int>::max()));
}

}  // namespace

StepControlsView::StepControlsView(RunSession* session, QWidget* parent)
    : QWidget(parent), session_(session) {
  setObjectName(QStringLiteral("stepControls"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 2, 4, 2);
  minus_ = new QToolButton(this);
  minus_->setObjectName(QStringLiteral("stepMinus"));
  minus_->setText(QStringLiteral("-"));
  minus_->setToolTip(tr("Previous step (Left)"));
  minus_->setAutoRepeat(true);
  spin_ = new QSpinBox(this);
  spin_->setObjectName(QStringLiteral("stepSpin"));
  spin_->setToolTip(tr("Current step"));
  spin_->setKeyboardTracking(false);
  spin_->setMinimumWidth(90);
  plus_ = new QToolButton(this);
  plus_->setObjectName(QStringLiteral("stepPlus"));
  plus_->setText(QStringLiteral("+"));
  plus_->setToolTip(tr("Next step (Right)"));
  plus_->setAutoRepeat(true);
  total_ = new QLabel(this);
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setObjectName(QStringLiteral("stepSlider"));
  slider_->setToolTip(tr("Scrub through the run"));
  play_ = new QToolButton(this);
  play_->setObjectName(QStringLiteral("play"));
  play_->setCheckable(true);
  play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  play_->setToolTip(tr("Play or pause (Space)"));
  speed_ = new QComboBox(this);
  speed_->setObjectName(QStringLiteral("playSpeed"));
  speed_->setToolTip(tr("Playing speed"));
  for (int s : kSpeeds)
    speed_->addItem(tr("%1 steps/s").arg(s), s);
  speed_->setCurrentIndex(3);
  layout->addWidget(minus_);
  layout->addWidget(spin_);
  layout->addWidget(plus_);
  layout->addWidget(total_);
  layout->addWidget(slider_, 1);
  layout->addWidget(play_);
  layout->addWidget(speed_);

  timer_ = new QTimer(this);
  timer_->setInterval(kTickMs);
  connect(timer_, &QTimer::timeout, this, &StepControlsView::advance);
  connect(minus_, &QToolButton::clicked, this,
          [this] { session_->setCurrentStep(session_->currentStep() - 1); });
  connect(plus_, &QToolButton::clicked, this,
          [this] { session_->setCurrentStep(session_->currentStep() + 1); });
  connect(spin_, &QSpinBox::valueChanged, this, [this](int v) { session_->setCurrentStep(v); });
  connect(slider_, &QSlider::valueChanged, this, [this](int v) {
    const std::int64_t steps = session_->stepCount();
    if (steps <= slider_->maximum() + 1) {
      session_->setCurrentStep(v);
    } else {
      session_->setCurrentStep(static_cast<std::int64_t>(
          static_cast<double>(v) / slider_->maximum() * static_cast<double>(steps - 1)));
    }
  });
  connect(play_, &QToolButton::toggled, this, &StepControlsView::setPlaying);
  connect(speed_, &QComboBox::currentIndexChanged, this, [this] { emit speedChanged(speed()); });
  connect(session_, &RunSession::runOpened, this, &StepControlsView::syncToRun);
  connect(session_, &RunSession::currentStepChanged, this, &StepControlsView::showStep);
  syncToRun();
}

bool StepControlsView::playing() const {
  return timer_->isActive();
}

int StepControlsView::speed() const {
  return speed_->currentData().toInt();
}

void StepControlsView::setSpeed(int stepsPerSecond) {
  const int i = speed_->findData(stepsPerSecond);
  if (i >= 0) speed_->setCurrentIndex(i);
}

void StepControlsView::setPlaying(bool play) {
  play = play && session_->isOpen();
  if (play && session_->currentStep() >= session_->stepCount() - 1) session_->setCurrentStep(0);
  if (play) {
    carry_ = 0.0;
    timer_->start();
  } else {
    timer_->stop();
  }
  const QSignalBlocker block(play_);
  play_->setChecked(play);
  play_->setIcon(style()->standardIcon(play ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void StepControlsView::advance() {
  carry_ += speed() * kTickMs / 1000.0;
  const auto steps = static_cast<std::int64_t>(carry_);
  carry_ -= static_cast<double>(steps);
  if (steps > 0) session_->setCurrentStep(session_->currentStep() + steps);
  if (session_->currentStep() >= session_->stepCount() - 1) setPlaying(false);
}

void StepControlsView::syncToRun() {
  const bool open = session_->isOpen() && session_->stepCount() > 0;
  setEnabled(open);
  if (!open) setPlaying(false);
  const std::int64_t last = open ? session_->stepCount() - 1 : 0;
  {
    const QSignalBlocker a(spin_);
    const QSignalBlocker b(slider_);
    spin_->setRange(0, toInt(last));
    slider_->setRange(0, std::min(toInt(last), 1'000'000));
  }
  // Counted as the runs list counts: the number of steps. Steps are numbered from 0, so the last
  // one is that number minus one.
  const std::int64_t count = open ? session_->stepCount() : 0;
  total_->setText(tr("of %1 steps").arg(QLocale().toString(static_cast<qlonglong>(count))));
  total_->setToolTip(
      tr("Steps are numbered from 0 to %1").arg(QLocale().toString(static_cast<qlonglong>(last))));
  showStep(session_->currentStep());
}

void StepControlsView::showStep(std::int64_t step) {
  const QSignalBlocker a(spin_);
  const QSignalBlocker b(slider_);
  spin_->setValue(toInt(step));
  const std::int64_t steps = session_->stepCount();
  if (steps <= slider_->maximum() + 1) {
    slider_->setValue(toInt(step));
  } else {
    slider_->setValue(static_cast<int>(static_cast<double>(step) / static_cast<double>(steps - 1) *
                                       slider_->maximum()));
  }
}

}  // namespace tactile::gui
