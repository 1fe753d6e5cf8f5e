// The workbench's models and undo commands without any widget: the run session's cursor and
// selection, label edits written to the database at once, and undo/redo restoring exactly what
// an edit replaced.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <cmath>

#include "app/gui/common/file_dialog_memory.h"
#include "app/gui/common/plot_style.h"
#include "app/gui/common/shortcuts.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/runs/run_list_model.h"
#include "app/gui/runs/run_session_model.h"
#include "base/text_rules.h"
#include "tests/app/gui_fixture.h"
#include "workspace/workspace.h"

using tactile::ContactClass;
using tactile::SensorGroup;
using tactile::gui::LabelModel;
using tactile::gui::RunSession;
using tactile::gui::testing::GuiFixture;

namespace {

// The set's stored segments of one group, as (first, last, class) triples.
std::vector<std::tuple<std::int64_t, std::int64_t, ContactClass>> stored(GuiFixture& fx,
                                                                         std::int64_t setId,
                                                                         SensorGroup group) {
  std::vector<std::tuple<std::int64_t, std::int64_t, ContactClass>> out;
  auto all = fx.workspace->labelStore().segments(setId);
  if (!all) return out;
  for (const auto& s : all.value())
    if (s.group == group) out.emplace_back(s.firstStep, s.lastStep, s.cls);
  return out;
}

// Opens the fixture's run in `session` and a new, empty label set `set` in `labels` for it.
bool openWithNewSet(GuiFixture& fx, RunSession& session, LabelModel& labels, const char* set) {
  session.setWorkspace(fx.workspace.get());
  if (!session.open(fx.runName).ok()) return false;
  labels.setWorkspace(fx.workspace.get());
  if (!labels.createSet(set).ok()) return false;
  labels.setRun(session.info().id, session.info().name, session.stepCount());
  return true;
}

// CIE L* (D65) of an sRGB colour: the lightness a reader sees.
double lightness(const QColor& c) {
  auto linear = [](double v) {
    v /= 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  const double y =
      0.2126 * linear(c.red()) + 0.7152 * linear(c.green()) + 0.0722 * linear(c.blue());
  return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

}  // namespace

class GuiCoreTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { QLocale::setDefault(QLocale::c()); }

  // File dialogs start where the last one of their kind ended (they once started in the current
  // directory), each kind on its own; before any choice, in the home folder.
  void fileDialogsRememberTheirFolder() {
    QTemporaryDir settingsDir, a, b;
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QCOMPARE(tactile::gui::startPath(QStringLiteral("models")), QDir::homePath());
    tactile::gui::rememberPath(QStringLiteral("models"), a.filePath(QStringLiteral("m.json")));
    tactile::gui::rememberPath(QStringLiteral("reports"), b.path());
    QCOMPARE(tactile::gui::startPath(QStringLiteral("models"), QStringLiteral("x.json")),
             QDir(a.path()).filePath(QStringLiteral("x.json")));
    QCOMPARE(tactile::gui::startPath(QStringLiteral("reports")),
             QFileInfo(b.path()).absoluteFilePath());
    tactile::gui::rememberPath(QStringLiteral("models"), QString());  // a cancelled dialog
    QCOMPARE(tactile::gui::startPath(QStringLiteral("models")), a.path());
  }

  // Guards "F14" (a key of old Sun keyboards that X11 lists for Undo) in the key list.
  void keyListHasNoKeysPastF12() {
    for (const tactile::gui::ShortcutEntry& e : tactile::gui::shortcutTable())
      for (const QKeySequence& k : e.keys) {
        const int code = k[0].key();
        QVERIFY2(code < Qt::Key_F13 || code > Qt::Key_F35, qPrintable(k.toString()));
      }
    QVERIFY(tactile::gui::shortcutTableHtml().contains(QStringLiteral("nowrap")));
  }

  // Guards the rainbow map whose lightness rose and fell (the maximum as dark as 0.6): normal
  // force's scale gets lighter all the way; shear's is neutral at zero and equally light at +-v.
  void valueScalesAreHonest() {
    double previous = -1.0;
    for (int i = 0; i <= 100; ++i) {
      const double l = lightness(tactile::gui::valueColor(i * 0.05, 5.0));
      QVERIFY2(l > previous, qPrintable(QStringLiteral("L* %1 at %2").arg(l).arg(i * 0.05)));
      previous = l;
    }
    QVERIFY(lightness(tactile::gui::valueColor(5.0, 5.0)) -
                lightness(tactile::gui::valueColor(0.0, 5.0)) >
            60.0);
    const QColor zero = tactile::gui::signedValueColor(0.0, 5.0);
    QVERIFY(std::abs(zero.red() - zero.green()) <= 2 && std::abs(zero.green() - zero.blue()) <= 2);
    QVERIFY(lightness(zero) > 90.0);
    for (double v : {1.0, 2.5, 5.0}) {
      const QColor below = tactile::gui::signedValueColor(-v, 5.0);
      const QColor above = tactile::gui::signedValueColor(v, 5.0);
      QVERIFY(below.blue() > below.red());
      QVERIFY(above.red() > above.blue());
      QVERIFY(std::abs(lightness(below) - lightness(above)) < 6.0);
      QVERIFY(lightness(above) < lightness(zero));
    }
  }

  void sessionOpensTrackSceneAndClampsTheCursor() {
    GuiFixture fx(300);
    RunSession session;
    session.setWorkspace(fx.workspace.get());
    QSignalSpy moved(&session, &RunSession::currentStepChanged);
    QVERIFY(session.open(fx.runName).ok());
    QCOMPARE(session.stepCount(), 300);
    QVERIFY(session.scene().has_value());
    QVERIFY(session.track().hasTruth());
    auto run = fx.workspace->loadRun(fx.runName);
    QVERIFY(run.ok());
    QCOMPARE(session.track().x, run->x);
    QCOMPARE(session.track().theta, run->theta);
    QCOMPARE(session.track().truth, run->truth);
    session.setCurrentStep(57);
    QCOMPARE(session.currentStep(), 57);
    for (int v = 0; v < tactile::kValuesPerStep; ++v)
      QCOMPARE(session.currentSensors()[static_cast<std::size_t>(v)], run->stepSensors(57)[v]);
    session.setCurrentStep(10'000);
    QCOMPARE(session.currentStep(), 299);
    session.setCurrentStep(-5);
    QCOMPARE(session.currentStep(), 0);
    const int before = static_cast<int>(moved.count());
    session.setCurrentStep(0);  // no move, no signal
    QCOMPARE(moved.count(), before);
    session.setSelection(120, 80);
    QCOMPARE(session.selection()->first, 80);
    QCOMPARE(session.selection()->last, 120);
    session.setSelection(-3, 1000);
    QCOMPARE(session.selection()->first, 0);
    QCOMPARE(session.selection()->last, 299);
    QVERIFY(!session.open("no_such_run").ok());
    QCOMPARE(session.info().name, fx.runName);  // the open run stays
  }

  void labelEditIsStoredAtOnceAndUndoRestoresExactly() {
    GuiFixture fx(400);
    RunSession session;
    LabelModel labels;
    QVERIFY(openWithNewSet(fx, session, labels, "mine"));
    const std::int64_t set = labels.setId();

    QVERIFY(labels.label({SensorGroup::Left}, 100, 199, ContactClass::Wall).ok());
    using Seg = std::tuple<std::int64_t, std::int64_t, ContactClass>;
    const std::vector<Seg> wall{{100, 199, ContactClass::Wall}};
    QCOMPARE(stored(fx, set, SensorGroup::Left), wall);
    // A second edit splits the first; its undo must restore the split segment exactly.
    QVERIFY(labels.label({SensorGroup::Left}, 140, 149, ContactClass::Corner).ok());
    const std::vector<Seg> split{{100, 139, ContactClass::Wall},
                                 {140, 149, ContactClass::Corner},
                                 {150, 199, ContactClass::Wall}};
    QCOMPARE(stored(fx, set, SensorGroup::Left), split);
    QCOMPARE(labels.segments(SensorGroup::Left).size(), std::size_t{3});
    QCOMPARE(*labels.classAt(SensorGroup::Left, 145), ContactClass::Corner);
    QVERIFY(!labels.classAt(SensorGroup::Left, 99).has_value());

    labels.undoStack()->undo();
    QCOMPARE(stored(fx, set, SensorGroup::Left), wall);
    QCOMPARE(labels.segments(SensorGroup::Left).size(), std::size_t{1});
    labels.undoStack()->undo();
    QVERIFY(stored(fx, set, SensorGroup::Left).empty());
    labels.undoStack()->redo();
    labels.undoStack()->redo();
    QCOMPARE(stored(fx, set, SensorGroup::Left), split);
  }

  void severalGroupsAreOneUndoStep() {
    GuiFixture fx(300);
    RunSession session;
    LabelModel labels;
    QVERIFY(openWithNewSet(fx, session, labels, "two"));
    QVERIFY(labels.label({SensorGroup::Left, SensorGroup::Right}, 10, 20, ContactClass::Wall).ok());
    QCOMPARE(stored(fx, labels.setId(), SensorGroup::Left).size(), std::size_t{1});
    QCOMPARE(stored(fx, labels.setId(), SensorGroup::Right).size(), std::size_t{1});
    QCOMPARE(labels.undoStack()->count(), 1);
    labels.undoStack()->undo();
    QVERIFY(stored(fx, labels.setId(), SensorGroup::Left).empty());
    QVERIFY(stored(fx, labels.setId(), SensorGroup::Right).empty());
  }

  void moveAndRemoveAreUndoable() {
    GuiFixture fx(300);
    RunSession session;
    LabelModel labels;
    QVERIFY(openWithNewSet(fx, session, labels, "m"));
    QVERIFY(labels.label({SensorGroup::Front}, 50, 60, ContactClass::Corner).ok());
    const std::int64_t id = labels.segments(SensorGroup::Front).front().id;
    QVERIFY(labels.moveSegment(id, 50, 90).ok());
    QCOMPARE(labels.segments(SensorGroup::Front).front().lastStep, 90);
    QVERIFY(labels.removeSegment(labels.segments(SensorGroup::Front).front().id).ok());
    QVERIFY(labels.segments(SensorGroup::Front).empty());
    labels.undoStack()->undo();
    QCOMPARE(labels.segments(SensorGroup::Front).front().lastStep, 90);
    labels.undoStack()->undo();
    QCOMPARE(labels.segments(SensorGroup::Front).front().lastStep, 60);
    // Editing without a run or beyond it is an error that changes nothing.
    QVERIFY(!labels.label({}, 1, 2, ContactClass::Wall).ok());
    QVERIFY(!labels.label({SensorGroup::Front}, 500, 600, ContactClass::Wall).ok());
    QCOMPARE(labels.segments(SensorGroup::Front).size(), std::size_t{1});
  }

  void failedEditLeavesNoUndoStep() {
    GuiFixture fx(100);
    RunSession session;
    LabelModel labels;
    QVERIFY(openWithNewSet(fx, session, labels, "gone"));
    // The set vanishes underneath the model (another program deleted it).
    QVERIFY(fx.workspace->labelStore().remove({"gone"}).ok());
    QVERIFY(!labels.label({SensorGroup::Back}, 1, 5, ContactClass::Wall).ok());
    QVERIFY(!labels.undoStack()->canUndo() || labels.undoStack()->command(0)->childCount() == 0);
  }

  void labelSetsSaveAsExportAndImport() {
    GuiFixture fx(300);
    RunSession session;
    LabelModel labels;
    QVERIFY(openWithNewSet(fx, session, labels, "first"));
    QVERIFY(labels.label({SensorGroup::Right}, 30, 80, ContactClass::Wall).ok());
    QVERIFY(!labels.createSet("first").ok());  // the name is taken
    QCOMPARE(labels.setName(), std::string("first"));
    // Save As copies the set and continues in the copy; the original keeps its segment.
    QVERIFY(labels.saveSetAs("second").ok());
    QCOMPARE(labels.setName(), std::string("second"));
    QVERIFY(labels.label({SensorGroup::Right}, 81, 90, ContactClass::Corner).ok());
    QCOMPARE(stored(fx, labels.setId(), SensorGroup::Right).size(), std::size_t{2});
    auto first = fx.workspace->labelStore().find("first");
    QVERIFY(first.ok());
    QCOMPARE(stored(fx, first->id, SensorGroup::Right).size(), std::size_t{1});
    // Export, then import into a fresh set: the same segments.
    const std::string file = fx.dir.filePath(QStringLiteral("second.csv")).toStdString();
    QVERIFY(labels.exportFile(file).ok());
    QVERIFY(labels.createSet("third").ok());
    auto read = labels.importFile(file);
    QVERIFY2(read.ok(), read.ok() ? "" : read.errorText().c_str());
    QCOMPARE(read.value(), 2);
    QCOMPARE(labels.segments(SensorGroup::Right).size(), std::size_t{2});
    QCOMPARE(labels.segments(SensorGroup::Right)[1].cls, ContactClass::Corner);
    // A broken file changes nothing and names the file.
    const QString bad = fx.dir.filePath(QStringLiteral("bad.csv"));
    {
      QFile f(bad);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("run,group,first_step,last_step,class\nroom1_demo,R,5,1,Wall\n");
    }
    auto refused = labels.importFile(bad.toStdString());
    QVERIFY(!refused.ok());
    QVERIFY(QString::fromStdString(refused.errorText()).contains(QStringLiteral("bad.csv")));
    QCOMPARE(labels.segments(SensorGroup::Right).size(), std::size_t{2});
  }

  void truthAgreementCountsLabelledStepsAndKappa() {
    GuiFixture fx(400);
    RunSession session;
    session.setWorkspace(fx.workspace.get());
    QVERIFY(session.open(fx.runName).ok());
    const auto& track = session.track();
    // Labels equal to the truth over steps 0..199 of group R agree fully.
    std::vector<tactile::storage::LabelSegment> segments;
    for (std::int64_t k = 0; k < 200; ++k) {
      tactile::storage::LabelSegment s;
      s.group = SensorGroup::Right;
      s.firstStep = s.lastStep = k;
      s.cls = track.truthAt(static_cast<std::size_t>(k), SensorGroup::Right);
      segments.push_back(s);
    }
    auto rows = tactile::workspace::truthAgreement(track, segments);
    QCOMPARE(rows.size(), std::size_t{8});
    const auto& r = rows[static_cast<std::size_t>(tactile::groupIndex(SensorGroup::Right))];
    QCOMPARE(r.comparedSteps, 200);
    QCOMPARE(r.agreeingSteps, 200);
    QCOMPARE(*r.percent, 100.0);
    QVERIFY(!rows[0].percent.has_value());  // nothing labelled in F
    // One wrong class on every fourth step lowers both figures.
    for (std::size_t i = 0; i < segments.size(); i += 4)
      segments[i].cls =
          segments[i].cls == ContactClass::DeadPath ? ContactClass::Wall : ContactClass::DeadPath;
    rows = tactile::workspace::truthAgreement(track, segments);
    const auto& worse = rows[static_cast<std::size_t>(tactile::groupIndex(SensorGroup::Right))];
    QCOMPARE(*worse.percent, 75.0);
    QVERIFY(worse.kappa.has_value());
    QVERIFY(*worse.kappa < 0.9);
  }

  // Two annotators' sets against each other, with the chance agreement that explains a kappa.
  void labelSetAgreementHasItsChance() {
    using tactile::storage::LabelSegment;
    auto seg = [](SensorGroup g, std::int64_t first, std::int64_t last, ContactClass c) {
      LabelSegment s;
      s.group = g;
      s.firstStep = first;
      s.lastStep = last;
      s.cls = c;
      return s;
    };
    // F: one says Wall on 0..9; the other Wall on 0..4, Corner on 5..9 and labels 10..19 alone.
    const std::vector<LabelSegment> one{seg(SensorGroup::Front, 0, 9, ContactClass::Wall),
                                        seg(SensorGroup::Back, 0, 99, ContactClass::NoContact)};
    const std::vector<LabelSegment> other{seg(SensorGroup::Front, 0, 4, ContactClass::Wall),
                                          seg(SensorGroup::Front, 5, 9, ContactClass::Corner),
                                          seg(SensorGroup::Front, 10, 19, ContactClass::Wall),
                                          seg(SensorGroup::Back, 50, 149, ContactClass::NoContact)};
    const auto rows = tactile::workspace::labelAgreement(120, one, other);
    QCOMPARE(rows.size(), std::size_t{8});
    const auto& f = rows[static_cast<std::size_t>(tactile::groupIndex(SensorGroup::Front))];
    QCOMPARE(f.comparedSteps, 10);  // only the steps both label
    QCOMPARE(f.agreeingSteps, 5);
    QCOMPARE(*f.percent, 50.0);
    // Chance: one says Wall always, the other half the time: 1 * 0.5.
    QCOMPARE(*f.chancePercent, 50.0);
    QVERIFY(std::abs(*f.kappa) < 1e-12);  // no better than chance
    // B: both NoContact on 50..99 (clipped to the run's 120 steps on the other side): full
    // agreement, chance 100 %, kappa undefined.
    const auto& b = rows[static_cast<std::size_t>(tactile::groupIndex(SensorGroup::Back))];
    QCOMPARE(b.comparedSteps, 50);
    QCOMPARE(*b.percent, 100.0);
    QCOMPARE(*b.chancePercent, 100.0);
    QVERIFY(!b.kappa.has_value());
    QVERIFY(!rows[static_cast<std::size_t>(tactile::groupIndex(SensorGroup::Left))].percent);
    // The truth agreement reports its chance the same way.
    GuiFixture fx(300);
    RunSession session;
    session.setWorkspace(fx.workspace.get());
    QVERIFY(session.open(fx.runName).ok());
    std::vector<LabelSegment> labels{seg(SensorGroup::Right, 0, 299, ContactClass::NoContact)};
    const auto truth = tactile::workspace::truthAgreement(session.track(), labels);
    const auto& r = truth[static_cast<std::size_t>(tactile::groupIndex(SensorGroup::Right))];
    std::int64_t noContact = 0;
    for (std::size_t k = 0; k < 300; ++k)
      noContact += session.track().truthAt(k, SensorGroup::Right) == ContactClass::NoContact;
    // The labels say NoContact throughout, so chance is the truth's NoContact share.
    QCOMPARE(*r.chancePercent, 100.0 * static_cast<double>(noContact) / 300.0);
    QCOMPARE(*r.percent, *r.chancePercent);
  }

  // Sweeps named by what they sweep, not all "<set> sweep".
  void sweepNamesSayWhatWasSwept() {
    tactile::analysis::SweepGrid g;
    g.orders = {1, 4, 16};
    g.forms = {tactile::analysis::CovarianceForm::NodalFull};
    g.varianceFloors = {0.03, 0.01};
    g.groups = {SensorGroup::Front, SensorGroup::Left};
    const std::string a = tactile::workspace::defaultSweepName("truth", g);
    QCOMPARE(QString::fromStdString(a),
             QStringLiteral("truth: order 1-16 x floor 0.01-0.03 (F L)"));
    // A default name follows the name rule: no comma, whatever the grid.
    QVERIFY(!tactile::nameProblem(a).has_value());
    g.orders = {4};
    g.varianceFloors = {0.01};
    g.groups = {};
    const std::string b = tactile::workspace::defaultSweepName("truth", g);
    QVERIFY2(b != a && QString::fromStdString(b).contains(QStringLiteral("order 4")), b.c_str());
    QVERIFY(QString::fromStdString(b).contains(QStringLiteral("floor 0.01")));
    QVERIFY2(!tactile::nameProblem(b).has_value(), b.c_str());
  }

  void runListShowsCoverageOfTheSet() {
    GuiFixture fx(200);
    auto set = fx.workspace->labelStore().create("cov");
    QVERIFY(set.ok());
    auto run = fx.workspace->runStore().find(fx.runName);
    QVERIFY(run.ok());
    tactile::storage::LabelSegment s;
    s.runId = run->id;
    s.group = SensorGroup::Left;
    s.firstStep = 0;
    s.lastStep = 199;
    s.cls = ContactClass::Wall;
    QVERIFY(fx.workspace->addSegment(set.value(), s).ok());
    tactile::gui::RunListModel model;
    QVERIFY(model.reload(fx.workspace.get(), set.value()).ok());
    QCOMPARE(model.rowCount(), 1);
    // One of eight groups over the whole run.
    QCOMPARE(
        model.data(model.index(0, tactile::gui::RunListModel::Coverage), Qt::UserRole).toDouble(),
        12.5);
    QCOMPARE(model.data(model.index(0, tactile::gui::RunListModel::Steps)).toString(),
             QStringLiteral("200"));
  }
};

QTEST_MAIN(GuiCoreTest)
#include "gui_core_test.moc"
