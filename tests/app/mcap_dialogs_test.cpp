// The workbench's MCAP dialogs and actions: the mapping dialog picks a bag's topics by their
// message types and writes the mapping the importer reads; File > Export Run > MCAP writes the
// open run with the chosen label set, and that file imports back without a mapping; a ROS 2 bag
// dropped on the window opens the mapping dialog.
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>
#include <set>

#include "app/gui/labels/label_model.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/mcap_dialogs.h"
#include "app/gui/runs/run_list_view.h"
#include "app/gui/runs/run_session_model.h"
#include "mcap/reader.h"
#include "mcap/ros2_bag.h"
#include "mcap/writer.h"
#include "tests/app/gui_fixture.h"

using tactile::gui::MainWindow;
using tactile::gui::McapExportDialog;
using tactile::gui::McapMappingDialog;
using tactile::gui::testing::GuiFixture;
namespace mcap = tactile::mcap;

namespace {

// The event handler as the drag and drop machinery calls it.
struct DropTarget : MainWindow {
  using MainWindow::dropEvent;
};

// What `mcap info` reads from a robot's bag: odometry, a command, the tactile array, a bumper and
// a camera (which no role takes).
mcap::ScanResult robotBag() {
  mcap::ScanResult s;
  const std::pair<const char*, const char*> channels[] = {
      {"/camera/image", "sensor_msgs/msg/Image"},
      {"/odom", "nav_msgs/msg/Odometry"},
      {"/cmd_vel", "geometry_msgs/msg/Twist"},
      {"/skin/readings", "std_msgs/msg/Float32MultiArray"},
      {"/bumper", "std_msgs/msg/Bool"}};
  std::uint16_t id = 1;
  for (const auto& [topic, type] : channels) {
    mcap::Schema schema;
    schema.id = id;
    schema.name = type;
    schema.encoding = "ros2msg";
    s.schemas[id] = schema;
    mcap::Channel c;
    c.id = id;
    c.schemaId = id;
    c.topic = topic;
    c.messageEncoding = "cdr";
    s.channels[id] = c;
    s.channelMessageCounts[id] = 100ULL * id;
    ++id;
  }
  return s;
}

}  // namespace

class McapDialogsTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    QLocale::setDefault(QLocale::c());
    QVERIFY(settingsDir_.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
    QCoreApplication::setOrganizationName(QStringLiteral("TactileWorkbenchTest"));
  }

  void init() { QSettings().clear(); }

  void mappingDialogPicksTopicsByTypeAndWritesTheMapping() {
    McapMappingDialog dialog(robotBag(), QStringLiteral("/data/hallway run.mcap"));
    // The channels as `mcap info` lists them, with their message counts.
    auto* table = dialog.findChild<QTableWidget*>(QStringLiteral("mcapChannels"));
    QVERIFY(table != nullptr);
    QCOMPARE(table->rowCount(), 5);
    QCOMPARE(table->item(3, 0)->text(), QStringLiteral("/skin/readings"));
    QCOMPARE(table->item(3, 3)->text(), QStringLiteral("400"));
    auto combo = [&](const char* name) {
      auto* box = dialog.findChild<QComboBox*>(QLatin1String(name));
      return box != nullptr ? box->currentData().toString() : QStringLiteral("<missing>");
    };
    QCOMPARE(combo("tactileTopic"), QStringLiteral("/skin/readings"));
    QCOMPARE(combo("poseTopic"), QStringLiteral("/odom"));
    QCOMPARE(combo("commandTopic"), QStringLiteral("/cmd_vel"));
    QCOMPARE(combo("blockedTopic"), QStringLiteral("/bumper"));
    QCOMPARE(dialog.runName(), QStringLiteral("hallway run"));

    // The user's choices: no bumper, interleaved values, a bag in centimetres.
    auto* blocked = dialog.findChild<QComboBox*>(QStringLiteral("blockedTopic"));
    blocked->setCurrentIndex(blocked->findData(QString()));
    auto* layout = dialog.findChild<QComboBox*>(QStringLiteral("layout"));
    layout->setCurrentIndex(layout->findData(QStringLiteral("interleaved")));
    dialog.findChild<QDoubleSpinBox*>(QStringLiteral("scale"))->setValue(10.0);
    const auto mapping = nlohmann::json::parse(dialog.mappingJson());
    QCOMPARE(mapping["tactile"]["topic"].get<std::string>(), std::string("/skin/readings"));
    QCOMPARE(mapping["tactile"]["layout"].get<std::string>(), std::string("interleaved"));
    QCOMPARE(mapping["pose"]["topic"].get<std::string>(), std::string("/odom"));
    QCOMPARE(mapping["command"]["topic"].get<std::string>(), std::string("/cmd_vel"));
    QVERIFY(!mapping.contains("blocked"));
    QCOMPARE(mapping["scale"].get<double>(), 10.0);
    // The importer reads what the dialog writes.
    auto parsed = mcap::parseMapping(dialog.mappingJson(), "dialog");
    QVERIFY2(parsed.ok(), parsed.ok() ? "" : parsed.errorText().c_str());
    QCOMPARE(parsed->scale, 10.0);
    QCOMPARE(parsed->shears[0], 1);  // interleaved: n0, s0, ...
  }

  void exportActionWritesTheRunAndItImportsBack() {
    GuiFixture fx(300);
    DropTarget window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    QVERIFY(window.labels()->createSet("mine").ok());
    // The menu entry is there (File > Export Run > MCAP...).
    auto* action = window.findChild<QAction*>(QStringLiteral("exportMcapAction"));
    QVERIFY(action != nullptr);
    QVERIFY(action->isEnabled());

    // The dialog offers the run's name as the file and ticks the open label set.
    McapExportDialog dialog(QStringLiteral("room1_demo"), {"mine", "other"}, {"mine"}, {"m1"},
                            fx.dir.filePath(QStringLiteral("room1_demo.mcap")));
    QCOMPARE(dialog.labelSets(), QStringList{"mine"});
    QCOMPARE(dialog.model(), QString());
    QVERIFY(dialog.path().endsWith(QStringLiteral("room1_demo.mcap")));

    const QString out = fx.dir.filePath(QStringLiteral("exported.mcap"));
    window.exportRunMcap(out, dialog.labelSets(), dialog.model());
    QTRY_VERIFY_WITH_TIMEOUT(!window.mcapBusy(), 20000);
    QVERIFY2(window.lastError().isEmpty(), qPrintable(window.lastError()));
    auto scanned = mcap::scanFile(out.toStdString());
    QVERIFY2(scanned.ok(), scanned.ok() ? "" : scanned.errorText().c_str());
    std::set<std::string> topics;
    for (const auto& [id, c] : scanned->channels)
      topics.insert(c.topic);
    QVERIFY(topics.count("/labels/mine") == 1);
    QVERIFY(topics.count("/tactile") == 1);
    QCOMPARE(scanned->channelMessageCounts.at(1), std::uint64_t{300});

    // An export that cannot be written names the file.
    window.exportRunMcap(fx.dir.filePath(QStringLiteral("no/such/folder/x.mcap")), {}, {});
    QTRY_VERIFY_WITH_TIMEOUT(!window.mcapBusy(), 20000);
    QVERIFY2(window.lastError().contains(QStringLiteral("x.mcap")), qPrintable(window.lastError()));

    // Dropped on the window with a new database open, the export imports without a mapping.
    QVERIFY(window.openDatabase(fx.dir.filePath(QStringLiteral("second.db")), true).ok());
    QCOMPARE(window.runList()->table()->model()->rowCount(), 0);
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(out)});
    QDropEvent event(QPointF(100, 100), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    window.dropEvent(&event);
    QTRY_VERIFY_WITH_TIMEOUT(!window.mcapBusy(), 20000);
    QVERIFY2(window.lastError().isEmpty(), qPrintable(window.lastError()));
    QTRY_COMPARE_WITH_TIMEOUT(window.runList()->table()->model()->rowCount(), 1, 10000);
    auto second = tactile::workspace::Workspace::open(
        fx.dir.filePath(QStringLiteral("second.db")).toStdString());
    QVERIFY(second.ok());
    auto back = second.value()->loadRun("exported");
    auto original = fx.workspace->loadRun(fx.runName);
    QVERIFY(back.ok() && original.ok());
    QCOMPARE(back->stepCount(), original->stepCount());
    QVERIFY(back->x == original->x && back->sensors == original->sensors);
  }

  void aDroppedBagOpensTheMappingDialog() {
    GuiFixture fx(50);
    // A bag with one tactile channel and no message: enough for the dialog.
    const QString bag = fx.dir.filePath(QStringLiteral("robot.mcap"));
    {
      mcap::WriterOptions o;
      o.profile = "ros2";
      mcap::Writer w(o);
      const auto schema = w.addSchema(
          "std_msgs/msg/Float32MultiArray", "ros2msg",
          "MultiArrayLayout layout\nfloat32[] data\n"
          "================================================================================\n"
          "MSG: std_msgs/MultiArrayLayout\nMultiArrayDimension[] dim\nuint32 data_offset\n"
          "================================================================================\n"
          "MSG: std_msgs/MultiArrayDimension\nstring label\nuint32 size\nuint32 stride\n");
      w.addChannel(schema, "/tactile", "cdr");
      const std::string bytes = w.finish();
      QFile f(bag);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(bytes.data(), static_cast<qint64>(bytes.size()));
    }
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openDatabase(QString::fromStdString(fx.dbPath)).ok());
    window.importMcapFile(bag);
    auto* dialog = window.findChild<McapMappingDialog*>();
    QVERIFY(dialog != nullptr);
    QTRY_VERIFY(dialog->isVisible());
    QCOMPARE(dialog->runName(), QStringLiteral("robot"));
    QVERIFY(dialog->mappingJson().find("\"/tactile\"") != std::string::npos);
    dialog->reject();
  }

 private:
  QTemporaryDir settingsDir_;
};

QTEST_MAIN(McapDialogsTest)
#include "mcap_dialogs_test.moc"
