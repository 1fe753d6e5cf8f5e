// Two annotators' workbenches on one database: an edit over steps the other changed since it was
// loaded is refused and the stretch reloaded; the other's edits arrive by polling; the History
// dock lists every edit. A workbench whose server connection is cut says so and reconnects.
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include "app/gui/labels/history_view.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/run_list_model.h"
#include "app/gui/runs/run_list_view.h"
#include "app/gui/runs/run_session_model.h"
#include "gui_fixture.h"

#include <libpq-fe.h>
#include <unistd.h>

#include <QStatusBar>

#include <cstdlib>
#include <fstream>

using tactile::ContactClass;
using tactile::SensorGroup;
using tactile::gui::HistoryView;
using tactile::gui::LabelModel;
using tactile::gui::RunSession;
using tactile::gui::testing::GuiFixture;

class TeamLabelsTest : public QObject {
  Q_OBJECT

 private slots:
  void twoAnnotatorsNeverLoseAnEdit() {
    GuiFixture fx(300);
    auto second = tactile::workspace::Workspace::open(fx.dbPath);
    QVERIFY(second.ok());
    RunSession sessionA, sessionB;
    LabelModel anna, ben;
    anna.setAnnotator("anna");
    ben.setAnnotator("ben");
    sessionA.setWorkspace(fx.workspace.get());
    sessionB.setWorkspace(second.value().get());
    QVERIFY(sessionA.open(fx.runName).ok());
    QVERIFY(sessionB.open(fx.runName).ok());
    anna.setWorkspace(fx.workspace.get());
    ben.setWorkspace(second.value().get());
    QVERIFY(anna.createSet("team").ok());
    QVERIFY(ben.openSet("team").ok());
    anna.setRun(sessionA.info().id, sessionA.info().name, sessionA.stepCount());
    ben.setRun(sessionB.info().id, sessionB.info().name, sessionB.stepCount());
    HistoryView history(&sessionA, &anna);
    QCOMPARE(history.rowCount(), 0);

    // Anna labels; Ben, who loaded before, labels over her steps: refused, told who, reloaded.
    QVERIFY(anna.label({SensorGroup::Left}, 10, 50, ContactClass::Wall).ok());
    QCOMPARE(history.rowCount(), 1);
    QSignalSpy benErrors(&ben, &LabelModel::errorOccurred);
    const auto refused = ben.label({SensorGroup::Left}, 40, 60, ContactClass::Corner);
    QVERIFY(!refused.ok());
    QVERIFY(tactile::storage::isLabelConflict(refused.error()));
    QVERIFY(QString::fromStdString(refused.error().message).contains("anna"));
    QCOMPARE(benErrors.count(), 1);
    QCOMPARE(*ben.classAt(SensorGroup::Left, 45), ContactClass::Wall);  // her edit, reloaded
    // Now that he has seen it, his edit stands; so does one over other steps.
    QVERIFY(ben.label({SensorGroup::Left}, 40, 60, ContactClass::Corner).ok());
    QVERIFY(ben.label({SensorGroup::Right}, 100, 110, ContactClass::Wall).ok());

    // Anna's workbench learns of Ben's edits by polling (as its timer does).
    QSignalSpy arrived(&anna, &LabelModel::changedElsewhere);
    for (int i = 0; i < 20 && arrived.isEmpty(); ++i) {
      anna.pollChanges();
      if (arrived.isEmpty()) QTest::qWait(50);
    }
    QCOMPARE(arrived.count(), 1);
    QVERIFY(arrived.front().front().toString().contains("ben changed L steps 40-60"));
    QCOMPARE(*anna.classAt(SensorGroup::Left, 45), ContactClass::Corner);
    QCOMPARE(*anna.classAt(SensorGroup::Right, 105), ContactClass::Wall);
    QCOMPARE(history.rowCount(), 3);
    QCOMPARE(anna.seenRevision(), ben.seenRevision());

    // Anna's undo of her own edit would overwrite Ben's steps 40-50: refused, nothing lost.
    anna.undoStack()->undo();
    QCOMPARE(*anna.classAt(SensorGroup::Left, 45), ContactClass::Corner);
    // An undo that touches only her own steps stands: her next edit, then its undo.
    anna.undoStack()->redo();
    QVERIFY(anna.label({SensorGroup::Front}, 200, 220, ContactClass::DeadPath).ok());
    anna.undoStack()->undo();
    QVERIFY(!anna.classAt(SensorGroup::Front, 210).has_value());
    QCOMPARE(history.rowCount(), 5);
  }

  void labelFromModelWritesTheDecisionAsOneUndoableEdit() {
    GuiFixture fx(400);
    auto run = fx.workspace->runStore().find(fx.runName);
    QVERIFY(run.ok());
    QVERIFY(fx.workspace->labelStore().autolabel(run->id, "truth").ok());
    tactile::workspace::TrainRequest request;
    request.labelSet = "truth";
    request.modelName = "m";
    tactile::analysis::TrainSettings quick;
    quick.classifier.gmm.components = 1;
    quick.classifier.gmm.varianceFloor = 0.01;
    request.settings = tactile::analysis::GroupSettings::same(quick);
    auto trained = fx.workspace->train(request);
    QVERIFY2(trained.ok(), trained.ok() ? "" : trained.errorText().c_str());
    RunSession session;
    LabelModel labels;
    labels.setAnnotator("anna");
    session.setWorkspace(fx.workspace.get());
    QVERIFY(session.open(fx.runName).ok());
    labels.setWorkspace(fx.workspace.get());
    QVERIFY(labels.createSet("mine").ok());
    labels.setRun(session.info().id, session.info().name, session.stepCount());
    QVERIFY(labels.label({SensorGroup::Right}, 0, 399, ContactClass::Wall).ok());
    std::array<std::string, tactile::kGroupCount> models;
    models.fill("m");
    // The right side and another group the model covers (a wall-following run's contacts).
    QVERIFY(trained->bundle.find(SensorGroup::Right) != nullptr);
    SensorGroup other = SensorGroup::Right;
    for (const auto& g : tactile::kSensorGroups) {
      if (g.group != SensorGroup::Right && trained->bundle.find(g.group) != nullptr)
        other = g.group;
    }
    QVERIFY(other != SensorGroup::Right);
    const std::vector<SensorGroup> groups{SensorGroup::Right, other};
    QVERIFY(labels.labelFromModels(models, groups, 100, 199).ok());
    QCOMPARE(labels.undoStack()->count(), 2);  // anna's edit, then the model's, one step
    // Inside the range the model's decisions, outside anna's Wall.
    QCOMPARE(*labels.classAt(SensorGroup::Right, 99), ContactClass::Wall);
    QCOMPARE(*labels.classAt(SensorGroup::Right, 200), ContactClass::Wall);
    for (const auto& seg : labels.segments(other)) {
      QVERIFY(seg.firstStep >= 100 && seg.lastStep <= 199);
      QCOMPARE(seg.annotator, std::string("model:m"));
    }
    QVERIFY(!labels.segments(other).empty());
    // The runs dock tells the model's share from people's.
    tactile::gui::RunListModel runs;
    QVERIFY(runs.reload(fx.workspace.get(), labels.setId()).ok());
    const QString shown = runs.data(runs.index(0, tactile::gui::RunListModel::Coverage)).toString();
    QVERIFY2(shown.contains("model"), qPrintable(shown));
    QVERIFY(runs.data(runs.index(0, tactile::gui::RunListModel::Coverage), Qt::ToolTipRole)
                .toString()
                .contains("by people"));
    auto history = fx.workspace->labelStore().history(labels.setId(), session.info().id);
    QVERIFY(history.ok());
    QCOMPARE(history->back().annotator, std::string("model:m"));
    QCOMPARE(history->back().action, std::string("model"));
    // A group no chosen model covers: said, nothing stored, nothing on the undo stack.
    for (const auto& g : tactile::kSensorGroups) {
      if (trained->bundle.find(g.group) != nullptr) continue;
      const int before = labels.undoStack()->count();
      const auto refused = labels.labelFromModels(models, {g.group}, 0, 50);
      QVERIFY(!refused.ok());
      QVERIFY(QString::fromStdString(refused.error().message).contains("no chosen model covers"));
      QCOMPARE(labels.undoStack()->count(), before);
      break;
    }
    labels.undoStack()->undo();
    QVERIFY(labels.segments(other).empty());
    QCOMPARE(labels.segments(SensorGroup::Right).size(), std::size_t{1});
    QCOMPARE(*labels.classAt(SensorGroup::Right, 150), ContactClass::Wall);
  }

  void theRunsDockShowsAssignmentsAndFiltersMine() {
    GuiFixture fx(100);
    tactile::gui::RunListModel model;
    tactile::gui::RunListView view(&model);
    QVERIFY(model.reload(fx.workspace.get(), 0).ok());
    QCOMPARE(view.visibleRows(), 1);
    view.setAnnotator("anna");
    view.setAssignedToMeOnly(true);
    QCOMPARE(view.visibleRows(), 0);  // nothing assigned yet
    QVERIFY(fx.workspace->labelStore()
                .assign({fx.runName}, std::nullopt, "anna", "",
                        tactile::storage::AssignmentState::Labelled, "lead")
                .ok());
    QVERIFY(model.reloadAssignments(fx.workspace.get()).ok());
    QCOMPARE(view.visibleRows(), 1);
    const QString shown =
        model.data(model.index(0, tactile::gui::RunListModel::Assigned)).toString();
    QCOMPARE(shown, QStringLiteral("anna: labelled"));
    view.setAnnotator("ben");
    QCOMPARE(view.visibleRows(), 0);
    view.setAssignedToMeOnly(false);
    QCOMPARE(view.visibleRows(), 1);
  }
  // The server ends the workbench's session (as a restart or a network cut does): the window says
  // it lost the database, reconnects on its own, and an edit made after that is stored.
  void theWorkbenchSaysItLostTheServerAndReconnects() {
    const char* file = std::getenv("TACTILE_TEST_PG_FILE");
    std::string server;
    if (file != nullptr) {
      std::ifstream in(file);
      std::getline(in, server);
    }
    if (server.empty()) QSKIP("no PostgreSQL test server (ctest starts one)");
    // A schema of its own, and a session name that picks out only this window's connections.
    const std::string name = "reconnect_" + std::to_string(::getpid());
    const auto sql = [&](const std::string& text) {
      PGconn* conn = PQconnectdb(server.c_str());
      QVERIFY2(PQstatus(conn) == CONNECTION_OK, PQerrorMessage(conn));
      PGresult* result = PQexec(conn, text.c_str());
      const ExecStatusType status = PQresultStatus(result);
      QVERIFY2(status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK,
               PQresultErrorMessage(result));
      PQclear(result);
      PQfinish(conn);
    };
    sql("CREATE SCHEMA " + name);
    const std::string address =
        server + "&options=-csearch_path%3D" + name + "&application_name=" + name;
    GuiFixture fx(200);
    {
      auto target = tactile::storage::RunDatabase::open(address);
      QVERIFY2(target.ok(), target.ok() ? "" : target.errorText().c_str());
      auto source = tactile::storage::RunDatabase::open(fx.dbPath);
      QVERIFY(source.ok());
      auto copied = target.value()->copyFrom(*source.value(), {});
      QVERIFY2(copied.ok(), copied.ok() ? "" : copied.errorText().c_str());
    }
    tactile::gui::MainWindow window;
    const QString qaddress = QString::fromStdString(address);
    QVERIFY(window.openDatabase(qaddress).ok());
    QVERIFY(window.openRun(QString::fromStdString(fx.runName)).ok());
    QVERIFY(window.labels()->createSet("after").ok());

    sql("SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE application_name = '" + name +
        "'");
    QTRY_VERIFY_WITH_TIMEOUT(window.lastError().contains("Lost the connection"), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(window.statusBar()->currentMessage().startsWith("Reconnected"), 10000);
    QCOMPARE(window.databasePath(), qaddress);
    QVERIFY(window.openRun(QString::fromStdString(fx.runName)).ok());
    QVERIFY(window.labels()->openSet("after").ok());
    QVERIFY(window.labels()->label({SensorGroup::Left}, 5, 9, ContactClass::Wall).ok());
    auto check = tactile::workspace::Workspace::open(address);
    QVERIFY(check.ok());
    auto set = check.value()->labelStore().find("after");
    QVERIFY(set.ok());
    QCOMPARE(check.value()->labelStore().segments(set->id).value().size(), std::size_t{1});
    sql("DROP SCHEMA " + name + " CASCADE");
  }
};

QTEST_MAIN(TeamLabelsTest)
#include "team_labels_test.moc"
