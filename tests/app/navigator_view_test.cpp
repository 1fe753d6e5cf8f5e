// The workbench's Navigator panel on a stored `navigate` run: at the cursor it marks the strategy
// the run recorded and shows the integrated status and every group's status as recorded.
#include <QtTest>

#include <algorithm>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

#include "app/gui/runs/navigator_track_model.h"
#include "app/gui/runs/navigator_view.h"
#include "app/gui/runs/run_session_model.h"
#include "nav/navigate.h"
#include "sim/scene_source.h"
#include "workspace/workspace.h"

using tactile::GroupInfo;
using tactile::kSensorGroups;
using tactile::RunData;

namespace {

class NavigatorViewTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir dir_;
  std::unique_ptr<tactile::workspace::Workspace> workspace_;
  RunData run_;
  std::size_t columns_ = 0;

  // The recorded text of column `column` (0 strategy, 1 integrated, 2.. groups) at `step`.
  std::string cell(std::int64_t step, std::size_t column) const {
    return run_.extraValues[static_cast<std::size_t>(step) * columns_ + column];
  }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    auto opened = tactile::workspace::Workspace::open(dir_.filePath("nav.db").toStdString());
    QVERIFY2(opened.ok(), opened.ok() ? "" : opened.errorText().c_str());
    workspace_ = std::move(opened.value());
    auto scene = tactile::sim::loadScene("chapter5");
    QVERIFY(scene.ok());
    auto world = std::make_shared<const tactile::sim::World>(std::move(scene.value()));
    tactile::nav::NavigatorConfig config;
    config.source = tactile::nav::StatusSource::Truth;
    tactile::nav::NavigateOptions options;
    options.maxSteps = 700;
    auto r = tactile::nav::navigate(world, "chapter5", tactile::nav::drawStart(world, 5),
                                    world->scene().goal, config, options);
    QVERIFY2(r.ok(), r.ok() ? "" : r.errorText().c_str());
    run_ = std::move(r.value().run);
    columns_ = run_.extraColumns.size();
    QCOMPARE(columns_, std::size_t{2 + tactile::kGroupCount});
    const auto out = workspace_->runStore().importRun(run_, "nav_demo");
    QVERIFY2(out.status == tactile::storage::ImportStatus::Imported, out.message.c_str());
  }

  void panelShowsTheStrategyAndStatusAtTheCursor() {
    tactile::gui::RunSession session;
    session.setWorkspace(workspace_.get());
    tactile::gui::NavigatorTrackModel track(&session);
    tactile::gui::NavigatorPanelView panel(&session, &track);
    QVERIFY(session.open("nav_demo").ok());
    QVERIFY(track.hasTrack());
    QCOMPARE(track.stepCount(), static_cast<std::int64_t>(run_.stepCount()));
    // Steps of at least two different strategies, so a panel stuck on one row fails.
    std::set<std::string> seen;
    int checked = 0;
    const std::int64_t stride = std::max<std::int64_t>(1, session.stepCount() / 40);
    for (std::int64_t step = 0; step < session.stepCount(); ++step) {
      // Every step where the strategy changes, and every stride-th step.
      if (step % stride != 0 && (step == 0 || cell(step, 0) == cell(step - 1, 0))) continue;
      session.setCurrentStep(step);
      const auto recorded = tactile::nav::parseStrategyKey(cell(step, 0));
      QVERIFY(recorded.has_value());
      seen.insert(cell(step, 0));
      QCOMPARE(panel.markedStrategyRow(), static_cast<int>(*recorded));
      QCOMPARE(panel.statusText(0).toStdString(), cell(step, 1));
      for (const GroupInfo& info : kSensorGroups) {
        const std::size_t g = static_cast<std::size_t>(tactile::groupIndex(info.group));
        QCOMPARE(panel.statusText(1 + static_cast<int>(g)).toStdString(), cell(step, 2 + g));
      }
      ++checked;
    }
    QVERIFY(checked > 10);
    QVERIFY2(seen.size() >= 2, "the run used one strategy only");
  }
};

}  // namespace

QTEST_MAIN(NavigatorViewTest)
#include "navigator_view_test.moc"
