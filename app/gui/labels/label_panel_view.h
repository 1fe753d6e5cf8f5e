// The labels dock: the current label set (New, Open, Save As, Import, Export), which groups an
// edit applies to (the selected group, the checked groups, or every group in contact over the
// range), the class legend with its keys 1-5, the segment under the cursor, and, where the run has
// truth, the agreement of the labels with it per group (percent of steps and Cohen's kappa).
#pragma once

#include <QWidget>

#include <array>
#include <vector>

#include "run/contact_class.h"
#include "run/sensor_layout.h"

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QLabel;
class QTableWidget;
class QSettings;

namespace tactile::gui {

class LabelModel;
class RunSession;

class LabelPanelView : public QWidget {
  Q_OBJECT

 public:
  enum class GroupsMode { Selected, Checked, Contacting };

  LabelPanelView(RunSession* session, LabelModel* labels, QWidget* parent = nullptr);

  GroupsMode groupsMode() const;
  void setGroupsMode(GroupsMode mode);
  void setGroupChecked(SensorGroup group, bool checked);
  std::vector<SensorGroup> checkedGroups() const;
  // The groups an edit over [first, last] applies to under the current mode.
  std::vector<SensorGroup> groupsFor(std::int64_t first, std::int64_t last) const;

  void saveSettings(QSettings& settings) const;
  void restoreSettings(const QSettings& settings);

 public slots:
  // Labels the selection (or, without one, the current step) with `cls`; errors are reported
  // through errorOccurred.
  void applyClass(tactile::ContactClass cls);
  // Deletes the segments under the cursor in the groups an edit applies to.
  void deleteAtCursor();
  // Moves the start (or end) edge of the selected group's segment under the cursor by `delta`.
  void nudgeEdge(bool endEdge, int delta);
  void newSet();
  void saveSetAs();
  void importLabels();
  void exportLabels();
  void refreshSets();

 signals:
  void errorOccurred(const QString& message);
  void statusMessage(const QString& message);
  // The "Apply to" mode or a group's check changed.
  void settingsChanged();

 private:
  void openSetAt(int index);
  void refreshCursorInfo();
  void refreshAgreement();
  void report(const QString& failure);

  RunSession* session_;
  LabelModel* labels_;
  QComboBox* sets_;
  QButtonGroup* mode_;
  std::array<QCheckBox*, kGroupCount> checks_{};
  QLabel* range_;
  QLabel* atCursor_;
  QTableWidget* agreement_;
  QComboBox* agreementWith_;  // "truth" (empty data) or another label set's name
};

}  // namespace tactile::gui
