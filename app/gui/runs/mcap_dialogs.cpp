#include "app/gui/runs/mcap_dialogs.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tactile::gui {

// ---- export ----------------------------------------------------------------------------------

McapExportDialog::McapExportDialog(const QString& run, const QStringList& labelSets,
                                   const QStringList& checkedSets, const QStringList& models,
                                   const QString& defaultPath, QWidget* parent)
    : QDialog(parent) {
  setObjectName(QStringLiteral("mcapExportDialog"));
  setWindowTitle(tr("Export Run as MCAP"));
  auto* form = new QFormLayout;
  form->addRow(tr("Run:"), new QLabel(run));
  sets_ = new QListWidget;
  sets_->setObjectName(QStringLiteral("labelSets"));
  for (const QString& set : labelSets) {
    auto* item = new QListWidgetItem(set, sets_);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(checkedSets.contains(set) ? Qt::Checked : Qt::Unchecked);
  }
  sets_->setMaximumHeight(120);
  if (labelSets.isEmpty()) {
    form->addRow(tr("Label sets:"), new QLabel(tr("none in this database")));
    sets_->hide();
  } else {
    form->addRow(tr("Label sets:"), sets_);
  }
  model_ = new QComboBox;
  model_->setObjectName(QStringLiteral("model"));
  model_->addItem(tr("(none)"), QString());
  for (const QString& m : models)
    model_->addItem(m, m);
  model_->setToolTip(tr("The model's online decisions go on /decisions/MODEL"));
  form->addRow(tr("Model decisions:"), model_);
  path_ = new QLineEdit(defaultPath);
  path_->setObjectName(QStringLiteral("outPath"));
  path_->setMinimumWidth(320);
  auto* browse = new QPushButton(tr("Browse..."));
  auto* fileRow = new QHBoxLayout;
  fileRow->addWidget(path_, 1);
  fileRow->addWidget(browse);
  form->addRow(tr("File:"), fileRow);
  auto* note = new QLabel(
      tr("Opens in Foxglove and Lichtblick: the readings, pose, command, truth, the chosen label "
         "sets and the model's decisions, one message per step, and the scene's walls."));
  note->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(note);
  layout->addWidget(buttons);
  connect(browse, &QPushButton::clicked, this, &McapExportDialog::browse);
  connect(path_, &QLineEdit::textChanged, this, &McapExportDialog::updateOk);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  updateOk();
}

void McapExportDialog::browse() {
  const QString chosen = QFileDialog::getSaveFileName(this, tr("Export Run as MCAP"), path_->text(),
                                                      tr("MCAP files (*.mcap);;All files (*)"));
  if (!chosen.isEmpty()) path_->setText(chosen);
}

void McapExportDialog::updateOk() {
  auto* box = findChild<QDialogButtonBox*>();
  if (box != nullptr) box->button(QDialogButtonBox::Ok)->setEnabled(!path_->text().isEmpty());
}

QStringList McapExportDialog::labelSets() const {
  QStringList out;
  for (int i = 0; i < sets_->count(); ++i)
    if (sets_->item(i)->checkState() == Qt::Checked) out << sets_->item(i)->text();
  return out;
}

QString McapExportDialog::model() const {
  return model_->currentData().toString();
}

QString McapExportDialog::path() const {
  return path_->text();
}

// ---- mapping ---------------------------------------------------------------------------------

namespace {

// The channels whose schema is one of `types` first (the likely choice), then the others.
void fillTopics(QComboBox* box, const mcap::ScanResult& scanned, const QStringList& types,
                bool optional) {
  if (optional) box->addItem(QObject::tr("(none)"), QString());
  QStringList preferred, others;
  for (const auto& [id, c] : scanned.channels) {
    const auto schema = scanned.schemas.find(c.schemaId);
    QString type =
        schema == scanned.schemas.end() ? QString() : QString::fromStdString(schema->second.name);
    type.replace(QStringLiteral("/msg/"), QStringLiteral("/"));
    (types.contains(type) ? preferred : others) << QString::fromStdString(c.topic);
  }
  for (const QString& t : preferred)
    box->addItem(t, t);
  if (!preferred.isEmpty() && !others.isEmpty()) box->insertSeparator(box->count());
  for (const QString& t : others)
    box->addItem(t, t);
  // A likely topic is picked; an optional role without one stays at "(none)".
  if (!preferred.isEmpty()) {
    box->setCurrentIndex(box->findData(preferred.front()));
  } else if (optional) {
    box->setCurrentIndex(0);
  }
}

}  // namespace

McapMappingDialog::McapMappingDialog(const mcap::ScanResult& scanned, const QString& file,
                                     QWidget* parent)
    : QDialog(parent) {
  setObjectName(QStringLiteral("mcapMappingDialog"));
  setWindowTitle(tr("Import ROS 2 Bag"));
  auto* intro = new QLabel(tr("<b>%1</b> is not an export of this program. Choose which of its "
                              "topics make the run: one step per message on the tactile topic; "
                              "pose and command are the latest messages before it.")
                               .arg(QFileInfo(file).fileName().toHtmlEscaped()));
  intro->setWordWrap(true);
  channels_ = new QTableWidget(static_cast<int>(scanned.channels.size()), 4);
  channels_->setObjectName(QStringLiteral("mcapChannels"));
  channels_->setHorizontalHeaderLabels(
      {tr("Topic"), tr("Schema"), tr("Message encoding"), tr("Messages")});
  channels_->verticalHeader()->hide();
  channels_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  channels_->setSelectionMode(QAbstractItemView::NoSelection);
  int row = 0;
  for (const auto& [id, c] : scanned.channels) {
    const auto schema = scanned.schemas.find(c.schemaId);
    const auto count = scanned.channelMessageCounts.find(id);
    const QStringList cells{
        QString::fromStdString(c.topic),
        schema == scanned.schemas.end() ? QString() : QString::fromStdString(schema->second.name),
        QString::fromStdString(c.messageEncoding),
        QString::number(count == scanned.channelMessageCounts.end() ? 0 : count->second)};
    for (int col = 0; col < 4; ++col) {
      auto* item = new QTableWidgetItem(cells[col]);
      if (col == 3) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      channels_->setItem(row, col, item);
    }
    ++row;
  }
  channels_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  channels_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  channels_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
  channels_->horizontalHeader()->setSectionResizeMode(3, QHeaderView::ResizeToContents);
  channels_->setMinimumHeight(140);

  tactile_ = new QComboBox;
  tactile_->setObjectName(QStringLiteral("tactileTopic"));
  fillTopics(
      tactile_, scanned,
      {QStringLiteral("std_msgs/Float32MultiArray"), QStringLiteral("std_msgs/Float64MultiArray")},
      false);
  pose_ = new QComboBox;
  pose_->setObjectName(QStringLiteral("poseTopic"));
  fillTopics(pose_, scanned,
             {QStringLiteral("nav_msgs/Odometry"), QStringLiteral("geometry_msgs/PoseStamped")},
             true);
  command_ = new QComboBox;
  command_->setObjectName(QStringLiteral("commandTopic"));
  fillTopics(command_, scanned,
             {QStringLiteral("geometry_msgs/Twist"), QStringLiteral("geometry_msgs/TwistStamped")},
             true);
  blocked_ = new QComboBox;
  blocked_->setObjectName(QStringLiteral("blockedTopic"));
  fillTopics(blocked_, scanned, {QStringLiteral("std_msgs/Bool")}, true);
  layout_ = new QComboBox;
  layout_->setObjectName(QStringLiteral("layout"));
  layout_->addItem(tr("44 normals, then 44 shears"), QStringLiteral("normal-then-shear"));
  layout_->addItem(tr("interleaved: n0, s0, n1, s1, ..."), QStringLiteral("interleaved"));
  scale_ = new QDoubleSpinBox;
  scale_->setObjectName(QStringLiteral("scale"));
  scale_->setDecimals(4);
  scale_->setRange(0.0001, 1e6);
  scale_->setValue(1000.0);
  scale_->setToolTip(tr("Scene units per bag unit: 1000 for a bag in metres (scenes are in mm)"));
  name_ = new QLineEdit(QFileInfo(file).completeBaseName());
  name_->setObjectName(QStringLiteral("runName"));

  auto* form = new QFormLayout;
  form->addRow(tr("Tactile readings:"), tactile_);
  form->addRow(tr("Layout of the 88 values:"), layout_);
  form->addRow(tr("Pose:"), pose_);
  form->addRow(tr("Command:"), command_);
  form->addRow(tr("Blocked flag:"), blocked_);
  form->addRow(tr("Scale:"), scale_);
  form->addRow(tr("Run name:"), name_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addWidget(new QLabel(tr("Channels in the file:")));
  layout->addWidget(channels_, 1);
  layout->addLayout(form);
  layout->addWidget(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(name_, &QLineEdit::textChanged, this, &McapMappingDialog::updateOk);
  connect(tactile_, &QComboBox::currentIndexChanged, this, &McapMappingDialog::updateOk);
  resize(640, 520);
  channels_->setFocusPolicy(Qt::NoFocus);  // the table only shows; the choices below take keys
  tactile_->setFocus();
  updateOk();
}

void McapMappingDialog::updateOk() {
  auto* box = findChild<QDialogButtonBox*>();
  if (box == nullptr) return;
  box->button(QDialogButtonBox::Ok)
      ->setEnabled(!tactile_->currentData().toString().isEmpty() &&
                   !name_->text().trimmed().isEmpty());
}

std::string McapMappingDialog::mappingJson() const {
  QJsonObject doc;
  doc[QStringLiteral("tactile")] =
      QJsonObject{{QStringLiteral("topic"), tactile_->currentData().toString()},
                  {QStringLiteral("layout"), layout_->currentData().toString()}};
  const std::pair<const char*, QComboBox*> roles[] = {
      {"pose", pose_}, {"command", command_}, {"blocked", blocked_}};
  for (const auto& [key, box] : roles) {
    const QString topic = box->currentData().toString();
    if (!topic.isEmpty()) doc[QLatin1String(key)] = QJsonObject{{QStringLiteral("topic"), topic}};
  }
  doc[QStringLiteral("scale")] = scale_->value();
  return QJsonDocument(doc).toJson(QJsonDocument::Compact).toStdString();
}

QString McapMappingDialog::runName() const {
  return name_->text().trimmed();
}

}  // namespace tactile::gui
