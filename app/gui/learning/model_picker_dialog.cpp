#include "app/gui/learning/model_picker_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace tactile::gui {

namespace {

QComboBox* modelBox(const QStringList& models, const QString& current) {
  auto* box = new QComboBox;
  box->addItem(QObject::tr("none"), QString());
  for (const QString& m : models)
    box->addItem(m, m);
  const int at = box->findData(current);
  box->setCurrentIndex(at >= 0 ? at : 0);
  return box;
}

}  // namespace

ModelPickerDialog::ModelPickerDialog(const QStringList& models,
                                     const PredictionModel::Choice& current, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Show Predictions"));
  bool same = true;
  for (const QString& m : current)
    same = same && m == current.front();
  QString first = current.front();
  if (first.isEmpty() && !models.isEmpty()) first = models.back();  // the newest model
  all_ = modelBox(models, first);
  all_->setObjectName(QStringLiteral("allGroups"));
  perGroup_ = new QCheckBox(tr("A model per group"));
  auto* form = new QFormLayout;
  form->addRow(tr("Model:"), all_);
  form->addRow(perGroup_);
  for (const GroupInfo& g : kSensorGroups) {
    QComboBox* box =
        modelBox(models, same ? first : current[static_cast<std::size_t>(groupIndex(g.group))]);
    groups_[static_cast<std::size_t>(groupIndex(g.group))] = box;
    form->addRow(QString::fromUtf8(g.longName.data(), static_cast<qsizetype>(g.longName.size())) +
                     QLatin1Char(':'),
                 box);
  }
  connect(perGroup_, &QCheckBox::toggled, this, &ModelPickerDialog::setPerGroup);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  auto* note =
      new QLabel(tr("The timeline shows each group's predicted class under its labels, "
                    "pale where the model is unsure, and marks where it disagrees with "
                    "the labels (N: next disagreement)."));
  note->setWordWrap(true);
  layout->addWidget(note);
  layout->addLayout(form);
  layout->addWidget(buttons);
  perGroup_->setChecked(!same);
  setPerGroup(!same);
}

void ModelPickerDialog::setPerGroup(bool perGroup) {
  if (perGroup_->isChecked() != perGroup) perGroup_->setChecked(perGroup);
  all_->setEnabled(!perGroup);
  for (QComboBox* box : groups_)
    box->setEnabled(perGroup);
}

PredictionModel::Choice ModelPickerDialog::choice() const {
  if (!perGroup_->isChecked()) return PredictionModel::sameForAll(all_->currentData().toString());
  PredictionModel::Choice c;
  for (std::size_t g = 0; g < groups_.size(); ++g)
    c[g] = groups_[g]->currentData().toString();
  return c;
}

void ModelPickerDialog::setCoverage(const QMap<QString, QStringList>& groupsOfModel) {
  std::vector<QComboBox*> boxes{all_};
  for (QComboBox* b : groups_)
    boxes.push_back(b);
  for (QComboBox* box : boxes) {
    for (int i = 0; i < box->count(); ++i) {
      const QString name = box->itemData(i).toString();
      if (name.isEmpty() || !groupsOfModel.contains(name)) continue;
      const QStringList groups = groupsOfModel.value(name);
      box->setItemText(i, groups.size() == kGroupCount
                              ? tr("%1 (all groups)").arg(name)
                              : tr("%1 (%2 only)").arg(name, groups.join(QStringLiteral(", "))));
    }
  }
}

}  // namespace tactile::gui
