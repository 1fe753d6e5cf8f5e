// Chooses the stored models whose predictions the timeline shows: one for every group, or one per
// group (a bundle need not have all eight groups; "none" leaves a group without predictions).
#pragma once

#include <QDialog>
#include <QMap>
#include <QStringList>

#include <array>
#include <vector>

#include "app/gui/learning/prediction_model.h"

class QCheckBox;
class QComboBox;

namespace tactile::gui {

class ModelPickerDialog : public QDialog {
  Q_OBJECT

 public:
  ModelPickerDialog(const QStringList& models, const PredictionModel::Choice& current,
                    QWidget* parent = nullptr);

  PredictionModel::Choice choice() const;
  void setPerGroup(bool perGroup);
  QComboBox* allGroupsBox() const { return all_; }
  // Says beside each model which groups it covers ("m1 (F, L, R)"), by model name.
  void setCoverage(const QMap<QString, QStringList>& groupsOfModel);
  QComboBox* groupBox(SensorGroup g) const {
    return groups_[static_cast<std::size_t>(groupIndex(g))];
  }

 private:
  QCheckBox* perGroup_ = nullptr;
  QComboBox* all_ = nullptr;
  std::array<QComboBox*, kGroupCount> groups_{};
};

}  // namespace tactile::gui
