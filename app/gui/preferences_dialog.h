// File > Preferences: the interface language, the annotator's name stored on every label segment
// written here, and the height of the timelines' label rows. Stored in QSettings
// (settings_keys.h) when accepted.
#pragma once

#include <QDialog>

class QComboBox;
class QLineEdit;
class QSpinBox;

namespace tactile::gui {

class PreferencesDialog : public QDialog {
  Q_OBJECT

 public:
  explicit PreferencesDialog(QWidget* parent = nullptr);

  // Fills the fields from QSettings.
  void load();
  // Writes the fields to QSettings.
  void save() const;

  // The language codes offered, "" first (follow the system).
  static QStringList languageCodes();
  static constexpr int kDefaultRowHeight = 16;
  static constexpr int kMinRowHeight = 8;
  static constexpr int kMaxRowHeight = 48;

  QComboBox* languageBox() const { return language_; }
  QLineEdit* annotatorEdit() const { return annotator_; }
  QSpinBox* rowHeightBox() const { return rowHeight_; }

 private:
  QComboBox* language_;
  QLineEdit* annotator_;
  QSpinBox* rowHeight_;
  QSpinBox* doubt_;
};

}  // namespace tactile::gui
