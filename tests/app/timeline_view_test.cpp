// The timeline view on a simulated 600-step run: clicks seek and pick groups, drags select,
// the wheel zooms about the pointer, label strips show the classes and their edges drag, the
// settings round trip, and a hidden view bins nothing until shown.
#include <qcustomplot.h>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

#include <cmath>
#include <memory>

#include "app/gui/common/plot_style.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"
#include "gui_fixture.h"

using tactile::ContactClass;
using tactile::SensorGroup;
using tactile::gui::StepRange;
using tactile::gui::TimelineView;

namespace {

void settle() {
  for (int i = 0; i < 3; ++i)
    QTest::qWait(10);
}

bool near(QColor a, QColor b, int tolerance = 8) {
  return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
         std::abs(a.blue() - b.blue()) <= tolerance;
}

// A run opened in a session, a label set on it, and the view shown at 1200x700.
struct Bench {
  tactile::gui::testing::GuiFixture fx;
  tactile::gui::RunSession session;
  tactile::gui::LabelModel labels;
  std::unique_ptr<TimelineView> view;

  explicit Bench(bool show = true, QSize size = {1200, 700}) {
    session.setWorkspace(fx.workspace.get());
    if (!session.open(fx.runName)) throw std::runtime_error("run does not open");
    labels.setWorkspace(fx.workspace.get());
    if (!labels.createSet("test")) throw std::runtime_error("no label set");
    labels.setRun(session.info().id, session.info().name, session.stepCount());
    view = std::make_unique<TimelineView>(&session, &labels);
    view->resize(size);
    if (!show) return;
    view->show();
    if (!QTest::qWaitForWindowExposed(view.get())) throw std::runtime_error("not exposed");
    settle();
  }
  QPoint at(std::int64_t step, int y) const {
    return view->plot()->mapFrom(view.get(), QPoint(int(std::lround(view->stepToX(step))), y));
  }
  void click(std::int64_t step, int y, Qt::KeyboardModifiers mods = {}) {
    QTest::mouseClick(view->plot(), Qt::LeftButton, mods, at(step, y));
  }
  void drag(std::int64_t from, std::int64_t to, int y) {
    QTest::mousePress(view->plot(), Qt::LeftButton, {}, at(from, y));
    QTest::mouseMove(view->plot(), at((from + to) / 2, y));
    QTest::mouseMove(view->plot(), at(to, y));
    QTest::mouseRelease(view->plot(), Qt::LeftButton, {}, at(to, y));
  }
  void wheel(std::int64_t step, int notches) {
    const QPointF pos = at(step, view->heatmapRect().center().y());
    QWheelEvent event(pos, view->plot()->mapToGlobal(pos), QPoint(), QPoint(0, 120 * notches),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(view->plot(), &event);
  }
  QColor pixel(std::int64_t step, int y) {
    settle();
    return view->grab().toImage().pixelColor(int(std::lround(view->stepToX(step))), y);
  }
};

}  // namespace

class TimelineViewTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { QLocale::setDefault(QLocale::c()); }

  void clickSeeksToTheStepUnderThePointer() {
    Bench b;
    QCOMPARE(b.view->visibleRange(), (StepRange{0, 599}));
    const int y = b.view->headingRect().center().y();
    for (std::int64_t k : {300, 0, 599, 17}) {
      b.click(k, y);
      QCOMPARE(b.session.currentStep(), k);
    }
    b.view->setVisibleRange({100, 160});  // wide steps: a click anywhere in one lands on it
    for (std::int64_t k : {130, 100, 160}) {
      b.click(k, y);
      QCOMPARE(b.session.currentStep(), k);
    }
  }

  void clickInTheHeatmapSelectsTheSensorsGroup() {
    Bench b;
    QCOMPARE(b.session.selectedGroup(), SensorGroup::Front);
    const QRect heat = b.view->heatmapRect();
    auto rowY = [&](int sensor) { return int(heat.top() + (sensor + 0.5) * heat.height() / 44.0); };
    b.click(250, rowY(14));  // sensors 10..19 are the left side
    QCOMPARE(b.session.selectedGroup(), SensorGroup::Left);
    QCOMPARE(b.session.currentStep(), 250);
    b.click(260, rowY(43));
    QCOMPARE(b.session.selectedGroup(), SensorGroup::FrontRightCorner);
  }

  void dragSelectsAnOrderedRange() {
    Bench b;
    const int y = b.view->headingRect().center().y();
    b.drag(200, 300, y);
    QVERIFY(b.session.selection().has_value());
    QCOMPARE(*b.session.selection(), (StepRange{200, 300}));
    QCOMPARE(b.session.currentStep(), 0);  // a drag selects, it does not seek
    b.drag(400, 350, y);
    QCOMPARE(*b.session.selection(), (StepRange{350, 400}));
    b.click(100, y);
    b.click(150, y, Qt::ShiftModifier);  // extends from the cursor
    QCOMPARE(*b.session.selection(), (StepRange{100, 150}));
    QCOMPARE(b.session.currentStep(), 100);
  }

  void wheelZoomsAboutThePointer() {
    Bench b;
    QSignalSpy changed(b.view.get(), &TimelineView::visibleRangeChanged);
    const double x = b.view->stepToX(450);
    b.wheel(450, 1);
    const StepRange r = b.view->visibleRange();
    QVERIFY(r.size() < 600);
    QVERIFY(r.contains(450));
    QVERIFY(std::abs(b.view->stepToX(450) - x) < 3.0);  // the step stays under the pointer
    QCOMPARE(changed.count(), 1);
    for (int i = 0; i < 40; ++i)
      b.wheel(450, 1);
    QCOMPARE(b.view->visibleRange().size(), 20);  // never narrower
    QVERIFY(b.view->visibleRange().contains(450));
    for (int i = 0; i < 40; ++i)
      b.wheel(450, -1);
    QCOMPARE(b.view->visibleRange(), (StepRange{0, 599}));  // never wider than the run
    b.view->setVisibleRange({10, 90});
    b.view->showWholeRun();
    QCOMPARE(b.view->visibleRange(), (StepRange{0, 599}));
  }

  void cursorOutsideTheVisibleRangePansKeepingTheZoom() {
    Bench b;
    b.view->setVisibleRange({0, 99});
    b.session.setCurrentStep(400);
    QCOMPARE(b.view->visibleRange().size(), 100);
    QVERIFY(b.view->visibleRange().contains(400));
  }

  void labelStripShowsTheClassAndItsEdgeDrags() {
    Bench b;
    QVERIFY(b.labels.label({SensorGroup::Left}, 100, 199, ContactClass::Wall));
    const int y = b.view->labelStripRect(SensorGroup::Left).center().y();
    QVERIFY(near(b.pixel(150, y), tactile::gui::classColor(ContactClass::Wall)));
    QVERIFY(!near(b.pixel(300, y), tactile::gui::classColor(ContactClass::Wall)));
    const int frontY = b.view->labelStripRect(SensorGroup::Front).center().y();
    QVERIFY(!near(b.pixel(150, frontY), tactile::gui::classColor(ContactClass::Wall)));

    b.drag(199, 249, y);
    const auto& segs = b.labels.segments(SensorGroup::Left);
    QCOMPARE(segs.size(), std::size_t{1});
    QCOMPARE(segs[0].firstStep, 100);
    QVERIFY(std::abs(segs[0].lastStep - 249) <= 1);
    QVERIFY(near(b.pixel(230, y), tactile::gui::classColor(ContactClass::Wall)));
    b.drag(100, 80, y);  // the left edge too
    QCOMPARE(b.labels.segments(SensorGroup::Left)[0].firstStep, 80);
  }

  void aSegmentNarrowerThanAPixelStillShows() {
    Bench b(true, {400, 700});  // about 0.5 px a step
    QVERIFY(b.labels.label({SensorGroup::Right}, 301, 301, ContactClass::DeadPath));
    const int y = b.view->labelStripRect(SensorGroup::Right).center().y();
    QVERIFY(near(b.pixel(301, y), tactile::gui::classColor(ContactClass::DeadPath)));
  }

  void settingsRoundTrip() {
    Bench b;
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("t.ini")), QSettings::IniFormat);
    b.view->setChannel(TimelineView::Channel::Shear);
    b.view->setVisibleRange({50, 150});
    b.view->saveSettings(settings);
    settings.sync();

    TimelineView same(&b.session, &b.labels);
    QCOMPARE(same.channel(), TimelineView::Channel::Normal);
    same.restoreSettings(settings);
    QCOMPARE(same.channel(), TimelineView::Channel::Shear);
    QCOMPARE(same.visibleRange(), (StepRange{50, 150}));

    // Restored before the run opens, the range waits for it.
    tactile::gui::RunSession later;
    later.setWorkspace(b.fx.workspace.get());
    TimelineView early(&later, nullptr);
    early.restoreSettings(settings);
    QVERIFY(later.open(b.fx.runName));
    QCOMPARE(early.visibleRange(), (StepRange{50, 150}));
  }

  void hiddenViewBinsNothingUntilShown() {
    Bench b(false);
    auto* heat = qobject_cast<QCPColorMap*>(b.view->plot()->plottable(0));
    QVERIFY(heat != nullptr);
    b.view->setVisibleRange({100, 200});
    QVERIFY(heat->data()->isEmpty());
    b.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(b.view.get()));
    settle();
    QVERIFY(!heat->data()->isEmpty());
    QVERIFY(std::abs(heat->data()->keyRange().lower - 100) < 1.0);
    QVERIFY(std::abs(heat->data()->keyRange().upper - 200) < 1.0);
  }

  // The row-height preference gives every label row that many pixels.
  void rowHeightSetsTheLabelRows() {
    Bench b(true, {1200, 900});
    for (int h : {12, 26}) {
      b.view->setRowHeight(h);
      settle();
      QCOMPARE(b.view->rowHeight(), h);
      for (SensorGroup g : {SensorGroup::Front, SensorGroup::FrontRightCorner})
        QVERIFY2(std::abs(b.view->labelStripRect(g).height() - h) <= 1,
                 qPrintable(QString::number(b.view->labelStripRect(g).height())));
    }
  }

  // Regression: the selection was shaded in the grey of NoContact, and the selected group was not
  // marked.
  void selectionAndSelectedGroupStandOut() {
    Bench b;
    QVERIFY(b.labels.label({SensorGroup::Front}, 100, 400, ContactClass::NoContact));
    b.session.setSelection(200, 300);
    b.session.setSelectedGroup(SensorGroup::Back);
    const QRect front = b.view->labelStripRect(SensorGroup::Front);
    const QColor grey = tactile::gui::classColor(ContactClass::NoContact);
    QVERIFY(near(b.pixel(150, front.center().y()), grey));
    const QColor selected = b.pixel(250, front.center().y());
    QVERIFY2(!near(selected, grey, 20),
             qPrintable(selected.name()));             // not a shade of the class's grey
    QVERIFY(selected.blue() > selected.green() + 20);  // violet
    // The selected group's rows are outlined in black; another group's are not.
    auto darkest = [&](SensorGroup g) {
      const QImage image = b.view->grab().toImage();
      const int top = b.view->labelStripRect(g).top();
      const int x = int(std::lround(b.view->stepToX(50)));
      int best = 255;
      for (int y = top - 2; y <= top + 1; ++y)
        best = std::min(best, qGray(image.pixel(x, y)));
      return best;
    };
    settle();
    QVERIFY(darkest(SensorGroup::Back) < 60);
    QVERIFY(darkest(SensorGroup::Right) > 100);
  }

  // Hovering tells the value under the pointer: the sensor's value in the heatmap, the heading and
  // the command of the step in their strips.
  void hoverTellsTheValues() {
    Bench b;
    b.view->setVisibleRange({0, 99});  // more than a pixel per step: a column is one step
    settle();
    // The step with the largest normal value among the first hundred, and its sensor.
    std::int64_t step = 0;
    int sensor = 0;
    double value = -1;
    for (std::int64_t k = 0; k < 100; ++k) {
      b.session.setCurrentStep(k);
      for (int s = 0; s < tactile::kSensorCount; ++s) {
        const double n = b.session.currentSensors()[std::size_t(2 * s)];
        if (n > value) {
          value = n;
          step = k;
          sensor = s;
        }
      }
    }
    const QRect heat = b.view->heatmapRect();
    const double rowHeight = heat.height() / double(tactile::kSensorCount);
    const QPoint at(int(std::lround(b.view->stepToX(step))),
                    int(heat.top() + (sensor + 0.5) * rowHeight));
    const QString tip = b.view->trackTipAt(at);
    QVERIFY2(tip.contains(QStringLiteral("step %1,").arg(step)) &&
                 tip.contains(QStringLiteral("sensor %1 ").arg(sensor)) &&
                 tip.contains(QStringLiteral("normal %1").arg(value, 0, 'f', 2)),
             qPrintable(tip + QStringLiteral(" / want %1 %2 %3").arg(step).arg(sensor).arg(value)));
    const double theta = b.session.track().theta[std::size_t(step)];
    const QString head = b.view->trackTipAt(QPoint(at.x(), b.view->headingRect().center().y()));
    QVERIFY2(head.contains(QStringLiteral("heading %1").arg(theta * 180.0 / M_PI, 0, 'f', 1)),
             qPrintable(head));
    QVERIFY(
        b.view->trackTipAt(QPoint(at.x(), b.view->labelStripRect(SensorGroup::Front).center().y()))
            .isEmpty());
  }

  void screenshotShowsHeadingCursorAndLabels() {
    Bench b;
    QVERIFY(b.labels.label({SensorGroup::Front, SensorGroup::Left}, 40, 180, ContactClass::Wall));
    QVERIFY(b.labels.label({SensorGroup::Left}, 181, 230, ContactClass::Corner));
    QVERIFY(b.labels.label({SensorGroup::Right}, 300, 420, ContactClass::LeavingWall));
    b.session.setSelection(260, 330);
    b.session.setCurrentStep(250);
    settle();
    const QImage image = b.view->grab().toImage();
    QVERIFY(image.save(QStringLiteral("/tmp/timeline.png")));
    QCOMPARE(image.size(), QSize(1200, 700));
    const int headY = b.view->headingRect().center().y();
    const int x = int(std::lround(b.view->stepToX(250)));
    QVERIFY(near(image.pixelColor(x, headY), QColor(20, 20, 20), 30));  // the cursor
    for (std::int64_t k : {20, 120, 480}) {
      const QColor want = tactile::gui::headingColor(b.session.track().theta[std::size_t(k)]);
      QVERIFY(near(image.pixelColor(int(std::lround(b.view->stepToX(k))), headY), want));
    }
  }
};

QTEST_MAIN(TimelineViewTest)
#include "timeline_view_test.moc"
