// The route view driven with real mouse, wheel and key events on the offscreen platform.
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include "app/gui/common/plot_style.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/runs/route_view.h"
#include "app/gui/runs/run_session_model.h"
#include "gui_fixture.h"

using tactile::ContactClass;
using tactile::SensorGroup;
using tactile::gui::LabelModel;
using tactile::gui::RouteView;
using tactile::gui::RunSession;

namespace {

double distance(QPointF a, QPointF b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

// A fixture run opened in a session with its labels, and a 1000 x 800 view of it.
struct OpenRun {
  tactile::gui::testing::GuiFixture fx;
  RunSession session;
  LabelModel labels;
  std::unique_ptr<RouteView> view;

  OpenRun() {
    session.setWorkspace(fx.workspace.get());
    labels.setWorkspace(fx.workspace.get());
  }
  bool open(const std::string& name) {
    if (!session.open(name).ok()) return false;
    labels.setRun(session.info().id, session.info().name, session.stepCount());
    view = std::make_unique<RouteView>(&session, &labels);
    view->resize(1000, 800);
    return true;
  }
  // The step nearest to a widget point, by brute force over every step.
  double nearestDistance(QPointF at) const {
    double best = std::numeric_limits<double>::infinity();
    for (std::int64_t i = 0; i < session.stepCount(); ++i) {
      best = std::min(best, distance(view->stepToWidget(i), at));
    }
    return best;
  }
};

void sendWheel(QWidget* w, QPointF at, int angle) {
  QWheelEvent event(at, w->mapToGlobal(at), QPoint(), QPoint(0, angle), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(w, &event);
}

// The pixel a point lies on (not the nearest pixel corner, which toPoint() would give).
QColor pixelAt(const QImage& image, QPointF at) {
  return image.pixelColor(int(std::floor(at.x())), int(std::floor(at.y())));
}

bool isBackground(const QColor& c) {
  return c == QColor(Qt::white) || c == QColor(226, 226, 226);
}

}  // namespace

class RouteViewTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { QLocale::setDefault(QLocale::c()); }

  void clickMovesCursorToNearestStep() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    r.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(r.view.get()));
    const std::int64_t n = r.session.stepCount();
    for (const std::int64_t k : {std::int64_t{40}, n / 3, n / 2, n - 1}) {
      r.session.setCurrentStep(k < n / 2 ? n - 1 : 0);
      const QPoint click = r.view->stepToWidget(k).toPoint();
      QTest::mouseClick(r.view.get(), Qt::LeftButton, Qt::NoModifier, click);
      const std::int64_t got = r.session.currentStep();
      const double gotDistance = distance(r.view->stepToWidget(got), click);
      QVERIFY2(gotDistance <= 0.75, qPrintable(QStringLiteral("step %1 for %2").arg(got).arg(k)));
      QVERIFY(gotDistance <= r.nearestDistance(click) + 1e-9);
    }
  }

  void clickFarFromRouteKeepsCursor() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    r.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(r.view.get()));
    QPoint empty(-1, -1);
    for (int y = 40; y < 760 && empty.x() < 0; y += 20) {
      for (int x = 40; x < 960; x += 20) {
        if (r.nearestDistance(QPointF(x, y)) > 30.0) {
          empty = QPoint(x, y);
          break;
        }
      }
    }
    QVERIFY(empty.x() >= 0);
    r.session.setCurrentStep(123);
    QVERIFY(!r.view->stepAt(empty).has_value());
    QTest::mouseClick(r.view.get(), Qt::LeftButton, Qt::NoModifier, empty);
    QCOMPARE(r.session.currentStep(), std::int64_t{123});
  }

  void dragPansInsteadOfSeeking() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    r.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(r.view.get()));
    r.session.setCurrentStep(5);
    const std::int64_t k = r.session.stepCount() / 2;
    const QPointF before = r.view->stepToWidget(k);
    const QPoint from = before.toPoint();
    QTest::mousePress(r.view.get(), Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(r.view.get(), from + QPoint(30, 20));
    QTest::mouseRelease(r.view.get(), Qt::LeftButton, Qt::NoModifier, from + QPoint(30, 20));
    QCOMPARE(r.session.currentStep(), std::int64_t{5});
    QVERIFY(distance(r.view->stepToWidget(k), before + QPointF(30, 20)) < 1e-6);
    QTest::keyClick(r.view.get(), Qt::Key_Home);
    QVERIFY(distance(r.view->stepToWidget(k), before) < 1e-6);
  }

  void keyMTogglesCloseUp() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    const std::int64_t n = r.session.stepCount();
    r.session.setCurrentStep(n / 2);
    QSignalSpy spy(r.view.get(), &RouteView::viewSettingsChanged);
    QVERIFY(r.view->wholeScene());
    const QPointF a = r.view->stepToWidget(n / 2);
    const QPointF b = r.view->stepToWidget(n / 2 + 40);
    QTest::keyClick(r.view.get(), Qt::Key_M);
    QVERIFY(!r.view->wholeScene());
    QCOMPARE(spy.count(), 1);
    // The close-up is centred on the robot and larger: room1 is 1600 units wide, it shows ~400.
    QVERIFY(distance(r.view->stepToWidget(n / 2), QPointF(500, 400)) < 1e-6);
    const double ratio =
        distance(r.view->stepToWidget(n / 2), r.view->stepToWidget(n / 2 + 40)) / distance(a, b);
    QVERIFY2(ratio > 2.5, qPrintable(QString::number(ratio)));
    QTest::keyClick(r.view.get(), Qt::Key_M);
    QVERIFY(r.view->wholeScene());
    QCOMPARE(spy.count(), 2);
    QVERIFY(distance(r.view->stepToWidget(n / 2), a) < 1e-6);
  }

  void wheelZoomsAboutPointer() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    const std::int64_t n = r.session.stepCount();
    for (const bool whole : {true, false}) {
      r.view->setWholeScene(whole);
      const QPointF pointer = r.view->stepToWidget(n / 4);
      const double span = distance(r.view->stepToWidget(0), r.view->stepToWidget(n - 1));
      sendWheel(r.view.get(), pointer, 240);
      QVERIFY(distance(r.view->stepToWidget(n / 4), pointer) < 1.0);
      const double zoomedIn = distance(r.view->stepToWidget(0), r.view->stepToWidget(n - 1));
      QVERIFY2(std::abs(zoomedIn / span - std::sqrt(2.0)) < 1e-6,
               qPrintable(QString::number(zoomedIn / span)));
      sendWheel(r.view.get(), pointer, -480);
      QVERIFY(distance(r.view->stepToWidget(n / 4), pointer) < 1.0);
      const double zoomedOut = distance(r.view->stepToWidget(0), r.view->stepToWidget(n - 1));
      QVERIFY(std::abs(zoomedOut / span - std::sqrt(0.5)) < 1e-6);
    }
  }

  // Regression: the "Whole scene" badge stayed while the view was zoomed in.
  void badgeSaysWhenZoomed() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    QVERIFY(r.view->badgeText().startsWith(QStringLiteral("Whole scene")));
    sendWheel(r.view.get(), QPointF(300, 300), 480);
    QVERIFY2(r.view->badgeText().startsWith(QStringLiteral("Zoomed 2.0x")),
             qPrintable(r.view->badgeText()));
    QTest::mouseDClick(r.view.get(), Qt::LeftButton, {}, QPoint(300, 300));
    QVERIFY(r.view->badgeText().startsWith(QStringLiteral("Whole scene")));
    r.view->setWholeScene(false);
    QVERIFY(r.view->badgeText().startsWith(QStringLiteral("Close-up (")));
    sendWheel(r.view.get(), QPointF(300, 300), -480);
    QVERIFY(r.view->badgeText().startsWith(QStringLiteral("Close-up zoomed 0.5x")));
  }

  void settingsRoundTrip() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    {
      QSettings settings(dir.filePath(QStringLiteral("view.ini")), QSettings::IniFormat);
      r.view->setColourMode(RouteView::ColourMode::Label);
      r.view->setWholeScene(false);
      r.view->saveSettings(settings);
    }
    QSettings settings(dir.filePath(QStringLiteral("view.ini")), QSettings::IniFormat);
    QCOMPARE(settings.value(QStringLiteral("routeView/wholeScene")).toBool(), false);
    RouteView other(&r.session, &r.labels);
    QCOMPARE(other.colourMode(), RouteView::ColourMode::Time);
    QVERIFY(other.wholeScene());
    QSignalSpy spy(&other, &RouteView::viewSettingsChanged);
    other.restoreSettings(settings);
    QCOMPARE(other.colourMode(), RouteView::ColourMode::Label);
    QVERIFY(!other.wholeScene());
    QCOMPARE(spy.count(), 2);
  }

  void longStraightRunIsDecimated() {
    OpenRun r;
    constexpr std::size_t kSteps = 100000;
    tactile::RunData run;
    run.metadata = {{"format", "tactile-run 1"}, {"dt", "0.1"}};
    run.reserve(kSteps, false);
    const std::array<double, tactile::kValuesPerStep> values{};
    for (std::size_t i = 0; i < kSteps; ++i) {
      const double t = static_cast<double>(i) * 0.05;
      run.appendStep(t, 0.6 * t, std::atan2(0.6, 1.0), 1.0, 0.0, false, values.data(), nullptr);
    }
    const auto outcome = r.fx.workspace->runStore().importRun(run, "straight");
    QCOMPARE(int(outcome.status), int(tactile::storage::ImportStatus::Imported));
    QVERIFY(r.open("straight"));
    const auto n = static_cast<std::int64_t>(kSteps);
    r.session.setCurrentStep(n / 4);  // the robot is drawn away from the points checked below
    const int points = r.view->drawnRoutePoints();
    QVERIFY2(points > 100 && points < 4000, qPrintable(QString::number(points)));
    const QImage image = r.view->grab().toImage();
    for (const std::int64_t k : {std::int64_t{0}, n / 2, n - 1}) {
      const QPointF at = r.view->stepToWidget(k);
      QVERIFY(QRectF(r.view->rect()).contains(at));
      QVERIFY2(!isBackground(pixelAt(image, at)), qPrintable(QString::number(k)));
    }
    // Off the line is background, so the checks above do not pass on any image.
    const QPointF off = r.view->stepToWidget(n / 2) + QPointF(30, 50);
    QVERIFY(isBackground(pixelAt(image, off)));
    // The search refines inside a pixel run: the exact step under a click, not its run's ends.
    const auto hit = r.view->stepAt(r.view->stepToWidget(n / 2 + 7));
    QVERIFY(hit.has_value());
    QVERIFY(distance(r.view->stepToWidget(*hit), r.view->stepToWidget(n / 2 + 7)) < 1e-9);
  }

  void labelModeColoursByClassAndFollowsEdits() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    QVERIFY(r.labels.createSet("mine").ok());
    const std::int64_t n = r.session.stepCount();
    QVERIFY(r.labels.label({SensorGroup::Front}, 0, n - 1, ContactClass::Wall).ok());
    r.session.setSelectedGroup(SensorGroup::Front);
    r.session.setCurrentStep(0);
    r.view->setColourMode(RouteView::ColourMode::Label);
    const std::int64_t k = n / 2;  // far from the robot at step 0 and the goal marker
    QCOMPARE(pixelAt(r.view->grab().toImage(), r.view->stepToWidget(k)),
             tactile::gui::classColor(ContactClass::Wall));
    QVERIFY(r.labels.label({SensorGroup::Front}, k - 5, k + 5, ContactClass::Corner).ok());
    QCOMPARE(pixelAt(r.view->grab().toImage(), r.view->stepToWidget(k)),
             tactile::gui::classColor(ContactClass::Corner));
    // Another group has no labels: its route is grey.
    r.session.setSelectedGroup(SensorGroup::Back);
    QCOMPARE(pixelAt(r.view->grab().toImage(), r.view->stepToWidget(k)), QColor(150, 150, 150));
  }

  void screenshotsOfBothModes() {
    OpenRun r;
    QVERIFY(r.open(r.fx.runName));
    // A step where domes touch, so the picture shows filled domes.
    std::int64_t touching = -1;
    for (std::int64_t i = 0; i < r.session.stepCount() && touching < 0; i += 5) {
      r.session.setCurrentStep(i);
      for (int s = 0; s < tactile::kSensorCount; ++s) {
        if (r.session.currentSensors()[tactile::normalOffset(s)] > 0.0) touching = i;
      }
    }
    QVERIFY(touching >= 0);
    r.session.setCurrentStep(touching);
    r.session.setSelectedGroup(tactile::groupOfSensor(0));
    const QImage whole = r.view->grab().toImage();
    QVERIFY(whole.save(QStringLiteral("/tmp/route_whole.png")));
    r.view->setWholeScene(false);
    const QImage closeUp = r.view->grab().toImage();
    QVERIFY(closeUp.save(QStringLiteral("/tmp/route_closeup.png")));
    QCOMPARE(whole.size(), QSize(1000, 800));
    QVERIFY(whole != closeUp);
  }
};

QTEST_MAIN(RouteViewTest)
#include "route_view_test.moc"
