#include "app/gui/common/ui_language.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

#include "app/gui/common/settings_keys.h"

namespace tactile::gui {

namespace {

const QString kPrefix = QStringLiteral("tactile_workbench_");

QStringList translationFolders() {
  QStringList folders{QStringLiteral(":/i18n")};
  // An installed program: PREFIX/bin/tactile-workbench next to PREFIX/share/tactile-workbench.
  if (QCoreApplication::instance())
    folders << QDir(QCoreApplication::applicationDirPath())
                   .absoluteFilePath(QStringLiteral("../share/tactile-workbench/translations"));
  return folders;
}

// "de-AT" -> "de", "zh-Hans-CN" -> "zh_CN" (any Chinese), "pt-BR" -> "pt".
QString languageOf(const QString& name) {
  const QLocale locale(name);
  if (locale.language() == QLocale::Chinese) return QStringLiteral("zh_CN");
  if (locale.language() == QLocale::C) return {};
  const QString code = QLocale::languageToCode(locale.language());
  return code;
}

}  // namespace

QStringList availableTranslations() {
  QStringList out;
  for (const QString& folder : translationFolders()) {
    const QStringList files =
        QDir(folder).entryList({kPrefix + QStringLiteral("*.qm")}, QDir::Files, QDir::Name);
    for (const QString& file : files) {
      const QString language = file.mid(kPrefix.size()).chopped(3);
      if (!language.isEmpty() && !out.contains(language)) out << language;
    }
  }
  out.sort();
  return out;
}

QString chooseUiLanguage(const QString& setting, const QStringList& preferred,
                         const QStringList& available) {
  const QString english = QStringLiteral("en");
  if (setting == english || available.contains(setting)) return setting;
  for (const QString& name : preferred) {
    const QString language = languageOf(name);
    if (language == english) return english;
    if (available.contains(language)) return language;
    // A translation named with its territory ("pt_BR") serves "pt-BR".
    const QString full = QLocale(name).name();
    if (available.contains(full)) return full;
  }
  return english;
}

QLocale uiLocale(const QString& language, const QLocale& system) {
  const QLocale wanted(language == QStringLiteral("en") ? QStringLiteral("en_US") : language);
  if (system.language() == wanted.language() &&
      (wanted.language() != QLocale::Chinese || system.script() == wanted.script()))
    return system;
  return wanted;
}

bool loadWorkbenchTranslation(QTranslator& translator, const QString& language) {
  for (const QString& folder : translationFolders()) {
    if (translator.load(kPrefix + language, folder)) return true;
  }
  return false;
}

QString installUiLanguage(QCoreApplication& app) {
  const QString setting = QSettings().value(settings_keys::kLanguage).toString();
  const QString language =
      chooseUiLanguage(setting, QLocale::system().uiLanguages(), availableTranslations());
  QLocale::setDefault(uiLocale(language));
  // English too has a translation: the plural forms of the "%n" texts ("1 step", "2 steps").
  auto* own = new QTranslator(&app);
  if (loadWorkbenchTranslation(*own, language)) QCoreApplication::installTranslator(own);
  if (language == QStringLiteral("en")) return language;
  // Qt's own strings (standard buttons, file dialogs) where Debian's translations are installed.
  auto* qt = new QTranslator(&app);
  if (qt->load(QStringLiteral("qtbase_") + language,
               QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
    QCoreApplication::installTranslator(qt);
  return language;
}

}  // namespace tactile::gui
