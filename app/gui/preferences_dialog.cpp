#include "app/gui/preferences_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

#include "app/gui/common/settings_keys.h"

namespace tactile::gui {

namespace keys = settings_keys;

QStringList PreferencesDialog::languageCodes() {
  return {QString(), QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("zh_CN")};
}

PreferencesDialog::PreferencesDialog(QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("preferencesDialog"));
  setWindowTitle(tr("Preferences"));
  language_ = new QComboBox(this);
  language_->setObjectName(QStringLiteral("language"));
  // Each language named in itself, so a reader of any of them finds their own.
  const QStringList names{tr("Follow the system"), QStringLiteral("English"),
                          QStringLiteral("Deutsch"), QStringLiteral("\u7b80\u4f53\u4e2d\u6587")};
  const QStringList codes = languageCodes();
  for (qsizetype i = 0; i < codes.size(); ++i)
    language_->addItem(names[i], codes[i]);
  annotator_ = new QLineEdit(this);
  annotator_->setObjectName(QStringLiteral("annotator"));
  annotator_->setPlaceholderText(tr("e.g. your initials"));
  annotator_->setToolTip(
      tr("Stored with every label segment you write and in label exports (annotator column)"));
  rowHeight_ = new QSpinBox(this);
  rowHeight_->setObjectName(QStringLiteral("rowHeight"));
  rowHeight_->setRange(kMinRowHeight, kMaxRowHeight);
  rowHeight_->setSuffix(tr(" px"));
  rowHeight_->setToolTip(tr("Height of each label, truth and model row in the timelines"));

  auto* form = new QFormLayout;
  form->addRow(tr("&Language:"), language_);
  auto* note = new QLabel(tr("A new language applies at the next start."), this);
  note->setEnabled(false);
  form->addRow(QString(), note);
  form->addRow(tr("&Annotator:"), annotator_);
  form->addRow(tr("Timeline &row height:"), rowHeight_);
  doubt_ = new QSpinBox(this);
  doubt_->setObjectName(QStringLiteral("doubtThreshold"));
  doubt_->setRange(50, 99);
  doubt_->setSuffix(tr(" %"));
  doubt_->setToolTip(
      tr("Learn > Next Doubt (D) stops where the model's posterior of its own "
         "prediction is below this"));
  form->addRow(tr("Model &unsure below:"), doubt_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);
  load();
}

void PreferencesDialog::load() {
  QSettings settings;
  const int at =
      static_cast<int>(languageCodes().indexOf(settings.value(keys::kLanguage).toString()));
  language_->setCurrentIndex(std::max(0, at));
  annotator_->setText(settings.value(keys::kAnnotator).toString());
  rowHeight_->setValue(settings.value(keys::kTimelineRowHeight, kDefaultRowHeight).toInt());
  doubt_->setValue(static_cast<int>(std::lround(
      100.0 * settings.value(keys::kDoubtThreshold, keys::kDefaultDoubtThreshold).toDouble())));
}

void PreferencesDialog::save() const {
  QSettings settings;
  settings.setValue(keys::kLanguage, language_->currentData().toString());
  settings.setValue(keys::kAnnotator, annotator_->text().trimmed());
  settings.setValue(keys::kTimelineRowHeight, rowHeight_->value());
  settings.setValue(keys::kDoubtThreshold, doubt_->value() / 100.0);
}

}  // namespace tactile::gui
