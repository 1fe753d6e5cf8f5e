#include "app/gui/labels/label_panel_view.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include "app/gui/common/file_dialog_memory.h"
#include "app/gui/common/plot_style.h"
#include "app/gui/common/settings_keys.h"
#include "app/gui/labels/label_model.h"
#include "app/gui/runs/run_session_model.h"
#include "workspace/workspace.h"

namespace tactile::gui {
namespace {

QString groupName(SensorGroup g) {
  return QString::fromLatin1(groupInfo(g).shortName.data(),
                             static_cast<qsizetype>(groupInfo(g).shortName.size()));
}

}  // namespace

LabelPanelView::LabelPanelView(RunSession* session, LabelModel* labels, QWidget* parent)
    : QWidget(parent), session_(session), labels_(labels) {
  setObjectName(QStringLiteral("labelPanel"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);

  // ---- the set ----
  auto* setBox = new QGroupBox(tr("Label set"), this);
  auto* setLayout = new QGridLayout(setBox);
  sets_ = new QComboBox(setBox);
  sets_->setObjectName(QStringLiteral("labelSets"));
  sets_->setToolTip(tr("The label set being edited; choose another to open it"));
  setLayout->addWidget(sets_, 0, 0, 1, 4);
  const std::array<std::pair<QString, void (LabelPanelView::*)()>, 4> setButtons{{
      {tr("New..."), &LabelPanelView::newSet},
      {tr("Save As..."), &LabelPanelView::saveSetAs},
      {tr("Import..."), &LabelPanelView::importLabels},
      {tr("Export..."), &LabelPanelView::exportLabels},
  }};
  for (int i = 0; i < 4; ++i) {
    auto* b = new QPushButton(setButtons[static_cast<std::size_t>(i)].first, setBox);
    connect(b, &QPushButton::clicked, this, setButtons[static_cast<std::size_t>(i)].second);
    setLayout->addWidget(b, 1, i);
  }
  layout->addWidget(setBox);

  // ---- groups ----
  auto* groupBox = new QGroupBox(tr("Apply to"), this);
  auto* groupLayout = new QGridLayout(groupBox);
  mode_ = new QButtonGroup(this);
  const std::array<QString, 3> modes{tr("Selected group"), tr("Checked groups"),
                                     tr("Groups in contact")};
  for (int i = 0; i < 3; ++i) {
    auto* r = new QRadioButton(modes[static_cast<std::size_t>(i)], groupBox);
    r->setObjectName(QStringLiteral("groupsMode%1").arg(i));
    mode_->addButton(r, i);
    groupLayout->addWidget(r, i, 0, 1, 4);
  }
  mode_->button(0)->setChecked(true);
  connect(mode_, &QButtonGroup::idToggled, this, [this](int, bool on) {
    if (on) emit settingsChanged();
  });
  for (const GroupInfo& info : kSensorGroups) {
    const int g = groupIndex(info.group);
    auto* c = new QCheckBox(groupName(info.group), groupBox);
    c->setObjectName(QStringLiteral("groupCheck_%1").arg(groupName(info.group)));
    c->setToolTip(tr("Label the %1 group (with \"Checked groups\")")
                      .arg(QString::fromLatin1(info.longName.data(),
                                               static_cast<qsizetype>(info.longName.size()))));
    checks_[static_cast<std::size_t>(g)] = c;
    connect(c, &QCheckBox::toggled, this, &LabelPanelView::settingsChanged);
    groupLayout->addWidget(c, 3 + g / 4, g % 4);
  }
  layout->addWidget(groupBox);

  // ---- classes ----
  auto* classBox = new QGroupBox(tr("Classes (keys 1-5)"), this);
  auto* classLayout = new QVBoxLayout(classBox);
  for (int i = 0; i < kContactClassCount; ++i) {
    const auto cls = static_cast<ContactClass>(i);
    auto* b = new QToolButton(classBox);
    b->setObjectName(QStringLiteral("applyClass%1").arg(i + 1));
    b->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    QPixmap swatch(14, 14);
    swatch.fill(classColor(cls));
    b->setIcon(QIcon(swatch));
    b->setText(QStringLiteral("%1  %2").arg(i + 1).arg(className(cls)));
    b->setToolTip(tr("Label the selected steps as %1 (key %2)").arg(className(cls)).arg(i + 1));
    connect(b, &QToolButton::clicked, this, [this, cls] { applyClass(cls); });
    classLayout->addWidget(b);
  }
  layout->addWidget(classBox);

  // ---- where the cursor is ----
  auto* info = new QGroupBox(tr("At the cursor"), this);
  auto* infoLayout = new QFormLayout(info);
  range_ = new QLabel(info);
  range_->setObjectName(QStringLiteral("selectionRange"));
  atCursor_ = new QLabel(info);
  atCursor_->setObjectName(QStringLiteral("segmentAtCursor"));
  atCursor_->setWordWrap(true);
  auto* del = new QPushButton(tr("Delete segment (Del)"), info);
  connect(del, &QPushButton::clicked, this, &LabelPanelView::deleteAtCursor);
  infoLayout->addRow(tr("Selection:"), range_);
  infoLayout->addRow(tr("Segment:"), atCursor_);
  infoLayout->addRow(del);
  layout->addWidget(info);

  // ---- agreement with truth or with another label set ----
  agreementWith_ = new QComboBox(this);
  agreementWith_->setObjectName(QStringLiteral("agreementWith"));
  agreementWith_->setToolTip(
      tr("Compare the labels with the run's truth or with another label set (another annotator)"));
  agreement_ = new QTableWidget(kGroupCount, 4, this);
  agreement_->setObjectName(QStringLiteral("truthAgreement"));
  agreement_->setHorizontalHeaderLabels({tr("Group"), tr("Agree"), tr("Chance"), tr("Kappa")});
  agreement_->horizontalHeaderItem(1)->setToolTip(
      tr("Share of the steps both sides label on which they give the same class"));
  agreement_->horizontalHeaderItem(2)->setToolTip(
      tr("Agreement expected by chance from each side's class shares"));
  agreement_->horizontalHeaderItem(3)->setToolTip(
      tr("Cohen's kappa = (agree - chance) / (100 % - chance): 0 when the agreement is no better "
         "than chance, 1 when perfect; '-' when chance is 100 % (one class throughout)"));
  agreement_->verticalHeader()->hide();
  agreement_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
  agreement_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  agreement_->horizontalHeader()->setStretchLastSection(true);
  agreement_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  // All eight groups without a scroll bar, whatever the language's row height (the panel scrolls
  // as a whole on a short screen).
  agreement_->setMinimumHeight(agreement_->horizontalHeader()->sizeHint().height() +
                               kGroupCount * agreement_->verticalHeader()->defaultSectionSize() +
                               2 * agreement_->frameWidth() + 2);
  agreement_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  auto* withRow = new QHBoxLayout;
  withRow->addWidget(new QLabel(tr("Agreement with"), this));
  withRow->addWidget(agreementWith_, 1);
  layout->addLayout(withRow);
  layout->addWidget(agreement_, 1);
  connect(agreementWith_, &QComboBox::activated, this, &LabelPanelView::refreshAgreement);

  connect(labels_, &LabelModel::labelSetChanged, this, &LabelPanelView::refreshSets);
  connect(labels_, &LabelModel::labelsChanged, this, [this] {
    refreshCursorInfo();
    refreshAgreement();
  });
  connect(session_, &RunSession::runOpened, this, &LabelPanelView::refreshAgreement);
  connect(session_, &RunSession::currentStepChanged, this, &LabelPanelView::refreshCursorInfo);
  connect(session_, &RunSession::selectedGroupChanged, this, &LabelPanelView::refreshCursorInfo);
  connect(session_, &RunSession::selectionChanged, this, &LabelPanelView::refreshCursorInfo);
  connect(sets_, &QComboBox::activated, this, &LabelPanelView::openSetAt);
  refreshSets();
  refreshCursorInfo();
  refreshAgreement();
}

std::vector<SensorGroup> LabelPanelView::checkedGroups() const {
  std::vector<SensorGroup> out;
  for (const GroupInfo& info : kSensorGroups)
    if (checks_[static_cast<std::size_t>(groupIndex(info.group))]->isChecked())
      out.push_back(info.group);
  return out;
}

LabelPanelView::GroupsMode LabelPanelView::groupsMode() const {
  return static_cast<GroupsMode>(std::max(0, mode_->checkedId()));
}

void LabelPanelView::setGroupsMode(GroupsMode mode) {
  mode_->button(static_cast<int>(mode))->setChecked(true);
}

void LabelPanelView::setGroupChecked(SensorGroup group, bool checked) {
  checks_[static_cast<std::size_t>(groupIndex(group))]->setChecked(checked);
}

std::vector<SensorGroup> LabelPanelView::groupsFor(std::int64_t first, std::int64_t last) const {
  std::vector<SensorGroup> out;
  switch (groupsMode()) {
    case GroupsMode::Selected:
      out.push_back(session_->selectedGroup());
      break;
    case GroupsMode::Checked:
      for (const GroupInfo& info : kSensorGroups)
        if (checks_[static_cast<std::size_t>(groupIndex(info.group))]->isChecked())
          out.push_back(info.group);
      break;
    case GroupsMode::Contacting: {
      // One bucket over the range: its maxima say which domes were pressed at all.
      auto summary = session_->summary(first, last, 1);
      if (!summary || summary->buckets.empty()) break;
      for (const GroupInfo& info : kSensorGroups) {
        bool touched = false;
        for (int s = info.firstSensor; s < info.firstSensor + info.sensorCount; ++s) {
          for (const auto& bucket : summary->buckets)
            touched = touched || bucket.max[static_cast<std::size_t>(normalOffset(s))] > 0.0;
        }
        if (touched) out.push_back(info.group);
      }
      break;
    }
  }
  return out;
}

void LabelPanelView::report(const QString& failure) {
  if (!failure.isEmpty()) emit errorOccurred(failure);
}

void LabelPanelView::applyClass(ContactClass cls) {
  if (!session_->isOpen()) return report(tr("Open a run first."));
  if (!labels_->hasSet()) return report(tr("Create or open a label set first."));
  const auto range =
      session_->selection().value_or(StepRange{session_->currentStep(), session_->currentStep()});
  const std::vector<SensorGroup> groups = groupsFor(range.first, range.last);
  if (groups.empty()) {
    return report(groupsMode() == GroupsMode::Contacting
                      ? tr("No group is in contact here: nothing to label.")
                      : tr("No group to label: tick a group."));
  }
  Status s = labels_->label(groups, range.first, range.last, cls);
  if (!s) return report(QString::fromStdString(s.errorText()));
  QStringList names;
  for (SensorGroup g : groups)
    names << groupName(g);
  emit statusMessage(tr("Labelled steps %1-%2 as %3 in %4")
                         .arg(range.first)
                         .arg(range.last)
                         .arg(className(cls), names.join(QStringLiteral(", "))));
}

void LabelPanelView::deleteAtCursor() {
  if (!session_->isOpen() || !labels_->hasSet()) return;
  const std::int64_t step = session_->currentStep();
  for (SensorGroup g : groupsFor(step, step)) {
    if (const storage::LabelSegment* s = labels_->segmentAt(g, step)) {
      Status status = labels_->removeSegment(s->id);
      if (!status) return report(QString::fromStdString(status.errorText()));
    }
  }
}

void LabelPanelView::nudgeEdge(bool endEdge, int delta) {
  if (!session_->isOpen() || !labels_->hasSet()) return;
  const storage::LabelSegment* s =
      labels_->segmentAt(session_->selectedGroup(), session_->currentStep());
  if (s == nullptr) return report(tr("No segment of the selected group under the cursor."));
  std::int64_t first = s->firstStep;
  std::int64_t last = s->lastStep;
  (endEdge ? last : first) += delta;
  if (first > last) return;
  const std::int64_t moved = endEdge ? last : first;
  Status status = labels_->moveSegment(s->id, first, last);
  if (!status) return report(QString::fromStdString(status.errorText()));
  session_->setCurrentStep(moved);
}

void LabelPanelView::refreshSets() {
  const QSignalBlocker block(sets_);
  sets_->clear();
  workspace::Workspace* ws = labels_->workspace();
  if (ws != nullptr) {
    auto sets = ws->labelStore().list();
    if (sets) {
      for (const auto& s : sets.value())
        sets_->addItem(QString::fromStdString(s.name));
    }
  }
  sets_->setCurrentIndex(sets_->findText(QString::fromStdString(labels_->setName())));
  sets_->setPlaceholderText(tr("(no label set)"));
  // The comparison keeps its choice while that set exists and is not the one being edited.
  const QString with = agreementWith_->currentData().toString();
  {
    const QSignalBlocker blockWith(agreementWith_);
    agreementWith_->clear();
    agreementWith_->addItem(tr("truth"), QString());
    for (int i = 0; i < sets_->count(); ++i) {
      if (sets_->itemText(i).toStdString() != labels_->setName())
        agreementWith_->addItem(tr("label set %1").arg(sets_->itemText(i)), sets_->itemText(i));
    }
    agreementWith_->setCurrentIndex(std::max(0, agreementWith_->findData(with)));
  }
  refreshAgreement();
}

void LabelPanelView::openSetAt(int index) {
  if (index < 0) return;
  Status s = labels_->openSet(sets_->itemText(index).toStdString());
  if (!s) report(QString::fromStdString(s.errorText()));
}

void LabelPanelView::newSet() {
  bool ok = false;
  const QString name = QInputDialog::getText(this, tr("New label set"), tr("Name:"),
                                             QLineEdit::Normal, QString(), &ok);
  if (!ok || name.trimmed().isEmpty()) return;
  Status s = labels_->createSet(name.trimmed().toStdString());
  if (!s) report(QString::fromStdString(s.errorText()));
}

void LabelPanelView::saveSetAs() {
  if (!labels_->hasSet()) return report(tr("No label set is open."));
  bool ok = false;
  const QString name = QInputDialog::getText(
      this, tr("Save label set as"), tr("Name of the copy:"), QLineEdit::Normal,
      QString::fromStdString(labels_->setName()) + tr(" copy"), &ok);
  if (!ok || name.trimmed().isEmpty()) return;
  Status s = labels_->saveSetAs(name.trimmed().toStdString());
  if (!s) report(QString::fromStdString(s.errorText()));
}

void LabelPanelView::importLabels() {
  if (!labels_->hasSet()) return report(tr("Create or open a label set first."));
  const QString file =
      QFileDialog::getOpenFileName(this, tr("Import labels"), startPath(QStringLiteral("labels")),
                                   tr("Label files (*.csv *.json);;All files (*)"));
  if (file.isEmpty()) return;
  rememberPath(QStringLiteral("labels"), file);
  auto n = labels_->importFile(file.toStdString());
  if (!n) return report(QString::fromStdString(n.errorText()));
  emit statusMessage(tr("Imported %n segment(s)", nullptr, static_cast<int>(n.value())));
}

void LabelPanelView::exportLabels() {
  if (!labels_->hasSet()) return report(tr("No label set is open."));
  const QString file = QFileDialog::getSaveFileName(
      this, tr("Export labels"),
      startPath(QStringLiteral("labels"), QString::fromStdString(labels_->setName()) + ".csv"),
      tr("CSV (*.csv);;JSON (*.json)"));
  if (file.isEmpty()) return;
  rememberPath(QStringLiteral("labels"), file);
  Status s = labels_->exportFile(file.toStdString());
  if (!s) return report(QString::fromStdString(s.errorText()));
  emit statusMessage(tr("Exported %1 to %2").arg(QString::fromStdString(labels_->setName()), file));
}

void LabelPanelView::refreshCursorInfo() {
  if (const auto sel = session_->selection()) {
    range_->setText(tr("steps %1-%2 (%n step(s))", nullptr, static_cast<int>(sel->size()))
                        .arg(sel->first)
                        .arg(sel->last));
  } else {
    range_->setText(tr("none (an edit labels the current step)"));
  }
  const SensorGroup g = session_->selectedGroup();
  const storage::LabelSegment* s =
      session_->isOpen() ? labels_->segmentAt(g, session_->currentStep()) : nullptr;
  if (s == nullptr) {
    atCursor_->setText(tr("%1: unlabelled").arg(groupName(g)));
  } else {
    atCursor_->setText(tr("%1: %2, steps %3-%4")
                           .arg(groupName(g), className(s->cls))
                           .arg(s->firstStep)
                           .arg(s->lastStep));
  }
}

void LabelPanelView::refreshAgreement() {
  std::vector<storage::LabelSegment> all;
  for (const GroupInfo& info : kSensorGroups) {
    const auto& list = labels_->segments(info.group);
    all.insert(all.end(), list.begin(), list.end());
  }
  std::vector<workspace::GroupAgreement> rows;
  const QString other = agreementWith_->currentData().toString();
  workspace::Workspace* ws = labels_->workspace();
  if (session_->isOpen() && other.isEmpty()) {
    rows = workspace::truthAgreement(session_->track(), all);
  } else if (session_->isOpen() && ws != nullptr) {
    // Rows are the other set, columns this one.
    auto set = ws->labelStore().find(other.toStdString());
    auto theirs = set ? ws->labelStore().segments(set->id, session_->info().id)
                      : Result<std::vector<storage::LabelSegment>>(set.error());
    if (theirs) rows = workspace::labelAgreement(session_->stepCount(), theirs.value(), all);
  }
  agreement_->setEnabled(!rows.empty());
  for (const GroupInfo& info : kSensorGroups) {
    const int r = groupIndex(info.group);
    QString agree = QStringLiteral("-");
    QString chance = QStringLiteral("-");
    QString kappa = QStringLiteral("-");
    QString why;
    if (static_cast<std::size_t>(r) < rows.size()) {
      const workspace::GroupAgreement& a = rows[static_cast<std::size_t>(r)];
      if (a.percent) agree = QStringLiteral("%1 %").arg(*a.percent, 0, 'f', 1);
      if (a.chancePercent) chance = QStringLiteral("%1 %").arg(*a.chancePercent, 0, 'f', 1);
      if (a.kappa) kappa = QString::number(*a.kappa, 'f', 3);
      if (a.comparedSteps == 0) {
        why = tr("No step is labelled on both sides");
      } else if (!a.kappa) {
        why =
            tr("Undefined: both sides use one and the same class on all %n step(s), so chance "
               "agreement is 100 %",
               nullptr, static_cast<int>(a.comparedSteps));
      } else {
        why = tr("%1 of %2 steps agree (%3). Two annotators labelling at random with these class "
                 "shares would agree on %4. Kappa %5 says how much better than chance they agree: "
                 "1 fully, 0 no better than chance.")
                  .arg(a.agreeingSteps)
                  .arg(a.comparedSteps)
                  .arg(agree, chance, kappa);
      }
    }
    agreement_->setItem(r, 0, new QTableWidgetItem(groupName(info.group)));
    agreement_->setItem(r, 1, new QTableWidgetItem(agree));
    agreement_->setItem(r, 2, new QTableWidgetItem(chance));
    agreement_->setItem(r, 3, new QTableWidgetItem(kappa));
    for (int c = 0; c < 4; ++c)
      agreement_->item(r, c)->setToolTip(why);
  }
}

void LabelPanelView::saveSettings(QSettings& settings) const {
  settings.setValue(settings_keys::kLabelGroupsMode, static_cast<int>(groupsMode()));
  QStringList checked;
  for (const GroupInfo& info : kSensorGroups)
    if (checks_[static_cast<std::size_t>(groupIndex(info.group))]->isChecked())
      checked << groupName(info.group);
  settings.setValue(QStringLiteral("labels/checkedGroups"), checked);
}

void LabelPanelView::restoreSettings(const QSettings& settings) {
  const int mode = settings.value(settings_keys::kLabelGroupsMode, 0).toInt();
  if (mode >= 0 && mode <= 2) setGroupsMode(static_cast<GroupsMode>(mode));
  const QStringList checked = settings.value(QStringLiteral("labels/checkedGroups")).toStringList();
  for (const GroupInfo& info : kSensorGroups)
    setGroupChecked(info.group, checked.contains(groupName(info.group)));
}

}  // namespace tactile::gui
